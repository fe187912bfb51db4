#include "momenta/identify/frequency_response_data.hpp"

#include <cmath>
#include <complex>
#include <numbers>

#include <fmt/format.h>

#include "momenta/analysis/frequency_response.hpp"
#include "momenta/analysis/linearize.hpp"
#include "momenta/common/error.hpp"

namespace momenta::identify {
namespace {

// G(jω) of the model at the angular frequencies `omega`.
Eigen::VectorXcd response_of(const model::Model& model, const std::string& input,
                             const std::string& output,
                             const std::vector<model::OutputSpec>& outputs, const VecX& omega) {
  analysis::LinearizationOptions options;
  options.inputs = {input};
  options.outputs = {output};
  options.output_specs = outputs;
  const analysis::LinearModel linear =
      analysis::linearize(model, analysis::initial_operating_point(model), options);
  return analysis::frequency_response(linear.system, 0, 0, omega).response;
}

}  // namespace

SampledFrequencyResponse sample_frequency_response(const ModelFactory& make_model, const VecX& p,
                                                   const std::string& input,
                                                   const std::string& output,
                                                   const std::vector<model::OutputSpec>& outputs,
                                                   const VecX& frequency, const VecX& near_phase,
                                                   bool sensitivities, double relative_step) {
  constexpr double kDegrees = 180.0 / std::numbers::pi;
  const VecX omega = 2.0 * std::numbers::pi * frequency;
  const Eigen::Index n = frequency.size();
  SampledFrequencyResponse out;
  const Eigen::VectorXcd g = response_of(make_model(p), input, output, outputs, omega);
  out.linearizations = 1;
  out.values.resize(n, 2);
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!(std::abs(g[k]) > 0.0) || !std::isfinite(std::abs(g[k]))) {
      throw NumericalError(fmt::format(
          "the model's response from {} to {} at {} Hz is {}: a {} of the linearization sits at "
          "that test frequency",
          input, output, frequency[k], std::abs(g[k]) > 0.0 ? "not finite" : "zero",
          std::abs(g[k]) > 0.0 ? "pole" : "zero"));
    }
    out.values(k, 0) = 20.0 * std::log10(std::abs(g[k]));
    const double phase = std::arg(g[k]) * kDegrees;
    out.values(k, 1) = phase + 360.0 * std::round((near_phase[k] - phase) / 360.0);
  }
  if (!sensitivities) return out;

  out.sensitivities.resize(2 * n, p.size());
  for (Eigen::Index i = 0; i < p.size(); ++i) {
    const double h = relative_step * (p[i] != 0.0 ? std::abs(p[i]) : 1.0);
    VecX shifted = p;
    shifted[i] = p[i] + h;
    const Eigen::VectorXcd plus = response_of(make_model(shifted), input, output, outputs, omega);
    shifted[i] = p[i] - h;
    const Eigen::VectorXcd minus = response_of(make_model(shifted), input, output, outputs, omega);
    out.linearizations += 2;
    for (Eigen::Index k = 0; k < n; ++k) {
      const std::complex<double> relative = (plus[k] - minus[k]) / (2.0 * h) / g[k];
      out.sensitivities(2 * k, i) = 20.0 / std::log(10.0) * relative.real();
      out.sensitivities(2 * k + 1, i) = kDegrees * relative.imag();
    }
  }
  return out;
}

}  // namespace momenta::identify
