#pragma once
// Joints: what connects a child body to its parent, and how its coordinates are laid out.
//
// Frames. Every joint has a frame J fixed in the parent body P, at pose X_PJ, and a frame J'
// fixed in the child body C, at pose X_CJ (J' in C). At the neutral configuration J' coincides
// with J; the joint moves J' relative to J by X_JJ'(q). The pose of the child in its parent is
//   X_PC(q) = X_PJ · X_JJ'(q) · X_CJ⁻¹.
// Axes are unit vectors expressed in J (and J' for the universal joint's second axis).
//
// Coordinates (nq configuration, nv velocity; Featherstone 2008, Table 4.1):
//
// | type        | nq | nv | q                                  | v                               |
// |-------------|----|----|------------------------------------|---------------------------------|
// | fixed       | 0  | 0  | —                                  | —                               |
// | revolute    | 1  | 1  | angle θ about axis (rad)           | θ̇                               |
// | prismatic   | 1  | 1  | displacement d along axis (m)      | ḋ                               |
// | cylindrical | 2  | 2  | [θ, d] about and along axis        | [θ̇, ḋ]                          |
// | universal   | 2  | 2  | [θ1, θ2]: X_JJ' = Rot(axis, θ1) Rot(axis2, θ2) | [θ̇1, θ̇2]             |
// | spherical   | 4  | 3  | quaternion q_JJ' [w, x, y, z]      | w_JJ'_J' (rad/s, in J')         |
// | planar      | 3  | 3  | [x, y, θ]: translation in J's x-y plane, then rotation θ about J's z |
// [ẋ, ẏ, θ̇] | | free        | 7  | 6  | [p_JoJ'o_J (3); q_JJ' (4, wxyz)]   | [w_JJ'_J' (3, in J');
// v = ṗ_JoJ'o_J (3, in J)] |
//
// The free joint's velocity is the child's angular velocity in its own frame (as for the
// spherical joint) followed by the rate of its position in the parent joint frame, so the
// translation is a plain vector space: q̇_p = v_lin exactly, and q̇_quat = ½ q ⊗ [0; ω]
// (MuJoCo's convention, ordered rotation first). Quaternions are integrated with the exponential
// map, never by adding and normalizing (see integrate() in model.hpp).

#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "momenta/math/spatial.hpp"
#include "momenta/math/types.hpp"

