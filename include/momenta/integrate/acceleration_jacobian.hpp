#pragma once
// ∂a/∂q and ∂a/∂v of a SecondOrderSystem by forward differences: the Jacobian the implicit
// methods iterate with (sdirk3) and the linearization the stiffness check examines.

#include "momenta/integrate/second_order_system.hpp"
#include "momenta/math/types.hpp"

namespace momenta::integrate {

/// The probes' workspace, sized once (no allocation afterwards).
struct JacobianWorkspace {
  VecX q, v, dq, a, scale;
  void resize(int nq, int nv);
};

/// ∂a/∂q (along the tangent: the column j is (a(q ⊕ ε e_j, v) − a0)/ε) and ∂a/∂v at (t, q, v),
/// given a0 = a(t, q, v); the probe is √ε·max(1, |x_j|), with |q_j| from configuration_scale
/// (1 rad on rotations). 2 nv evaluations; dadq and dadv must be nv × nv; no allocation.
void acceleration_jacobian(SecondOrderSystem& system, double t, const VecX& q, const VecX& v,
                           const VecX& a0, MatX& dadq, MatX& dadv, JacobianWorkspace& work);

}  // namespace momenta::integrate
