#pragma once
// Where a contact (model::Contact) is at one configuration: its gap, its normal and the point
// where its bodies touch (or would), in W — what a run's unilaterals locate and strike with and
// what the report draws the contact's force at.
//
//   ground:   n the plane's normal; gap = n · (c_b − plane_point) − r_b; point c_b − r_b n
//   sphere:   n = (c_b − c_a) / |c_b − c_a|; gap = |c_b − c_a| − r_a − r_b; point c_a + r_a n
//
// c_b (c_a) the centre of body b's (a's) sphere, or b's point. The normal points from a (or the
// plane) towards b: the contact's force on b is N n, N ≥ 0.

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

struct ContactGeometry {
  double gap = 0.0;               ///< m: ≥ 0 apart
  Vec3 normal_W = Vec3::UnitZ();  ///< unit, from a (or the plane) towards b
  Vec3 point_W = Vec3::Zero();    ///< the contact point (b's surface point nearest a)
};

/// The geometry of `contact` at data's poses (data.X_WB, set by forward_kinematics). Throws
/// NumericalError where two spheres' centres coincide (no line of centres). No allocation.
ContactGeometry contact_geometry(const model::Contact& contact, const Data& data);

}  // namespace momenta::dynamics
