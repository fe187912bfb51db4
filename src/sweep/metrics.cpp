#include "momenta/sweep/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "momenta/analysis/step_info.hpp"
#include "momenta/analysis/time_response.hpp"
#include "momenta/common/error.hpp"

namespace momenta::sweep {
namespace {

constexpr double kUndefined = std::numeric_limits<double>::quiet_NaN();

std::vector<std::string> numbered(const std::string& prefix, int count,
                                  std::initializer_list<const char*> parts) {
  std::vector<std::string> columns;
  for (int i = 1; i <= count; ++i) {
    if (parts.size() == 0) columns.push_back(fmt::format("{}{}", prefix, i));
    for (const char* part : parts) columns.push_back(fmt::format("{}{}.{}", prefix, i, part));
  }
  return columns;
}

std::vector<std::string> suffixed(const std::string& prefix,
                                  std::initializer_list<const char*> parts) {
  std::vector<std::string> columns;
  for (const char* part : parts) columns.push_back(fmt::format("{}.{}", prefix, part));
  return columns;
}

std::string reaction_column(const std::string& joint, char axis) {
  return fmt::format("{}.reaction.F{}", joint, axis);
}

// ∫ f dt over the rows by the trapezoidal rule.
double integral(const std::vector<double>& t, const std::vector<double>& f) {
  double sum = 0.0;
  for (std::size_t k = 1; k < t.size(); ++k) sum += 0.5 * (f[k] + f[k - 1]) * (t[k] - t[k - 1]);
  return sum;
}

double time_average(const std::vector<double>& t, const std::vector<double>& f) {
  const double span = t.back() - t.front();
  return span > 0.0 ? integral(t, f) / span : f.front();
}

analysis::StepInfo step_figures(const Metric& metric, const ColumnSink& table) {
  const std::vector<double>& t = table.column("time");
  const std::vector<double>& y = table.column(metric.of);
  analysis::TimeResponse response;
  response.time = Eigen::Map<const VecX>(t.data(), static_cast<Eigen::Index>(t.size()));
  response.outputs.resize(static_cast<Eigen::Index>(y.size()), 1);
  for (std::size_t k = 0; k < y.size(); ++k) {
    response.outputs(static_cast<Eigen::Index>(k), 0) = y[k] - y.front();
  }
  return analysis::step_info(response, 0, y.back() - y.front(), metric.band);
}

double simulated_value(const Metric& metric, const ColumnSink& table,
                       const simulate::SimulationSummary& summary) {
  using K = Metric::Kind;
  if (metric.kind == K::kMaxAuditDrift) {
    for (const simulate::AuditEntry& entry : summary.audit) {
      if (entry.name == metric.of) return entry.max_drift;
    }
    return kUndefined;  // not audited in this run
  }
  if (metric.kind == K::kMaxReaction) {
    const auto& fx = table.column(reaction_column(metric.of, 'x'));
    const auto& fy = table.column(reaction_column(metric.of, 'y'));
    const auto& fz = table.column(reaction_column(metric.of, 'z'));
    double largest = 0.0;
    for (std::size_t k = 0; k < fx.size(); ++k) {
      largest = std::max(largest, std::sqrt(fx[k] * fx[k] + fy[k] * fy[k] + fz[k] * fz[k]));
    }
    return largest;
  }
  const std::vector<double>& y = table.column(metric.of);
  switch (metric.kind) {
    case K::kFinal:
      return y.back();
    case K::kInitial:
      return y.front();
    case K::kMax:
      return *std::max_element(y.begin(), y.end());
    case K::kMin:
      return *std::min_element(y.begin(), y.end());
    case K::kMaxAbs: {
      double largest = 0.0;
      for (double v : y) largest = std::max(largest, std::abs(v));
      return largest;
    }
    case K::kMean:
      return time_average(table.column("time"), y);
    case K::kRms: {
      std::vector<double> squares(y.size());
      std::transform(y.begin(), y.end(), squares.begin(), [](double v) { return v * v; });
      return std::sqrt(time_average(table.column("time"), squares));
    }
    case K::kRiseTime:
      return step_figures(metric, table).rise_time;
    case K::kSettlingTime:
      return step_figures(metric, table).settling_time;
    case K::kOvershoot:
      return step_figures(metric, table).overshoot;
    case K::kPeakTime:
      return step_figures(metric, table).peak_time;
    default:
      break;
  }
  throw InvalidArgument(
      fmt::format("metric {} is not a figure of a simulation", metric_keyword(metric.kind)));
}

}  // namespace

std::vector<std::string> metric_columns(const Metric& metric, int states) {
  using K = Metric::Kind;
  const bool named = !metric.name.empty();
  switch (metric.kind) {
    case K::kPoles:
      return numbered(named ? metric.name : "pole", states, {"re", "im"});
    case K::kNaturalFrequencies:
      return numbered(named ? metric.name : "wn", states, {});
    case K::kDampingRatios:
      return numbered(named ? metric.name : "zeta", states, {});
    case K::kCentreOfMass:
      return suffixed(named ? metric.name : "com", {"x", "y", "z"});
    case K::kInertia:
      return suffixed(named ? metric.name : "I", {"xx", "yy", "zz", "xy", "xz", "yz"});
    case K::kPrincipalMoments:
      return suffixed(named ? metric.name : "I_principal", {"1", "2", "3"});
    case K::kMass:
      return {named ? metric.name : "mass"};
    default:
      break;
  }
  if (named) return {metric.name};
  return {fmt::format("{}({})", metric_keyword(metric.kind), metric.of)};
}

std::vector<std::string> columns_read(std::span<const Metric> metrics) {
  std::vector<std::string> columns;
  for (const Metric& m : metrics) {
    if (m.kind == Metric::Kind::kMaxReaction) {
      for (char axis : {'x', 'y', 'z'}) columns.push_back(reaction_column(m.of, axis));
    } else if (m.kind <= Metric::Kind::kPeakTime) {
      columns.push_back(m.of);
    }
  }
  return columns;
}

ColumnSink::ColumnSink(std::vector<std::string> wanted, bool keep_all)
    : wanted_(std::move(wanted)), keep_all_(keep_all) {
  wanted_.push_back("time");
}

void ColumnSink::begin(std::span<const std::string> columns) {
  kept_names_.clear();
  indices_.clear();
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (keep_all_ || std::find(wanted_.begin(), wanted_.end(), columns[i]) != wanted_.end()) {
      kept_names_.push_back(columns[i]);
      indices_.push_back(i);
    }
  }
  kept_.assign(indices_.size(), {});
}

