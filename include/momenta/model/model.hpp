#pragma once
// The Model: an immutable description of a multibody system — a tree of bodies connected by
// joints, gravity, force elements and input signals. Built and validated by ModelBuilder
// (model_builder.hpp); the algorithms in momenta/dynamics read it and write a Data.
//
// Indexing. Bodies are numbered 0..num_bodies()−1 with 0 the world; parents come before their
// children (parent_index < index), depth first from the world with each body's children in the
// order their joints were added (a file's order; MuJoCo's qpos and Pinocchio's q lay out a tree
// so). Joint j carries body j + 1 (num_joints() == num_bodies() − 1), so joints are in the same
// order. Joint j's coordinates are q[q_index, q_index + nq)
// and v[v_index, v_index + nv), stacked in joint order (layout per joint type in joint.hpp).
//
// Configuration space. q is not a vector space where it holds quaternions (spherical and free
// joints, nq ≠ nv): use integrate(), difference() and neutral() below to move on it.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "momenta/math/spatial.hpp"
#include "momenta/model/body.hpp"
#include "momenta/model/constraint.hpp"
#include "momenta/model/controller.hpp"
#include "momenta/model/force_element.hpp"
#include "momenta/model/joint.hpp"
#include "momenta/model/signal.hpp"

namespace momenta::model {

class ModelBuilder;
namespace detail {
class ModelAssembler;
}

/// What the algorithms precompute for each joint from its description (read-only; for
/// implementers of algorithms, not needed by users).
struct JointConstants {
  JointType type = JointType::fixed;
  int nq = 0;
  int nv = 0;
  int q_index = 0;
  int v_index = 0;
  int parent = 0;              ///< Parent body index.
  int child = 0;               ///< Child body index.
  Transform X_PJ;              ///< Joint frame in the parent.
  Transform X_JC;              ///< Child body frame in J' (X_CJ⁻¹).
  bool child_at_joint = true;  ///< X_CJ is the identity (C ≡ J').
  /// 1-dof joints: the motion subspace column in the child frame C (constant).
  Vec6 S_C = Vec6::Zero();
  /// 1-dof joints whose S_C is a unit basis vector e_k: k (0–2 rotation, 3–5 translation); −1
  /// otherwise. The algorithms' fast path for axis-aligned joints.
  int S_basis = -1;
  /// A revolute joint about the coordinate axis S_basis (< 3) of its child, with the child at
  /// the joint and the joint frame parallel to the parent's: X_PB = (Rot_k(q), p_PJ), whose
  /// transforms cost half the general ones (kernel::*_about_axis).
  bool turns_about_axis = false;
  Vec3 axis = Vec3::UnitZ();
  Vec3 axis2 = Vec3::UnitY();
  /// Joint::armature: added to D (ABA) and M's diagonal (CRBA), τ += armature · v̇ (RNEA).
  double armature = 0.0;
};

class Model {
 public:
  /// Bodies including the world (index 0).
  int num_bodies() const { return static_cast<int>(bodies_.size()); }
  /// Joints; joint j carries body j + 1.
  int num_joints() const { return static_cast<int>(joints_.size()); }
  /// Size of the configuration vector q.
  int nq() const { return nq_; }
  /// Size of the velocity vector v (degrees of freedom).
  int nv() const { return nv_; }

  /// Gravitational acceleration g in the world frame (m/s²), e.g. (0, 0, −9.81).
  const Vec3& gravity() const { return gravity_; }

  const std::vector<Body>& bodies() const { return bodies_; }
  const Body& body(int b) const { return bodies_[b]; }
  const std::vector<Joint>& joints() const { return joints_; }
  const Joint& joint(int j) const { return joints_[j]; }
  const std::vector<ForceElement>& force_elements() const { return force_elements_; }
  const std::vector<Signal>& signals() const { return signals_; }
  /// Constraints beyond the tree (model/constraint.hpp), and the total rows they add.
  const std::vector<Constraint>& constraints() const { return constraints_; }
  bool has_constraints() const { return !constraints_.empty(); }
  int num_constraint_rows() const { return constraint_rows_; }
  /// Feedback controllers driving some of the signals (model/controller.hpp), resolved.
  const std::vector<ResolvedController>& controllers() const { return controllers_; }
  bool has_controllers() const { return !controllers_.empty(); }
  /// True when a controller drives signal s (its signal of time is then not used).
  bool is_driven(int s) const;
  /// The joint whose motion signal s prescribes (one of its prescribed_signal_indices); nullopt
  /// when s is an input (a force's, a torque's, a controller's), not a motion.
  std::optional<int> joint_prescribed_by(int s) const;
  /// The coordinate signal s prescribes where that is one coordinate (a revolute, prismatic,
  /// cylindrical, universal or planar joint's: q index and v index); nullopt for a signal that
  /// prescribes nothing or part of a ball or free joint's rotation vector or position.
  struct Coordinate {
    int q = -1;
    int v = -1;
  };
  std::optional<Coordinate> prescribed_coordinate(int s) const;

  /// Parent body index of body b (−1 for the world).
  int parent(int b) const { return bodies_[b].parent_index; }

  /// Spatial inertia of body b about Bo, expressed in B (zero for the world).
  const SpatialInertia& spatial_inertia(int b) const { return inertias_[b]; }
  /// Total mass of all bodies (kg).
  double total_mass() const { return total_mass_; }

