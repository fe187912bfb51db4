#pragma once
// Named model quantities a user asks for: what `momenta simulate` writes as extra CSV columns and
// what `momenta linearize` takes as outputs y (the rows of C and D).
//
// An output names one quantity of one joint, body, signal or force element. Vector quantities are
// three columns, "<name>.x", "<name>.y", "<name>.z", unless a single component is chosen; joint
// quantities are one column per coordinate, "<name>.<i>", unless one coordinate is chosen. A
// single column is called "<name>".

#include <span>
#include <string>
#include <vector>

#include "momenta/dynamics/reactions.hpp"
#include "momenta/math/types.hpp"
#include "momenta/model/model.hpp"

namespace momenta::simulate {

class MultibodySystem;

enum class OutputQuantity {
  joint_position,         ///< joint coordinates q (nq; quaternions as w, x, y, z)
  joint_velocity,         ///< joint speeds v (nv)
  joint_effort,           ///< generalized force on the joint: element forces + prescribed drive
  body_position,          ///< p_WoP_W of a point P fixed in the body (m)
  body_velocity,          ///< v_WP_W (m/s)
  body_acceleration,      ///< a_WP_W (m/s²)
  body_angular_velocity,  ///< w_WB_W (rad/s)
  reaction_force,         ///< force the joint transmits to its child (N), in `frame`
  reaction_moment,        ///< moment about the child-side joint frame's origin (N·m), in `frame`
  signal,                 ///< an input signal's value
  spring_length,          ///< a linear spring-damper's length ℓ (m)
  spring_tension,         ///< its tension k (ℓ − ℓ0) + c ℓ̇ (N)
};

/// The name used in model files: "position", "velocity", "effort", "reaction_force", ...
/// (see docs/model-format.md) — joint and body quantities share "position" and "velocity".
std::string_view output_quantity_name(OutputQuantity quantity);

/// One requested output, as written in a model file.
struct OutputSpec {
  std::string name;  ///< column name (stem)
  OutputQuantity quantity = OutputQuantity::body_position;
  std::string target;         ///< the joint, body, signal or force element it is of
  Vec3 point = Vec3::Zero();  ///< body quantities: the point, p_BoP_B (m)
  int component = -1;         ///< 0, 1, 2 for x, y, z (or one joint coordinate); −1 for all
  dynamics::ReactionFrame frame = dynamics::ReactionFrame::world;  ///< reactions only
};

/// A model's outputs, resolved against it once.
class OutputSet {
 public:
  /// Resolves every target by name. Throws InvalidArgument naming the output and what is wrong:
  /// an unknown target (with a did-you-mean), a quantity that does not fit the target (a spring
  /// length of a joint), a component out of range, or a repeated column name.
  OutputSet(const model::Model& model, std::vector<OutputSpec> specs);

  const std::vector<OutputSpec>& specs() const { return specs_; }
  /// Every column, in order: "tip.x", "tip.y", "tip.z", "angle", ...
  const std::vector<std::string>& column_names() const { return columns_; }
  std::size_t size() const { return columns_.size(); }
  /// Whether any output is a reaction (evaluate() then runs joint_reactions).
  bool needs_reactions() const { return needs_reactions_; }

  /// Writes every column's value (size()) at (t, q, v): runs system.evaluate(t, q, v) and, when
  /// needed, joint_reactions (with the prescribed joints' coordinates set to their signals at t,
  /// as evaluate() sets them). `system` must be built on the model this set was resolved
  /// against. Throws InvalidArgument if values.size() != size(). No allocation. Not thread-safe:
  /// one OutputSet (and one system) per thread.
  void evaluate(MultibodySystem& system, double t, const VecX& q, const VecX& v,
                std::span<double> values) const;

 private:
  struct Column {
    int spec = 0;       // index into specs_
    int index = 0;      // resolved joint, body, signal or element
    int component = 0;  // coordinate or axis
  };
  std::vector<OutputSpec> specs_;
  std::vector<Column> resolved_;
  std::vector<std::string> columns_;
  bool needs_reactions_ = false;
  int nq_ = 0, nv_ = 0;
  // Scratch for evaluate(): the state with prescribed motion applied, and v̇ (sized once).
  mutable VecX q_, v_, vdot_;
};

}  // namespace momenta::simulate
