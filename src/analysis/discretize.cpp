#include "momenta/analysis/discretize.hpp"

#include <cmath>

#include <fmt/format.h>
#include <Eigen/LU>

#include "momenta/analysis/time_response.hpp"
#include "momenta/common/error.hpp"

namespace momenta::analysis {
namespace {

StateSpace zero_order_hold_system(const StateSpace& s, double T) {
  const Discretization zoh = zero_order_hold(s.A(), s.B(), T);
  return StateSpace(zoh.transition, zoh.input, s.C(), s.D(), s.state_names(), s.input_names(),
                    s.output_names(), T)
      .with_units(s.units());
}

StateSpace tustin_system(const StateSpace& s, double T) {
  const Eigen::Index n = s.A().rows();
  const MatX I = MatX::Identity(n, n);
  const MatX left = I - 0.5 * T * s.A();  // I − A T/2, whose inverse is P
  const Eigen::FullPivLU<MatX> P(left);
  if (n > 0 && !P.isInvertible()) {
    throw NumericalError(fmt::format(
        "c2d (Tustin): I − A T/2 is singular at T = {} s: A has an eigenvalue at 2/T = {} 1/s; "
        "choose another sample time",
        T, 2.0 / T));
  }
  if (n == 0) {
    return StateSpace(MatX(0, 0), s.B(), s.C(), s.D(), {}, s.input_names(), s.output_names(), T)
        .with_units(s.units());
  }
  const MatX Ad = P.solve(I + 0.5 * T * s.A());
  const MatX Bd = P.solve(T * s.B());
  // C P from Pᵀ: (I − A T/2)ᵀ (C P)ᵀ = Cᵀ.
  const MatX Cd = Eigen::FullPivLU<MatX>(left.transpose()).solve(s.C().transpose()).transpose();
  const MatX Dd = s.D() + 0.5 * s.C() * Bd;
  return StateSpace(Ad, Bd, Cd, Dd, s.state_names(), s.input_names(), s.output_names(), T)
      .with_units(s.units());
}

}  // namespace

StateSpace c2d(const StateSpace& system, double sample_time, DiscretizationMethod method) {
  if (system.is_discrete()) {
    throw InvalidArgument(fmt::format("c2d: the system is already discrete (sample time {} s)",
                                      system.sample_time()));
  }
  if (!(sample_time > 0.0) || !std::isfinite(sample_time)) {
    throw InvalidArgument(
        fmt::format("c2d: sample time {} s must be positive and finite", sample_time));
  }
  switch (method) {
    case DiscretizationMethod::zero_order_hold:
      return zero_order_hold_system(system, sample_time);
    case DiscretizationMethod::tustin:
      return tustin_system(system, sample_time);
  }
  throw InvalidArgument("c2d: unknown discretization method");
}

DiscretizationMethod discretization_method(std::string_view name) {
  if (name == "zoh" || name == "zero_order_hold") return DiscretizationMethod::zero_order_hold;
  if (name == "tustin" || name == "bilinear") return DiscretizationMethod::tustin;
  throw InvalidArgument(fmt::format(
      "discretization method '{}': choose zoh (zero-order hold) or tustin (bilinear)", name));
}

}  // namespace momenta::analysis
