#pragma once
// The direction a slow slip takes: where its acceleration is along it.
//
// A contact sliding with kinetic friction −μk N ŝ against its slip v_t, ŝ = v_t / |v_t|: the slip's
// direction turns at (ŝ × v̇_t) / |v_t|, without bound as the slip speed goes to zero. From rest,
// a slip runs along its acceleration, so it starts in a direction ŝ where that acceleration,
// found with the friction against ŝ, is along ŝ: a(ŝ) = λ ŝ, λ ≥ 0 (Coulomb's law as a slip
// starts). Where the mechanism answers a force along the plane the same every way (a block, a
// ball), that is the way the friction sticking needed pointed; where it does not (a body
// pivoting on a corner, an arm), the two differ, and a slip started the other way turns within
// a few microseconds — turning at 1e11 rad/s at 1e-11 m/s, faster than an explicit integrator
// can follow (docs/contacts.md, "Coulomb friction"). MultibodySystem takes this direction while
// the slip is slower than kStartingSlip (multibody_system.hpp) and runs along it: its slow
// manifold, on which the turning has settled.
//
// A direction d is stable where the turning brings a slip near it back: its acceleration's
// part across it, a × d (positive turning it towards +θ), passes from positive to negative
// with θ. momenta takes the stable direction nearest the slip's reference with λ ≥ 0; where
// there is none, the slip is not starting but stopping, and the friction keeps the reference.

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include "momenta/math/types.hpp"

namespace momenta::system::detail {

// Directions tried round the plane (every 5°) before the stable ones are refined by bisection.
inline constexpr int kSlipDirectionsTried = 72;

// A direction, in the contact's tangent basis, turned by θ from `reference` (a unit 2-vector).
inline Vec2 turned(const Vec2& reference, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  return {c * reference.x() - s * reference.y(), s * reference.x() + c * reference.y()};
}

// The stable direction of a slip (above) nearest `reference`, in the contact's tangent basis,
// or none. `acceleration_of(d)` is the slip's acceleration (m/s², the same basis) with the
// friction against unit direction d, or nullopt where d gives no single normal force
// (Painlevé); it is called about 140 times. `reference` itself where the acceleration there is
// along it to 1e-12 of the largest one found and not against it, exactly (a planar slip keeps
// its line). No allocation.
template <class AccelerationOf>
std::optional<Vec2> stable_slip_direction(const Vec2& reference, AccelerationOf&& acceleration_of) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  constexpr double kStep = kTwoPi / kSlipDirectionsTried;
  struct Sample {
    double across = 0.0;  // a × d: the turning it gives (toward +θ where positive)
    double along = 0.0;   // a · d: λ
    double size = 0.0;    // |a|
  };
  const auto sample = [&](double theta) -> std::optional<Sample> {
    const Vec2 d = turned(reference, theta);
    const std::optional<Vec2> a = acceleration_of(d);
    if (!a) return std::nullopt;
    return Sample{d.x() * a->y() - d.y() * a->x(), a->dot(d), a->norm()};
  };
  std::array<std::optional<Sample>, kSlipDirectionsTried> round;
  double largest = 0.0;
  for (int k = 0; k < kSlipDirectionsTried; ++k) {
    round[k] = sample(k * kStep);
    if (round[k]) largest = std::max(largest, round[k]->size);
  }
  if (round[0] && std::abs(round[0]->across) <= 1e-12 * largest && round[0]->along >= 0.0)
    return reference;
  std::optional<double> best;  // θ of the stable direction nearest the reference
  const auto distance = [&](double theta) { return std::min(theta, kTwoPi - theta); };
  for (int k = 0; k < kSlipDirectionsTried; ++k) {
    const std::optional<Sample>& low_end = round[k];
    const std::optional<Sample>& high_end = round[(k + 1) % kSlipDirectionsTried];
    if (!low_end || !high_end || !(low_end->across > 0.0) || high_end->across > 0.0) continue;
    // Bisection to the crossing: 60 halvings of 5° leave less than 1e-19 rad.
    double low = k * kStep, high = (k + 1) * kStep;
    std::optional<Sample> at_high = high_end;
    for (int i = 0; i < 60 && at_high->across != 0.0; ++i) {
      const double middle = 0.5 * (low + high);
      const std::optional<Sample> at_middle = sample(middle);
      if (!at_middle) break;
      if (at_middle->across > 0.0) {
        low = middle;
      } else {
        high = middle;
        at_high = at_middle;
      }
    }
    if (!(at_high->along >= 0.0)) continue;  // a slip that would slow down
    const double root = std::fmod(high, kTwoPi);
    if (!best || distance(root) < distance(*best)) best = root;
  }
  if (!best) return std::nullopt;
  return turned(reference, *best);
}

}  // namespace momenta::system::detail
