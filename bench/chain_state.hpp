#pragma once
// The benchmark chain with a random state from a fixed seed (q, v, τ, v̇), and its Data: what the
// dynamics and derivative benchmarks share.

#include <random>

#include "momenta/dynamics/data.hpp"
#include "momenta_test/multibody_models.hpp"

namespace momenta::bench {

struct Chain {
  explicit Chain(int n) : model(test::revolute_chain(n)), data(model) {
    std::mt19937 rng(42);
    q = test::random_vector(model.nq(), rng, 3.14);
    v = test::random_vector(model.nv(), rng, 1.0);
    tau = test::random_vector(model.nv(), rng, 1.0);
    vdot = test::random_vector(model.nv(), rng, 1.0);
  }
  model::Model model;
  dynamics::Data data;
  VecX q, v, tau, vdot;
};

}  // namespace momenta::bench
