#include "momenta/integrate/acceleration_jacobian.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace momenta::integrate {

void JacobianWorkspace::resize(int nq, int nv) {
  q = VecX::Zero(nq);
  for (VecX* x : {&v, &dq, &a, &scale}) *x = VecX::Zero(nv);
}

void acceleration_jacobian(SecondOrderSystem& system, double t, const VecX& q, const VecX& v,
                           const VecX& a0, MatX& dadq, MatX& dadv, JacobianWorkspace& work) {
  const double probe = std::sqrt(std::numeric_limits<double>::epsilon());
  system.configuration_scale(q, work.scale);
  for (int j = 0; j < static_cast<int>(v.size()); ++j) {
    // Along the tangent of q.
    const double eps_q = probe * std::max(1.0, work.scale[j]);
    work.dq.setZero();
    work.dq[j] = eps_q;
    system.integrate(q, work.dq, work.q);
    system.acceleration(t, work.q, v, work.a);
    dadq.col(j) = (work.a - a0) / eps_q;
    // Along v.
    const double eps_v = probe * std::max(1.0, std::abs(v[j]));
    work.v = v;
    work.v[j] += eps_v;
    system.acceleration(t, q, work.v, work.a);
    dadv.col(j) = (work.a - a0) / eps_v;
  }
}

}  // namespace momenta::integrate
