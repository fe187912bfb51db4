#pragma once
// Two descriptions of one system compared through their dynamics: the mass matrix and the
// forward dynamics at random states (the file readers' tests: URDF, MJCF against YAML).

#include <algorithm>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/data.hpp"
#include "momenta/model/model.hpp"

namespace momenta::test {

// max |M_a − M_b| / max |M_b| and the same of ABA's accelerations over `samples` random states
// (angles in ±π, lengths in ±0.1 m, rates in ±3, efforts in ±5).
inline double largest_difference(const model::Model& a, const model::Model& b, int samples) {
  EXPECT_EQ(a.nq(), b.nq());
  EXPECT_EQ(a.nv(), b.nv());
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  dynamics::Data da(a), db(b);
  double worst = 0.0;
  for (int s = 0; s < samples; ++s) {
    VecX q = a.initial_q(), v(a.nv()), tau(a.nv());
    for (int i = 0; i < a.nq(); ++i) q[i] = 3.0 * unit(random);
    for (int i = 0; i < a.nv(); ++i) {
      v[i] = 3.0 * unit(random);
      tau[i] = 5.0 * unit(random);
    }
    const MatX Ma = dynamics::crba(a, da, q), Mb = dynamics::crba(b, db, q);
    const VecX va = dynamics::aba(a, da, q, v, tau), vb = dynamics::aba(b, db, q, v, tau);
    // A NaN compares false and would pass unseen: fail on it first.
    if (!Ma.allFinite() || !Mb.allFinite() || !va.allFinite() || !vb.allFinite()) {
      ADD_FAILURE() << "a non-finite mass matrix or acceleration at sample " << s;
      return std::numeric_limits<double>::infinity();
    }
    worst = std::max(worst, (Ma - Mb).cwiseAbs().maxCoeff() / Mb.cwiseAbs().maxCoeff());
    worst = std::max(worst, (va - vb).cwiseAbs().maxCoeff() / vb.cwiseAbs().maxCoeff());
  }
  return worst;
}

}  // namespace momenta::test
