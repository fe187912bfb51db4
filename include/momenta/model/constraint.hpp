#pragma once
// Constraints: what a tree of joints cannot express — loops closed between two bodies, rigid
// links and taut wires, wheels rolling without slipping, knife edges, gears — as data.
//
// These structs describe the constraints; ModelBuilder::build() checks them and fills the
// resolved indices; dynamics/constraints.hpp turns them into rows of the constraint equations
// and system::MultibodySystem enforces them (docs/constraints.md).
//
// Frames and points are fixed in their body and given in its frame; "world" is the ground. Every
// constraint acts on body b and, equal and opposite, on body a (or the ground), so that the
// forces it reports are those on b.
//
// | type        | rows | position rows | what it keeps                                          |
// |-------------|------|---------------|--------------------------------------------------------|
// | weld        | 6    | 6             | frame B coincides with frame A                         |
// | point       | 3    | 3             | the origins of A and B coincide (a ball joint)          |
// | hinge       | 5    | 5             | origins coincide, B's z axis stays along A's z axis     |
// | slider      | 5    | 5             | B's origin on A's z axis, orientations equal            |
// | distance    | 1    | 1             | |p_b − p_a| = length (a rigid link, a taut wire)       |
// | rolling     | 3    | 1             | the body's contact point with a plane has no velocity   |
// | knife_edge  | 1    | 0             | a body point does not slide across its blade            |
// | coupler     | 1    | 1             | q_a = ratio · q_b + offset between two 1-dof joints    |
// | contact     | 1, 3 | 1             | a point or sphere stays on or above the ground plane,  |
// |             |      |               | or outside another body's sphere; with friction, the   |
// |             |      |               | contact point does not slip while friction holds it    |
//
// A contact is unilateral (docs/contacts.md): its row is off while the body is clear of the
// plane or leaving it, and a run's simulate/unilaterals.hpp switches it on (ConstraintRows::
// enabled) while the plane holds the body up. Everything that forms the rows without a run — the
// analyses, the impulse equations, the symbolic equations — sees a contact as open.
//
// Rolling and knife-edge constraints are nonholonomic: besides the rolling contact's height they
// restrict velocities only, never positions.

#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "momenta/math/spatial.hpp"

