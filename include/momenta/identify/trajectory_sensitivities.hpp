#pragma once
// A run's outputs at sampled times and their derivatives with respect to numbers of the model —
// what a grey-box fit (identify/grey_box.hpp) compares with measurements and steps with.
//
// The derivatives come from the forward sensitivity equations, integrated with the state by the
// same adaptive method (dopri5) under the same error control: for x = (q, v), ẋ = f(t, x, p),
//
//     Ṡ_q,i = S_v,i,     Ṡ_v,i = ∂a/∂q S_q,i + ∂a/∂v S_v,i + ∂a/∂p_i,    S_i(t0) = ∂x0/∂p_i,
//
// with ∂a/∂q and ∂a/∂v analytic (analysis/acceleration_derivatives.hpp) and ∂a/∂p_i, ∂x0/∂p_i
// and an output's own ∂y/∂p_i by differences between models built at shifted p_i (at the same
// state: differences of the dynamics, never of whole runs). ∂a/∂p_i = −M_ff⁻¹ ∂r/∂p_i, r the
// generalized force a model's dynamics leave unbalanced at the nominal accelerations
// (MultibodySystem::residual: an inverse dynamics of the shifted model, not a forward one), M_ff
// the factor ∂a/∂x already holds. Each sensitivity is carried scaled by
// its parameter's size, p_i ∂x/∂p_i (lengths and angles like x itself). An output column of the
// model's `outputs:` is y(t, q, v; p): its ∂y/∂x by central differences of the output at the state.
//
// Scope: models whose coordinates are vectors (no ball or free joint: nq = nv), without
// constraints, contacts, stops or controllers; prescribed joints are inputs.

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "momenta/integrate/integrator.hpp"
#include "momenta/math/types.hpp"
#include "momenta/model/model.hpp"
#include "momenta/model/output_spec.hpp"

namespace momenta::identify {

/// The model at parameter values p (the caller's way of setting them: a model file's numbers by
/// path, io::ModelTemplate). Throws what building the model throws at values it refuses.
using ModelFactory = std::function<model::Model(const VecX& p)>;

struct SensitivityOptions {
  /// The run's tolerances. They weigh the state alone: the sensitivities follow the steps the
  /// state's accuracy chooses (SecondOrderSystem::error_controlled), as CVODES does with them
  /// left out of its error test.
  integrate::Tolerances tolerances{1e-9, 1e-12};
  /// ∂x0/∂p_i and an output's own ∂y/∂p_i (once per sample): central differences with
  /// h_i = relative_step · |p_i| (relative_step where p_i = 0), truncation O(h²) ~1e-8 relative.
  double relative_step = 1e-4;
  /// ∂r/∂p_i at every evaluation of the dynamics (∂a/∂p_i = −M_ff⁻¹ ∂r/∂p_i): forward differences
  /// with h_i = forward_step · |p_i| — one inverse dynamics of a shifted model per parameter
  /// (r = 0 for the nominal), error ~1e-7 relative (truncation h, round-off ε/h) — or central
  /// ones with relative_step, two, ~1e-8.
  enum class Differences { forward, central };
  Differences dynamics = Differences::forward;
  double forward_step = 1e-7;
  /// A run that takes more integration steps than this stops with a NumericalError naming the
  /// time it reached (0: no budget but integrate::kMaxRunSteps): a fit's trial at values that
  /// make the model stiff — a damper of 10⁸ N·s/m on a car — fails at once instead of crawling
  /// (the grey-box fit sets it from its first runs).
  long max_steps = 0;
};

/// What one run gives.
struct SampledOutputs {
  /// y: one row per sample time, one column per channel.
  MatX values;
  /// ∂y/∂p: row k · channels + c (sample k, channel c), column i; empty when not asked for.
  MatX sensitivities;
  /// Calls of the model's dynamics a(t, q, v), over every model (nominal and p ± h).
  long evaluations = 0;
  long steps = 0;  ///< accepted integration steps
};

/// A model's channels — output columns of `outputs` ("body_y") or coordinates by name
/// (Model::q_name, v_name: "pivot.angle", "pivot.angle_rate") — resolved once.
class ChannelSet {
 public:
  /// Throws InvalidArgument naming an unknown channel (with a did-you-mean over both kinds), a
  /// prescribed coordinate (its motion is an input), or a model outside the scope above (naming
  /// the joint, constraint or controller).
  ChannelSet(const model::Model& model, std::vector<model::OutputSpec> outputs,
             std::vector<std::string> channels);

  const std::vector<std::string>& names() const { return names_; }
  /// Each channel's unit ("m", "rad/s").
  const std::vector<std::string>& units() const { return units_; }
  const std::vector<model::OutputSpec>& outputs() const { return outputs_; }

  /// Where channel c comes from: a state index (into (q, v), ≥ 0) or an output column (−1 − k).
  int source(int c) const { return source_[static_cast<std::size_t>(c)]; }

 private:
  std::vector<model::OutputSpec> outputs_;
  std::vector<std::string> names_, units_;
  std::vector<int> source_;
};

/// Runs the model at p from its initial state at times[0] to times.back() and samples the
/// channels at `times` (evenly spaced, at least two), with ∂y/∂p when `sensitivities`. Throws
/// InvalidArgument for times that are not evenly spaced (naming the sample) and what the run
/// throws (NumericalError naming the time when the state stops being finite).
SampledOutputs sample_outputs(const ModelFactory& make_model, const VecX& p,
                              const ChannelSet& channels, const VecX& times, bool sensitivities,
                              const SensitivityOptions& options = {});

/// Checks that `times` are evenly spaced (to 1e-6 of the spacing) and at least two; returns the
/// spacing. Throws InvalidArgument naming the first sample off the grid.
double even_spacing(const VecX& times, const std::string& what);

}  // namespace momenta::identify
