#pragma once
// Rates and accelerations from logged positions, for data that has only the positions (an
// encoder's log): each sample's first and second derivative of a cubic fitted by least squares
// to the `window` samples around it (Savitzky & Golay 1964) — centred, and shifted to lie inside
// the log at its first and last window / 2 samples. Time steps must be uniform.

#include "momenta/math/types.hpp"

namespace momenta::identify {

/// The default window: 5 samples, the least smoothing a cubic allows (exact for cubics; in the
/// centre the rate's error is O(h⁴), the acceleration's O(h²)). Wider windows trade that bias for
/// less noise: choose by the positions' noise and the motion's frequencies.
inline constexpr int kDefaultDerivativeWindow = 5;

struct PositionDerivatives {
  MatX rate, acceleration;  ///< N × columns, as `positions`
};

/// Derivatives of each column of `positions` (N × n) sampled at `time` (N, uniform steps: each
/// within 1e-6 of the mean step, else InvalidArgument naming the row). `window` odd, ≥ 5 and
/// ≤ N (InvalidArgument otherwise).
PositionDerivatives differentiate_positions(const VecX& time, const MatX& positions, int window);

}  // namespace momenta::identify