namespace momenta::model {

/// A frame F fixed in a body: the body's name and X_BF (its pose in the body frame).
struct BodyFrame {
  std::string body;
  Transform X_BF;
  int body_index = -1;  ///< Set by ModelBuilder::build().
};

/// Which relative motions a loop closure removes.
enum class LoopType {
  weld,    ///< all six
  point,   ///< the three translations (a ball joint)
  hinge,   ///< the three translations and the two rotations about axes ⊥ z_A (a revolute joint)
  slider,  ///< the translations ⊥ z_A and all three rotations (a prismatic joint along z_A)
};

/// Closes a kinematic loop between frame `a` (on body a) and frame `b` (on body b): a joint that
/// the tree does not carry. Rows are expressed in frame A's axes: translations e_k·(p_Bo − p_Ao)
/// (all three, or the two ⊥ z_A for a slider), rotations as the dot products of the two frames'
/// axes that vanish when they are aligned (x_A·y_B, y_A·z_B, z_A·x_B for a weld or slider;
/// x_A·z_B, y_A·z_B for a hinge).
struct LoopClosure {
  std::string name;
  LoopType type = LoopType::point;
  BodyFrame a;
  BodyFrame b;
};

/// A massless rigid link, or a taut wire, of `length` between point a and point b:
/// |p_b − p_a| = length. Its tension T > 0 pulls the points together.
struct DistanceLink {
  std::string name;
  BodyFrame a;  ///< only the frame's origin is used
  BodyFrame b;
  double length = 0.0;  ///< m, > 0
};

enum class RollingShape {
  disk,    ///< a thin disk or wheel: touches the plane at one point of its rim
  sphere,  ///< a ball: touches the plane straight below its centre
};

/// Rolling without slipping of a disk or sphere of `radius` fixed in `body` on a fixed plane
/// (the ground): the body's material point at the contact has zero velocity. The disk's centre is
/// frame.p and its axis frame's z axis; the sphere's centre is frame.p. The plane passes through
/// plane_point with unit normal plane_normal (world), the side the body is on.
///
/// Rows: the contact's height (holonomic: the centre stays `radius` above the plane, less for a
/// tilted disk), then the no-slip rows along the rolling direction and sideways. The forces on
/// the body at the contact: normal (along the normal; > 0 pushes the body off the plane),
/// longitudinal (along the rolling direction z_B × n / |z_B × n| for a disk, world x projected
/// on the plane for a sphere) and lateral (n × longitudinal).
struct RollingContact {
  std::string name;
  BodyFrame frame;
  RollingShape shape = RollingShape::disk;
  double radius = 0.0;  ///< m, > 0
  Vec3 plane_normal = Vec3::UnitZ();
  Vec3 plane_point = Vec3::Zero();
};

/// A knife edge (a sled's runner, the Chaplygin sleigh's blade) at point frame.p of `body`
/// along its frame's x axis, on a plane of unit normal plane_normal: the point has no velocity
/// across the blade within the plane, s · v_P = 0 with s = n × x_B / |n × x_B|. Nonholonomic.
/// Reports the lateral force along s.
struct KnifeEdge {
  std::string name;
  BodyFrame frame;
  Vec3 plane_normal = Vec3::UnitZ();
};

/// A gear pair, belt or lever between two 1-dof joints: q_a = ratio · q_b + offset (rad or m).
/// Reports the generalized force it applies on each joint (effort_a on joint a, effort_b =
/// −ratio · effort_a on joint b).
struct JointCoupler {
  std::string name;
  std::string joint_a;
  std::string joint_b;
  double ratio = 1.0;
  double offset = 0.0;
  int joint_a_index = -1;  ///< Set by ModelBuilder::build().
  int joint_b_index = -1;
};

/// The shape of body b's side of a contact.
enum class ContactShape {
  sphere,  ///< a sphere of `radius` about frame.p (a point where the radius is 0)
  disk,    ///< the rim of a disk or wheel of `radius` about frame.p, its axis frame's z axis
};

/// A unilateral contact of a body's point, sphere or disk rim (body b: `frame`, `radius`) with
/// the ground plane — the plane through plane_point with unit normal plane_normal (world), the body
/// on its normal's side —, with another body's plane (other_plane: plane_point and plane_normal in
/// body a's frame; `other` is then the plane's frame, z along its normal, x along a's x axis
/// projected on it, set by ModelBuilder::build()), or with another body's sphere (body a: `other`,
/// `other_radius`, where other.body names a body):
///
///   plane:    gap = n · (p_centre − plane_point) − radius  (n, plane_point in W)
///   sphere:   gap = |p_centre − p_other| − radius − other_radius,  n = (p_centre − p_other) / |…|
///   disk rim on a plane: gap = n · (p_centre − plane_point) − radius |n − (n · a) a|, a the axis
///   disk on a sphere: gap = |q − p_other| − other_radius, q the disk's point (face or rim)
///             nearest p_other, n = (q − p_other) / |…| (dynamics/contact_geometry.hpp)
///
/// p_centre = frame.p (radius 0 for a point). A disk touches at the rim point nearest the plane,
/// p_centre − radius w / |w| with w = n − (n · a) a; a disk lying flat (|w| below 1e-9) touches
/// with its face, which is not modelled: a run stops where a closed disk contact comes within 1e-6
/// rad of flat, and takes the rim point along the frame's x axis for an open one. Where the gap
/// closes the bodies are struck by Newton's law of restitution along n, e ∈ [0, 1]
/// (dynamics::restitution_impact); while they touch the row holds them and its force (`normal`, N,
/// on body b along n, > 0 pushing it away) is reported; where that force would pull, they are let
/// go.
///
/// Coulomb friction (docs/contacts.md): with static_friction μs > 0 the contact has two more rows,
/// tangent_1 and tangent_2 (the plane's tangents t₁, the world's — or body a's — x axis, or y
/// where n is near x, projected on the plane, and t₂ = n × t₁; between two spheres the world's x
/// or y projected across the normal), which hold the body's
/// material point at the contact still while the friction they need stays in the cone
/// |F_t| ≤ μs N (sticking). Beyond it the contact slides: those rows are off and the kinetic
/// friction μk N acts against the slip. Their forces (N, on body b along t₁ and t₂) are the
/// friction either way.
struct Contact {
  std::string name;
  BodyFrame frame;  ///< body b: the point, the sphere's centre, or the disk's centre and axis (z)
  ContactShape shape = ContactShape::sphere;
  double radius = 0.0;  ///< m, ≥ 0 (0: a point; a disk's > 0)
  Vec3 plane_normal = Vec3::UnitZ();
  Vec3 plane_point = Vec3::Zero();
  /// Body a's sphere centre, or its plane's frame (other_plane), where other.body names a body;
  /// empty (or "world"): the ground plane.
  BodyFrame other;
  bool other_plane = false;       ///< other.body's plane (plane_point, plane_normal in its frame)
  double other_radius = 0.0;      ///< m, ≥ 0
  double restitution = 0.0;       ///< e ∈ [0, 1]
  double static_friction = 0.0;   ///< μs ≥ 0 (0: frictionless)
  double kinetic_friction = 0.0;  ///< μk ∈ [0, μs]
  /// Whether it is with the ground plane (not another body's plane or sphere).
  bool on_ground() const { return other.body.empty() || other.body == "world"; }
  /// Whether it is with a plane: the ground's or another body's (not a sphere).
  bool on_plane() const { return on_ground() || other_plane; }
  /// Whether it has friction (μs > 0): its tangent rows exist.
  bool has_friction() const { return static_friction > 0.0; }
};

using Constraint =
    std::variant<LoopClosure, DistanceLink, RollingContact, KnifeEdge, JointCoupler, Contact>;

/// The constraint's name.
const std::string& constraint_name(const Constraint& constraint);

/// "weld", "point", "hinge", "slider", "distance", "rolling", "knife_edge", "coupler",
/// "contact".
std::string_view constraint_type_name(const Constraint& constraint);
std::string_view loop_type_name(LoopType type);

/// Number of scalar equations (rows) the constraint adds, and how many of them restrict
/// positions (the others restrict velocities only).
int constraint_rows(const Constraint& constraint);
int constraint_position_rows(const Constraint& constraint);

/// Whether a constraint is a unilateral contact (model::Contact): on only while it holds.
bool is_unilateral(const Constraint& constraint);

/// Each row's label, in row order (rows are named "<constraint>.<label>"): a loop closure's x, y,
/// z, rx, ry, rz (those it has: a hinge x … ry, a slider x, y, rx … rz), a distance link's
/// length, a rolling contact's normal, longitudinal, lateral, a knife edge's lateral, a
/// coupler's ratio, a contact's normal (and, with friction, tangent_1, tangent_2).
std::vector<std::string_view> constraint_row_labels(const Constraint& constraint);

/// What a constraint reports as its forces, by label (CSV columns "<constraint>.<label>"):
///   weld, point, hinge, slider  reaction.Fx .Fy .Fz .Mx .My .Mz — the wrench on body b, in W,
///                               the moment about frame B's origin (as joint reactions are)
///   distance                    tension (N; > 0 pulls the points together)
///   rolling                     normal, longitudinal, lateral (N; forces on the body at the
///                               contact, along the plane normal, the rolling direction and n ×
///                               that)
///   knife_edge                  lateral (N, along n × blade on the body)
///   coupler                     effort_a, effort_b (generalized forces on joint a and b: N·m or N)
///   contact                     normal (N, on the body along the plane normal; 0 while open);
///                               with friction also tangent_1, tangent_2 (N, the friction on
///                               the body along the plane's tangents, sticking or sliding)
std::vector<std::string_view> constraint_force_labels(const Constraint& constraint);

}  // namespace momenta::model