  /// Index of the body, joint or signal with that name; nullopt if there is none.
  std::optional<int> find_body(std::string_view name) const;
  std::optional<int> find_joint(std::string_view name) const;
  std::optional<int> find_signal(std::string_view name) const;
  std::optional<int> find_constraint(std::string_view name) const;
  /// Index of the body, joint or signal with that name; throws InvalidArgument with a "did you
  /// mean" suggestion if there is none.
  int body_index(std::string_view name) const;
  int joint_index(std::string_view name) const;
  int signal_index(std::string_view name) const;

  /// The joint owning configuration coordinate i (0 ≤ i < nq) or velocity coordinate i.
  int joint_of_q(int i) const { return joint_of_q_[i]; }
  int joint_of_v(int i) const { return joint_of_v_[i]; }
  /// Readable names of the coordinates: "hinge.angle", "base.qw", "base.vx", ... for messages,
  /// plots and CSV headers.
  const std::string& q_name(int i) const { return q_names_[i]; }
  const std::string& v_name(int i) const { return v_names_[i]; }

  /// True when any joint is prescribed by signals.
  bool has_prescribed_joints() const { return has_prescribed_; }
  /// True when any joint has stops (Joint::limits).
  bool has_joint_limits() const {
    for (const Joint& j : joints_) {
      if (j.limits) return true;
    }
    return false;
  }
  /// True when any constraint is a unilateral contact (model::Contact).
  bool has_contacts() const {
    for (const Constraint& c : constraints_) {
      if (is_unilateral(c)) return true;
    }
    return false;
  }

  /// The initial state: each joint's q0 and v0 (neutral and zero where not given), stacked.
  const VecX& initial_q() const { return q0_; }
  const VecX& initial_v() const { return v0_; }
  /// This model starting from `q` (size nq) and `v` (size nv) instead: a state file's (`momenta
  /// simulate --state`). Throws InvalidArgument naming the size expected, or the first
  /// non-finite entry with its coordinate's name.
  Model with_initial_state(const VecX& q, const VecX& v) const;
  /// This model with signal s following `shape` instead (its name kept): a measured input
  /// replayed as a table (identify/grey_box.hpp). Throws InvalidArgument for s out of range and
  /// what Signal's constructor throws for the shape.
  Model with_signal_shape(int s, Signal::Shape shape) const;
  /// This model with one more controller (an external law's: Python's simulate(controller=fn)).
  /// Throws what resolve_controller and check_controller_fits throw.
  Model with_controller(const Controller& controller) const;

  /// Per-joint constants for the algorithms (see JointConstants).
  const std::vector<JointConstants>& joint_constants() const { return constants_; }

 private:
  friend class detail::ModelAssembler;
  Model() = default;

  Vec3 gravity_ = Vec3(0, 0, -9.81);
  std::vector<Body> bodies_;
  std::vector<Joint> joints_;
  std::vector<JointConstants> constants_;
  std::vector<SpatialInertia> inertias_;
  std::vector<ForceElement> force_elements_;
  std::vector<Signal> signals_;
  std::vector<Constraint> constraints_;
  std::vector<ResolvedController> controllers_;
  int constraint_rows_ = 0;
  std::vector<int> joint_of_q_;
  std::vector<int> joint_of_v_;
  std::vector<std::string> q_names_;
  std::vector<std::string> v_names_;
  VecX q0_;
  VecX v0_;
  int nq_ = 0;
  int nv_ = 0;
  double total_mass_ = 0.0;
  bool has_prescribed_ = false;
};

// --- Configuration space ---------------------------------------------------------------------

/// The neutral configuration (size nq): zero angles and displacements, identity quaternions.
VecX neutral(const Model& model);

/// q_out = q ⊕ v·dt: moves q along the constant velocity v (size nv) for dt seconds. Rotation
/// coordinates use the exponential map, q_JJ'(dt) = q_JJ' ⊗ exp(ω dt) with ω in J' (exact for
/// constant body angular velocity; no add-and-normalize); everything else, including the free
/// joint's translation, adds v·dt. q_out may alias q. Sizes: q, q_out nq; v nv.
void integrate(const Model& model, const VecX& q, const VecX& v, double dt, VecX& q_out);
VecX integrate(const Model& model, const VecX& q, const VecX& v, double dt);

/// The tangent vector d (size nv) with integrate(model, q0, d, 1) == q1: the rotation vector
/// log(q0⁻¹ ⊗ q1) (|·| ≤ π, in J') on rotations, q1 − q0 elsewhere.
void difference(const Model& model, const VecX& q0, const VecX& q1, VecX& d);
VecX difference(const Model& model, const VecX& q0, const VecX& q1);

/// q̇ (size nq) for velocity v at q: ½ q ⊗ [0; ω] on quaternions, v elsewhere.
void configuration_rate(const Model& model, const VecX& q, const VecX& v, VecX& qdot);

/// Rate δ̇ (size nv) of local coordinates q = q_base ⊕ δ when the velocity is v:
/// J_r(δ)⁻¹ ω on rotations (math/lie_group.hpp), v elsewhere (Munthe-Kaas 1998).
void local_coordinate_rate(const Model& model, const VecX& delta, const VecX& v, VecX& delta_rate);

/// Normalizes every quaternion in q in place; throws NumericalError naming the joint if one has
/// zero or non-finite norm.
void normalize(const Model& model, VecX& q);

/// Throws InvalidArgument naming `what` and the sizes unless q has size nq and v size nv.
void check_state_sizes(const Model& model, const VecX& q, const VecX& v, std::string_view what);

}  // namespace momenta::model
