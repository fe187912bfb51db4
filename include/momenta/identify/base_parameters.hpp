#pragma once
// The base (identifiable) inertial parameters of a tree: the fewest combinations of π that
// decide its joint forces (Gautier & Khalil 1990; Gautier 1991, by numerical QR).
//
// Some of π never shows in the joint forces (the first body's mass on a fixed pivot), and some
// only in fixed combinations (a link's own moment about its axis with the next link's mass times
// the length squared). The regressor's columns, stacked over many random states, are taken in
// π's order — body 1 first — and each kept when it is not a combination of those kept before it
// (Gram–Schmidt on unit columns, kept above kIndependenceTolerance). The kept ones are the
// independent parameters; each other column is Y_d = Y_I k_d, so
//   Y π = Y_I β,   β = π_I + K_d π_D   (regrouping: β = R π, R = [1  K_d] in π's columns).
// Taking π in body order regroups a child's parameters onto its ancestors', as Khalil's symbolic
// rules do: a planar two-link arm's base set is upper.I_yy + l₁² lower.m, upper.h_z − l₁
// lower.m, upper.h_x, lower.I_yy, lower.h_x, lower.h_z (tested against that closed form).

#include <string>
#include <vector>

#include "momenta/identify/inertial_parameters.hpp"

namespace momenta::identify {

/// A column whose distance from the span of those kept before it, as a unit vector, is below
/// this is a combination of them (round-off leaves ~1e-14; a genuine parameter's stays above
/// ~1e-4 on the random states base_parameters draws).
inline constexpr double kIndependenceTolerance = 1e-8;

struct BaseParameters {
  int num_parameters = 0;        ///< Size of π.
  std::vector<int> independent;  ///< π's indices kept, ascending: base parameter k leads with
                                 ///< independent[k].
  std::vector<int> dependent;    ///< Regrouped into the independent ones (or of no effect).
  std::vector<int> no_effect;    ///< Of the dependent: columns that are zero — never felt.
  MatX regrouping;               ///< rank × num_parameters: β = regrouping π.

  int rank() const { return static_cast<int>(independent.size()); }
  /// The dependent parameters that are felt: told only in the combinations.
  std::vector<int> regrouped() const;
  /// β of a π.
  VecX base_of(const VecX& pi) const { return regrouping * pi; }
  /// Base parameter k in words: "upper.I_yy + 1·lower.m" (coefficients in SI, 6 digits).
  std::string describe(const Model& model, int k) const;
};

/// The base parameters of a model's tree from its regressor at `num_states` random states
/// (uniform joint angles and displacements in [−π, π], rates and accelerations in [−1, 1]; 0:
/// enough for 4× as many equations as parameters), drawn from `seed` — the same every call.
BaseParameters base_parameters(const Model& model, int num_states = 0, unsigned seed = 1);

}  // namespace momenta::identify
