#include "momenta/dynamics/aba_derivatives.hpp"

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/rnea_derivatives.hpp"

namespace momenta::dynamics {

void aba_derivatives(const Model& model, Data& data, VecRef q, VecRef v, VecRef tau,
                     std::span<const Vec6> f_ext) {
  // v̇ first (aba checks the arguments), then ∂τ/∂(q, v) and M at that v̇.
  aba(model, data, q, v, tau, f_ext);
  rnea_derivatives(model, data, q, v, data.vdot, f_ext);

  data.M_factor.compute(data.M);
  if (data.M_factor.info() != Eigen::Success) {
    throw NumericalError(
        "aba_derivatives: the mass matrix is not positive definite (a joint that carries no "
        "mass or inertia along one of its axes)");
  }
  data.Minv.setIdentity();
  data.M_factor.solveInPlace(data.Minv);
  data.dvdot_dq.noalias() = -data.Minv * data.dtau_dq;
  data.dvdot_dv.noalias() = -data.Minv * data.dtau_dv;
}

}  // namespace momenta::dynamics
