#pragma once
// Internal to momenta::analysis: independent coordinates of a constrained model about a
// consistent state, by coordinate partitioning (Wehage & Haug 1982; Haug, Computer-Aided
// Kinematics and Dynamics of Mechanical Systems, 1989, §6.3). See linearize.hpp for how
// linearize() uses them.

#include <string>
#include <vector>

#include "momenta/dynamics/constraints.hpp"
#include "momenta/dynamics/data.hpp"
#include "momenta/math/types.hpp"
#include "momenta/model/model.hpp"

namespace momenta::analysis::detail {

class ConstraintChart {
 public:
  /// Partitions the free coordinates (velocity indices `free`) at the consistent state (q0, v0):
  /// the independent rows of G (holonomic ones first, in row order), then dependent coordinates
  /// with well-conditioned columns, from the last free coordinate back, those named in
  /// `preferred` last. Throws InvalidArgument when no coordinate is left independent.
  ConstraintChart(const model::Model& model, const std::vector<int>& free, const VecX& q0,
                  const VecX& v0, const std::vector<std::string>& preferred);

  /// Velocity indices of the configuration states ξ, the velocity states ζ, and the dependent
  /// coordinates of each.
  const std::vector<int>& positions() const { return position_independent_; }
  const std::vector<int>& velocities() const { return velocity_independent_; }
  const std::vector<int>& dependent_positions() const { return position_dependent_; }
  const std::vector<int>& dependent_velocities() const { return velocity_dependent_; }

  /// The independent rows of G at the operating point: the holonomic ones, and those with the
  /// velocity-only rows after them (the rows the dependent coordinates solve).
  const std::vector<int>& holonomic_rows() const { return holonomic_rows_; }
  const std::vector<int>& velocity_rows() const { return velocity_rows_; }

  /// q(ξ) = q0 ⊕ δ with δ on the configuration states ξ, on the dependent coordinates solved so
  /// that the independent holonomic rows hold (Newton's method until |φ| stops decreasing), 0
  /// elsewhere; also returns δ. Throws NumericalError when |φ| stays above 1e-9 (m or rad): ξ
  /// reaches past where the partition is valid.
  void configuration(const VecX& xi, VecX& q, VecX& delta);

  /// v(q, ζ): ζ on the velocity states, v0 on the prescribed coordinates, the dependent
  /// velocities from the independent rows of G(q) v = 0.
  void velocity(const VecX& q, const VecX& zeta, VecX& v);

  /// T = ∂v_f/∂ζ at q (free coordinates × velocity states): the velocities of unit ζ at rest,
  /// so that G T = 0 and v_f = T ζ plus the prescribed coordinates' share.
  MatX velocity_map(const VecX& q);

 private:
  void evaluate_rows(const VecX& q);

  const model::Model& model_;
  dynamics::Data data_;
  dynamics::ConstraintRows rows_;
  VecX q0_, v0_;
  double length_;  // characteristic length, m: scales the Newton tolerances
  std::vector<int> free_, prescribed_;
  std::vector<int> holonomic_rows_, velocity_rows_;  // independent rows of each kind
  std::vector<int> position_independent_, position_dependent_;
  std::vector<int> velocity_independent_, velocity_dependent_;
};

}  // namespace momenta::analysis::detail