void ColumnSink::row(std::span<const double> values) {
  for (std::size_t c = 0; c < indices_.size(); ++c) kept_[c].push_back(values[indices_[c]]);
}

const std::vector<double>& ColumnSink::column(const std::string& name) const {
  const auto it = std::find(kept_names_.begin(), kept_names_.end(), name);
  if (it == kept_names_.end()) {
    throw InvalidArgument(fmt::format("the run recorded no column '{}'", name));
  }
  return kept_[static_cast<std::size_t>(it - kept_names_.begin())];
}

std::vector<double> ColumnSink::row_major() const {
  std::vector<double> table;
  table.reserve(rows() * kept_.size());
  for (std::size_t r = 0; r < rows(); ++r) {
    for (const std::vector<double>& column : kept_) table.push_back(column[r]);
  }
  return table;
}

void evaluate(const Metric& metric, const ColumnSink& table,
              const simulate::SimulationSummary& summary, std::vector<double>& out) {
  out.push_back(simulated_value(metric, table, summary));
}

void evaluate(const Metric& metric, const analysis::Modes& modes, int states,
              std::vector<double>& out) {
  using K = Metric::Kind;
  for (int i = 0; i < states; ++i) {
    const bool have = static_cast<std::size_t>(i) < modes.modes.size();
    const analysis::Mode* mode = have ? &modes.modes[static_cast<std::size_t>(i)] : nullptr;
    switch (metric.kind) {
      case K::kPoles:
        out.push_back(mode ? mode->eigenvalue.real() : kUndefined);
        out.push_back(mode ? mode->eigenvalue.imag() : kUndefined);
        break;
      case K::kNaturalFrequencies:
        out.push_back(mode ? mode->natural_frequency : kUndefined);
        break;
      case K::kDampingRatios:
        out.push_back(mode ? mode->damping_ratio : kUndefined);
        break;
      default:
        throw InvalidArgument(fmt::format("metric {} is not a figure of a linearization",
                                          metric_keyword(metric.kind)));
    }
  }
}

void evaluate(const Metric& metric, const inertia::MassProperties& part, std::vector<double>& out) {
  using K = Metric::Kind;
  const Mat3& I = part.inertia_about_com();
  switch (metric.kind) {
    case K::kMass:
      out.push_back(part.mass());
      return;
    case K::kCentreOfMass:
      for (int i = 0; i < 3; ++i) out.push_back(part.center_of_mass()(i));
      return;
    case K::kInertia:
      out.insert(out.end(), {I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2)});
      return;
    case K::kPrincipalMoments: {
      const Vec3 moments = part.principal_axes().moments;
      for (int i = 0; i < 3; ++i) out.push_back(moments(i));
      return;
    }
    default:
      throw InvalidArgument(
          fmt::format("metric {} is not a figure of a part", metric_keyword(metric.kind)));
  }
}

}  // namespace momenta::sweep
