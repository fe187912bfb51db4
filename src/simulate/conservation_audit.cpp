#include "momenta/simulate/conservation_audit.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta::simulate {

namespace {

// max(|x0|, floor), and 1 where both are zero (the drift is then the absolute error).
double audit_scale(const std::string& name, double magnitude, double floor) {
  if (!std::isfinite(magnitude)) {
    throw InvalidArgument(fmt::format(
        "conservation audit of {}: the initial value {} is not finite", name, magnitude));
  }
  if (!(floor >= 0.0) || !std::isfinite(floor)) {
    throw InvalidArgument(
        fmt::format("conservation audit of {}: the scale floor {} must be finite and non-negative",
                    name, floor));
  }
  const double scale = std::max(magnitude, floor);
  return scale > 0.0 ? scale : 1.0;
}

// The largest drift so far; a NaN, once seen, stays (std::max would drop it).
void update_max(AuditEntry& entry, double size) {
  if (std::isnan(entry.max_drift)) return;
  if (!(size <= entry.max_drift)) entry.max_drift = size;
}

}  // namespace

int ConservationAudit::add(std::string name, double initial, double floor) {
  const double scale = audit_scale(name, std::abs(initial), floor);
  entries_.push_back({std::move(name), initial, scale, 0.0, 0.0, 0});
  initial_vectors_.push_back(Vec3::Zero());
  return static_cast<int>(entries_.size()) - 1;
}

int ConservationAudit::add(std::string name, const Vec3& initial, double floor) {
  const double norm = initial.norm();
  const double scale = audit_scale(name, norm, floor);
  entries_.push_back({std::move(name), norm, scale, 0.0, 0.0, 0});
  initial_vectors_.push_back(initial);
  return static_cast<int>(entries_.size()) - 1;
}

void ConservationAudit::record(int index, double value) {
  AuditEntry& entry = entries_[index];
  entry.final_drift = (value - entry.initial) / entry.scale;
  update_max(entry, std::abs(entry.final_drift));
  ++entry.records;
}

void ConservationAudit::record(int index, const Vec3& value) {
  AuditEntry& entry = entries_[index];
  entry.final_drift = (value - initial_vectors_[index]).norm() / entry.scale;
  update_max(entry, entry.final_drift);
  ++entry.records;
}

void ConservationAudit::reset() {
  for (AuditEntry& entry : entries_) {
    entry.final_drift = 0.0;
    entry.max_drift = 0.0;
    entry.records = 0;
  }
}

}  // namespace momenta::simulate