namespace momenta::model {

enum class JointType {
  fixed,
  revolute,
  prismatic,
  cylindrical,
  universal,
  spherical,
  planar,
  free
};

/// What a joint type is, one row per type: its names, sizes, axes, units and what it exports as.
/// Every reader, writer and algorithm that needs more than the joint's motion reads this table;
/// the motion itself is written in exhaustive switches (no `default:`: -Wswitch, an error in the
/// test build, names every switch a new type must join). docs/guides.md, "Adding a joint type".
struct JointTraits {
  JointType type;
  std::string_view name;   ///< lower case: "revolute"
  std::string_view alias;  ///< the other name model files accept ("hinge"), or empty
  int nq = 0;              ///< configuration size
  int nv = 0;              ///< velocity size (degrees of freedom)
  /// The axes it reads: 0, 1 (`axis`: revolute, prismatic, cylindrical) or 2 (`axis2` too).
  int axes = 0;
  int quaternion_at = -1;  ///< where its unit quaternion starts in its q; −1: none
  std::array<std::string_view, 7> q_units{};  ///< per coordinate: "rad", "m" or "1" (quaternion)
  std::array<std::string_view, 6> v_units{};  ///< per velocity: "rad/s" or "m/s"
  std::array<std::string_view, 7> q_names{};  ///< "<joint>.<name>": "angle", "qw", "x"
  std::array<std::string_view, 6> v_names{};  ///< "angle_rate", "wx", "vx"
  std::string_view q_layout;  ///< how q reads, for messages: "[x (m), y (m), angle (rad)]"
  std::string_view urdf;      ///< the URDF joint type it exports as; empty: URDF has none
};

inline constexpr std::array<JointTraits, 8> kJointTraits{{
    {JointType::fixed, "fixed", "weld", 0, 0, 0, -1, {}, {}, {}, {}, "no coordinates", "fixed"},
    {JointType::revolute,
     "revolute",
     "hinge",
     1,
     1,
     1,
     -1,
     {"rad"},
     {"rad/s"},
     {"angle"},
     {"angle_rate"},
     "(angle, rad)",
     "continuous"},
    {JointType::prismatic,
     "prismatic",
     "slider",
     1,
     1,
     1,
     -1,
     {"m"},
     {"m/s"},
     {"position"},
     {"position_rate"},
     "(displacement, m)",
     "prismatic"},
    {JointType::cylindrical,
     "cylindrical",
     "",
     2,
     2,
     1,
     -1,
     {"rad", "m"},
     {"rad/s", "m/s"},
     {"angle", "position"},
     {"angle_rate", "position_rate"},
     "[angle (rad), displacement (m)]",
     ""},
    {JointType::universal,
     "universal",
     "",
     2,
     2,
     2,
     -1,
     {"rad", "rad"},
     {"rad/s", "rad/s"},
     {"angle1", "angle2"},
     {"angle1_rate", "angle2_rate"},
     "[angle1, angle2] (rad)",
     ""},
    {JointType::spherical,
     "spherical",
     "ball",
     4,
     3,
     0,
     0,
     {"1", "1", "1", "1"},
     {"rad/s", "rad/s", "rad/s"},
     {"qw", "qx", "qy", "qz"},
     {"wx", "wy", "wz"},
     "quaternion [w, x, y, z]",
     ""},
    {JointType::planar,
     "planar",
     "",
     3,
     3,
     0,
     -1,
     {"m", "m", "rad"},
     {"m/s", "m/s", "rad/s"},
     {"x", "y", "angle"},
     {"x_rate", "y_rate", "angle_rate"},
     "[x (m), y (m), angle (rad)]",
     "planar"},
    {JointType::free,
     "free",
     "floating",
     7,
     6,
     0,
     3,
     {"m", "m", "m", "1", "1", "1", "1"},
     {"rad/s", "rad/s", "rad/s", "m/s", "m/s", "m/s"},
     {"x", "y", "z", "qw", "qx", "qy", "qz"},
     {"wx", "wy", "wz", "vx", "vy", "vz"},
     "[x, y, z (m), qw, qx, qy, qz]",
     "floating"},
}};

/// The row of kJointTraits for `type`.
constexpr const JointTraits& joint_traits(JointType type) {
  return kJointTraits[static_cast<std::size_t>(type)];
}

namespace detail {
constexpr bool traits_in_enum_order() {
  for (std::size_t i = 0; i < kJointTraits.size(); ++i) {
    if (kJointTraits[i].type != static_cast<JointType>(i)) return false;
  }
  return true;
}
}  // namespace detail
static_assert(detail::traits_in_enum_order(), "kJointTraits lists the joint types in enum order");

/// The lower-case name of a joint type: "fixed", "revolute", ...
std::string_view joint_type_name(JointType type);

/// The joint type with that name or alias (kJointTraits: "weld", "hinge", "slider", "ball",
/// "floating"); throws InvalidArgument with the list of names (and a "did you mean" suggestion)
/// for an unknown one.
JointType joint_type_from_name(std::string_view name);

/// Configuration size nq of a joint type.
constexpr int joint_nq(JointType type) { return joint_traits(type).nq; }

/// Velocity size nv of a joint type (its degrees of freedom).
constexpr int joint_nv(JointType type) { return joint_traits(type).nv; }

/// Whether velocity coordinate k (0-based within the joint) of a joint of this type is a rotation
/// rate (rad/s) rather than a translation rate (m/s).
constexpr bool is_rotation_rate(JointType type, int k) {
  return joint_traits(type).v_units[static_cast<std::size_t>(k)] == "rad/s";
}

/// Stops on a revolute or prismatic joint's coordinate (rad or m): the joint moves freely between
/// `lower` and `upper`; a stop it reaches strikes it with Newton's restitution (its rate after is
/// −restitution × its rate before) and holds it while the stop pushes (docs/contacts.md,
/// simulate/unilaterals.hpp). A bound may be infinite (a stop on one side only).
struct JointLimits {
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  double restitution = 0.0;  ///< e ∈ [0, 1]: 0 a plastic stop, 1 an elastic one
};

/// A joint as described by a user and stored in the Model. The fields under "set by
/// ModelBuilder::build()" are ignored on input and filled in by the builder.
struct Joint {
  std::string name;
  JointType type = JointType::revolute;
  std::string parent;  ///< Name of the parent body; "world" for the ground.
  std::string child;   ///< Name of the child body.

