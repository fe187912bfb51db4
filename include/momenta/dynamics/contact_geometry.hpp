#pragma once
// Where a contact (model::Contact) is at one configuration: its gap, its normal and the point
// where its bodies touch (or would), in W — what a run's unilaterals locate and strike with and
// what the report draws the contact's force at.
//
//   plane:    n the plane's normal; gap = n · (c_b − plane_point) − r_b; point c_b − r_b n
//   disk rim on a plane: point c_b − r_b w / |w|, w = n − (n · a) a (a the disk's axis);
//             gap = n · (point − plane_point)
//   sphere:   n = (c_b − c_a) / |c_b − c_a|; gap = |c_b − c_a| − r_a − r_b; point c_a + r_a n
//   disk on a sphere: the disk's point q nearest the sphere's centre c_a — over the face, under
//             c_a (n = ∓ the axis, the side c_a is on); else on the rim —; n = (q − c_a) / |q −
//             c_a|; gap = |q − c_a| − r_a; point c_a + r_a n
//
// c_b (c_a) the centre of body b's (a's) sphere, or b's point. The normal points from a (or the
// plane) towards b: the contact's force on b is N n, N ≥ 0. On another body's plane, n and the
// plane point turn and move with that body. The tangents t₁ (the ground's — or the plane's body's
// — x axis projected on the plane, its y axis where n is within 25° of x: plane_tangent) and
// t₂ = n × t₁ carry a contact's friction (model::Contact, its tangent_1 and tangent_2 rows).

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

struct ContactGeometry {
  double gap = 0.0;                  ///< m: ≥ 0 apart
  Vec3 normal_W = Vec3::UnitZ();     ///< unit, from a (or the plane) towards b
  Vec3 point_W = Vec3::Zero();       ///< the contact point (b's surface point nearest a)
  Vec3 tangent_1_W = Vec3::UnitX();  ///< unit, ⊥ normal_W
  Vec3 tangent_2_W = Vec3::UnitY();  ///< normal_W × tangent_1_W
};

/// The geometry of `contact` at data's poses (data.X_WB, set by forward_kinematics). Throws
/// NumericalError where two spheres' centres coincide (no line of centres), or a sphere's centre
/// lies in a disk's face or on its rim (no side to push it to). No allocation.
ContactGeometry contact_geometry(const model::Contact& contact, const Data& data);

/// The velocity (W) of body b's material point at `point_W` relative to body a's (or the
/// ground's): the contact's slip velocity once its normal part is taken out. Needs data's poses
/// and velocities (forward_kinematics(q, v)). No allocation.
Vec3 contact_point_velocity(const model::Contact& contact, const Data& data, const Vec3& point_W);

/// The gap's second time rate (m/s²) at data's poses, velocities and accelerations
/// (forward_kinematics(q, v, v̇)): the acceleration of body b's surface away from body a's, or
/// the plane, along the normal — the contact's first row's ẇ · (V_b − V_a) + w · (A_b − A_a)
/// (dynamics/constraints.hpp). No allocation.
double contact_gap_acceleration(const model::Contact& contact, const Data& data);

/// The slip's acceleration (m/s²) at data's poses, velocities and accelerations
/// (forward_kinematics(q, v, v̇)): the rates of the material points' relative velocity along the
/// contact's tangents t₁ and t₂ (its friction rows, which turn with the plane or the normal) —
/// each row's ẇ · (V_b − V_a) + w · (A_b − A_a). A contact with friction. No allocation.
Vec2 contact_slip_acceleration(const model::Contact& contact, const Data& data);

/// Whether a disk contact's axis is within `tolerance` rad of its plane's normal at data's
/// poses: the disk lies flat, touching with its face (not modelled). False for a sphere, and for a
/// disk against a sphere (whose face is modelled).
bool disk_lies_flat(const model::Contact& contact, const Data& data, double tolerance);

}  // namespace momenta::dynamics
