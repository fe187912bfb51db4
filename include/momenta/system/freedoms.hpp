#pragma once
// How many degrees of freedom a model has once its prescribed coordinates and constraints have
// taken theirs: the number of independent speeds a user can still give, the size of a
// linearization's velocity states. A four-bar has three joint speeds, two independent loop-
// closure rows and one freedom; driven by its crank it has none.

#include "momenta/model/model.hpp"

namespace momenta::system {

struct Freedoms {
  int speeds = 0;      ///< velocity coordinates of the joints (Model::nv)
  int prescribed = 0;  ///< of them, those driven by signals
  int constraint_rows =
      0;  ///< the constraints' rows (position and velocity); open contacts have none
  /// Of those, the independent ones over the unprescribed speeds at the initial configuration
  /// (the others are implied: a planar loop's out-of-plane rows).
  int independent_rows = 0;

  /// speeds − prescribed − independent_rows.
  int free() const { return speeds - prescribed - independent_rows; }
};

/// Counts the model's freedoms at its initial configuration (quaternions normalized). Rows
/// that are dependent there but not elsewhere (a mechanism started at a dead point) make it an
/// overcount; the solver names such a start when a run reaches it.
Freedoms count_freedoms(const model::Model& model);

}  // namespace momenta::system
