#pragma once
// Relative drift of quantities that should be conserved, at the end of a run and at its worst.

#include <string>
#include <vector>

#include "momenta/math/types.hpp"

namespace momenta::simulate {

/// One audited quantity. Its drift is (x(t) − x(0)) / scale for a scalar and |x(t) − x(0)| /
/// scale for a vector, with scale = max(|x(0)|, floor): relative to the initial value, and to
/// `floor` (a scale of the motion given when the entry was added) where x(0) is near zero, so a
/// drift is never 0/0. With x(0) = 0 and floor = 1 it is the absolute error.
struct AuditEntry {
  std::string name;
  double initial = 0.0;      ///< x(0), or |x(0)| for a vector
  double scale = 1.0;        ///< what drifts are divided by (> 0)
  double final_drift = 0.0;  ///< signed drift at the last record (≥ 0 for vectors)
  double max_drift = 0.0;    ///< largest |drift| over the run
  long records = 0;          ///< how many values were recorded
};

/// Keeps the drift of each audited quantity as values are recorded, step by step.
class ConservationAudit {
 public:
  /// Adds a scalar quantity with its value at t0. `floor` (≥ 0) is the smallest scale it is
  /// measured against (see AuditEntry). Returns its index for record(). Throws InvalidArgument
  /// for a non-finite initial value or a negative or non-finite floor.
  int add(std::string name, double initial, double floor = 0.0);
  /// Adds a vector quantity (e.g. H in the world frame), audited by |x(t) − x(0)| / scale.
  int add(std::string name, const Vec3& initial, double floor = 0.0);

  /// Records the current value of entry `index`. No allocation.
  void record(int index, double value);
  void record(int index, const Vec3& value);

  /// Starts again from the values given to add(): drifts and counts back to zero.
  void reset();

  const std::vector<AuditEntry>& entries() const { return entries_; }
  const AuditEntry& entry(int index) const { return entries_[index]; }
  bool empty() const { return entries_.empty(); }

 private:
  std::vector<AuditEntry> entries_;
  std::vector<Vec3> initial_vectors_;  // per entry; unused for scalars
};

}  // namespace momenta::simulate