  Transform X_PJ;  ///< Joint frame J in the parent body frame P.
  Transform X_CJ;  ///< Child-side joint frame J' in the child body frame C.

  /// Unit axis in J: revolute, prismatic and cylindrical axis, the universal joint's first axis.
  Vec3 axis = Vec3::UnitZ();
  /// Unit axis in J': the universal joint's second axis (not parallel to `axis`).
  Vec3 axis2 = Vec3::UnitY();

  /// Initial configuration (size nq); empty means neutral (zeros, identity quaternion).
  VecX q0;
  /// Initial velocity (size nv); empty means zero.
  VecX v0;

  /// Viscous damping coefficient c ≥ 0 on every velocity coordinate: τ = −c v (N·m·s/rad on
  /// angles, N·s/m on displacements). Evaluated by the force-element code, not by the
  /// dynamics algorithms.
  double damping = 0.0;
  /// Armature ≥ 0 on every velocity coordinate (kg·m² on a rotation, kg on a translation): the
  /// reflected inertia of a motor's rotor, gear² × rotor inertia, as MuJoCo's joint `armature`. It
  /// adds to the coordinate's diagonal of the mass matrix — a torque armature · v̇ and a kinetic
  /// energy ½ armature v² — with no gyroscopic or reaction effect on the bodies (the rotor's own
  /// spin axis is not modelled), so a model with armature does not conserve angular momentum.
  double armature = 0.0;

  /// Prescribed motion: empty for a joint driven by forces; otherwise one signal name per
  /// coordinate (size nq == nv: revolute, prismatic, cylindrical, universal, planar) whose value,
  /// rate and acceleration are q, v and v̇ of that coordinate. The signals live in the Model.
  std::vector<std::string> prescribed_signals;

  /// Stops on the coordinate of a revolute or prismatic joint that no signal prescribes; none
  /// when empty.
  std::optional<JointLimits> limits;

  // --- set by ModelBuilder::build() ----------------------------------------------------------
  int index = -1;                              ///< Index of this joint in Model::joints().
  int parent_index = -1;                       ///< Index of the parent body (0 = world).
  int child_index = -1;                        ///< Index of the child body; always index + 1.
  int q_index = -1;                            ///< First configuration coordinate in q.
  int v_index = -1;                            ///< First velocity coordinate in v.
  std::vector<int> prescribed_signal_indices;  ///< Indices into Model::signals().

  int nq() const { return joint_nq(type); }
  int nv() const { return joint_nv(type); }
  bool is_prescribed() const { return !prescribed_signals.empty(); }
};

/// X_JJ'(q): the pose of the child-side joint frame in the joint frame for configuration `q`
/// (the joint's nq coordinates). Quaternions are normalized before use.
Transform joint_transform(const Joint& joint, const double* q);

/// The joint's motion subspace S in J' (6 × nv): J''s spatial velocity relative to J, expressed in
/// J' about J'o, is S v. Returned in the leading nv columns of a 6×6 matrix.
Mat6 joint_motion_subspace(const Joint& joint, const double* q);

}  // namespace momenta::model
