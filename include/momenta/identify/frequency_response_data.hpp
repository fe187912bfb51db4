#pragma once
// A measured frequency response — what a Bode test on a shaker table or a swept-sine analyser
// gives: at each test frequency the output's amplitude and phase relative to the input's — and
// the model's, from its linearization, with derivatives with respect to numbers of the model. A
// grey-box fit (identify/grey_box.hpp) compares the two.
//
// The log: a CSV (io/measured_data.hpp's rules) with columns `frequency` (Hz, increasing, > 0),
// `magnitude` (|G|, output unit per input unit) or `magnitude_db` (20 log₁₀|G|), and `phase`
// (degrees; any branch: compared modulo 360°).
//
// The model's response: G(jω) = C (jωI − A)⁻¹ B + D of analysis::linearize about the model's
// initial state (its joints' q0 and v0: write the model about the equilibrium the test shakes it
// about), from `input` (a signal, or a prescribed coordinate) to `output` (an output column or a
// coordinate). Compared as 20 log₁₀|G| in dB and arg G in degrees — relative errors in
// magnitude, as a Bode plot shows them. Derivatives: ∂G/∂p_i by central differences of
// G(jω) between models linearized at p_i ± h_i (each linearization analytic; h_i = 10⁻⁴|p_i|,
// truncation ~10⁻⁸ relative), then ∂dB/∂p = (20/ln 10) Re(G⁻¹ ∂G/∂p) and
// ∂phase/∂p = (180/π) Im(G⁻¹ ∂G/∂p).

#include <optional>
#include <string>
#include <vector>

#include "momenta/identify/trajectory_sensitivities.hpp"
#include "momenta/io/measured_data.hpp"
#include "momenta/math/types.hpp"
#include "momenta/model/output_spec.hpp"

namespace momenta::identify {

/// A Bode test's data of one input–output pair.
struct MeasuredFrequencyResponse {
  std::string source;      ///< the file, as named
  VecX frequency;          ///< Hz, increasing, > 0
  VecX magnitude_db;       ///< 20 log₁₀|G|
  VecX phase_deg;          ///< arg G, degrees, as measured
  std::vector<int> lines;  ///< the file's line of each row
};

/// The response in `table`: its `frequency`, `magnitude` or `magnitude_db`, and `phase` columns.
/// Throws InvalidArgument naming the file and line: a column missing (its columns listed), a
/// frequency ≤ 0 or not increasing, a magnitude ≤ 0.
MeasuredFrequencyResponse frequency_response_data(const io::MeasuredTable& table);

/// The model's response at the measured frequencies: one row per frequency, columns magnitude
/// (dB) and phase (degrees, the branch nearest each measured phase).
struct SampledFrequencyResponse {
  MatX values;
  /// ∂/∂p: row k · 2 + c (frequency k; c = 0 magnitude, 1 phase), column i; empty unless asked.
  MatX sensitivities;
  long linearizations = 0;
};

/// The model built at p, linearized from `input` to `output` (names as analysis::linearize
/// takes them; `outputs` the model file's output columns), at `frequency` Hz. `near_phase`: the
/// measured phases, to choose each model phase's branch. Throws InvalidArgument for names the
/// linearization refuses; NumericalError where G is 0 or not finite (a pole or a zero at a test
/// frequency: that magnitude in dB is not a number).
SampledFrequencyResponse sample_frequency_response(const ModelFactory& make_model, const VecX& p,
                                                   const std::string& input,
                                                   const std::string& output,
                                                   const std::vector<model::OutputSpec>& outputs,
                                                   const VecX& frequency, const VecX& near_phase,
                                                   bool sensitivities, double relative_step = 1e-4);

}  // namespace momenta::identify
