#pragma once
// The Campbell sweep shared by every rotor description (a spinning body in Euler–Poisson
// variables, a rotor in joint coordinates): the whirls at each speed, and the critical speeds
// where a forward whirl crosses the 1× line.

#include <functional>

#include "momenta/analysis/steady_motion.hpp"

namespace momenta::analysis::detail {

/// The whirls at spin speed Ω (rad/s), ordered so that the k-th stands for the same mode from one
/// speed to the next (backward before forward, then by frequency).
using WhirlsAt = std::function<CampbellPoint(double)>;

/// Checks the range (0 < from < to, finite, points ≥ 2; InvalidArgument otherwise), evaluates
/// `whirls_at` at `points` evenly spaced speeds and finds each critical speed: a sign change of a
/// forward whirl's frequency minus Ω between two stable speeds, refined by bisection to 1e-12
/// relative (stopping where the modes change their order).
CampbellDiagram campbell_sweep(const WhirlsAt& whirls_at, double from, double to, int points);

/// Sorts a point's whirls: backward before forward before none, then by frequency.
void sort_whirls(CampbellPoint& point);

}  // namespace momenta::analysis::detail
