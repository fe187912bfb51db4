#include <string_view>

#include "momenta/sweep/sweep_spec.hpp"

namespace momenta::sweep {

std::string_view metric_keyword(Metric::Kind kind) {
  switch (kind) {
    case Metric::Kind::kFinal:
      return "final";
    case Metric::Kind::kInitial:
      return "initial";
    case Metric::Kind::kMax:
      return "max";
    case Metric::Kind::kMin:
      return "min";
    case Metric::Kind::kMaxAbs:
      return "max_abs";
    case Metric::Kind::kMean:
      return "mean";
    case Metric::Kind::kRms:
      return "rms";
    case Metric::Kind::kRiseTime:
      return "rise_time";
    case Metric::Kind::kSettlingTime:
      return "settling_time";
    case Metric::Kind::kOvershoot:
      return "overshoot";
    case Metric::Kind::kPeakTime:
      return "peak_time";
    case Metric::Kind::kMaxReaction:
      return "max_reaction";
    case Metric::Kind::kMaxAuditDrift:
      return "max_audit_drift";
    case Metric::Kind::kPoles:
      return "poles";
    case Metric::Kind::kNaturalFrequencies:
      return "natural_frequencies";
    case Metric::Kind::kDampingRatios:
      return "damping_ratios";
    case Metric::Kind::kMass:
      return "mass";
    case Metric::Kind::kCentreOfMass:
      return "centre_of_mass";
    case Metric::Kind::kInertia:
      return "inertia";
    case Metric::Kind::kPrincipalMoments:
      return "principal_moments";
  }
  return "?";
}

std::optional<Metric::Kind> metric_kind(std::string_view keyword) {
  for (int k = 0; k <= static_cast<int>(Metric::Kind::kPrincipalMoments); ++k) {
    const auto kind = static_cast<Metric::Kind>(k);
    if (metric_keyword(kind) == keyword) return kind;
  }
  return std::nullopt;
}

}  // namespace momenta::sweep
