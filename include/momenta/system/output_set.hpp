#pragma once
// The outputs a user asks for (model/output_spec.hpp: what `momenta simulate` writes as extra CSV
// columns and `momenta linearize` takes as outputs y), resolved against a model and evaluated on
// its state.

#include <span>
#include <string>
#include <vector>

#include "momenta/math/types.hpp"
#include "momenta/model/model.hpp"
#include "momenta/model/output_spec.hpp"

namespace momenta::system {

class MultibodySystem;

/// A model's outputs, resolved against it once.
class OutputSet {
 public:
  /// Resolves every target by name. Throws InvalidArgument naming the output and what is wrong:
  /// an unknown target (with a did-you-mean), a quantity that does not fit the target (a spring
  /// length of a joint), a component out of range, or a repeated column name.
  OutputSet(const model::Model& model, std::vector<model::OutputSpec> specs);

  const std::vector<model::OutputSpec>& specs() const { return specs_; }
  /// Every column, in order: "tip.x", "tip.y", "tip.z", "angle", ...
  const std::vector<std::string>& column_names() const { return columns_; }
  /// Each column's unit (model/units.hpp): "m", "rad/s", "N·m", ...
  const std::vector<std::string>& column_units() const { return units_; }
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
    int frame = 0;      // body quantities: the body whose frame they are seen from (0: world)
  };
  std::vector<model::OutputSpec> specs_;
  std::vector<Column> resolved_;
  std::vector<std::string> columns_;
  std::vector<std::string> units_;
  bool needs_reactions_ = false;
  int nq_ = 0, nv_ = 0;
  // Scratch for evaluate(): the state with prescribed motion applied, and v̇ (sized once).
  mutable VecX q_, v_, vdot_;
};

}  // namespace momenta::system
