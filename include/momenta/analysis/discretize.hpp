#pragma once
// From continuous to sampled time: the discrete system a digital controller sees when it holds
// its output between samples (zero-order hold), or the bilinear (Tustin) approximation a
// designer uses to carry a continuous controller onto a computer (Franklin, Powell & Workman,
// Digital Control of Dynamic Systems, ch. 4 and 6).

#include <string_view>

#include "momenta/analysis/state_space.hpp"

namespace momenta::analysis {

enum class DiscretizationMethod {
  /// Exact for an input held constant over each sample: A_d = e^(A T), B_d = ∫₀ᵀ e^(A τ) dτ B,
  /// C_d = C, D_d = D (Van Loan's augmented exponential, time_response.hpp).
  zero_order_hold,
  /// The bilinear map s = (2/T)(z − 1)/(z + 1), without prewarping: with P = (I − A T/2)⁻¹,
  /// A_d = P (I + A T/2), B_d = P B T, C_d = C P, D_d = D + C P B T/2 — the layout of SciPy's
  /// cont2discrete(method="bilinear"), so H_d(z) = G((2/T)(z − 1)/(z + 1)) exactly.
  tustin,
};

/// The sampled form of a continuous system at period `sample_time` (s), with the same names.
/// Throws InvalidArgument when the system is already discrete or the period is not positive and
/// finite; NumericalError when e^(A T) overflows (zero-order hold) or I − A T/2 is singular
/// (Tustin: A has an eigenvalue at 2/T).
StateSpace c2d(const StateSpace& system, double sample_time,
               DiscretizationMethod method = DiscretizationMethod::zero_order_hold);

/// "zoh" / "tustin" (also "zero_order_hold", "bilinear"); throws InvalidArgument naming the
/// choices otherwise.
DiscretizationMethod discretization_method(std::string_view name);

}  // namespace momenta::analysis
