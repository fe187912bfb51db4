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

VecX column(const io::MeasuredTable& table, std::string_view name, std::string_view what) {
  const auto c = table.find(name);
  if (!c) {
    throw InvalidArgument(fmt::format("{}: no column '{}' ({}); its columns: {}", table.source,
                                      name, what, fmt::join(table.columns, ", ")));
  }
  return table.values.col(*c);
}

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

MeasuredFrequencyResponse frequency_response_data(const io::MeasuredTable& table) {
  MeasuredFrequencyResponse data;
  data.source = table.source;
  data.lines = table.lines;
  data.frequency = column(table, "frequency", "the test frequencies, Hz");
  data.phase_deg = column(table, "phase", "the phase of the output against the input, degrees");
  const bool in_db = table.find("magnitude_db").has_value();
  const VecX magnitude = in_db ? column(table, "magnitude_db", "20 log₁₀|G|")
                               : column(table, "magnitude", "|G|, or a magnitude_db column in dB");
  data.magnitude_db.resize(magnitude.size());
  for (Eigen::Index k = 0; k < magnitude.size(); ++k) {
    const int line = table.lines.empty() ? int(k) + 2 : table.lines[std::size_t(k)];
    if (!(data.frequency[k] > 0.0)) {
      throw InvalidArgument(fmt::format("{}:{}: frequency {} Hz: a test frequency must be > 0",
                                        table.source, line, data.frequency[k]));
    }
    if (k > 0 && !(data.frequency[k] > data.frequency[k - 1])) {
      throw InvalidArgument(fmt::format("{}:{}: frequency {} Hz does not increase (after {} Hz)",
                                        table.source, line, data.frequency[k],
                                        data.frequency[k - 1]));
    }
    if (!in_db && !(magnitude[k] > 0.0)) {
      throw InvalidArgument(
          fmt::format("{}:{}: magnitude {}: |G| must be > 0 (a magnitude_db column takes dB)",
                      table.source, line, magnitude[k]));
    }
    data.magnitude_db[k] = in_db ? magnitude[k] : 20.0 * std::log10(magnitude[k]);
  }
  return data;
}

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
