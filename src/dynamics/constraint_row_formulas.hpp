#pragma once
// Internal to momenta::dynamics: the constraint rows of dynamics/constraints.hpp as formulas of
// the motions of the frames they join, written once for any scalar S — double for the rows
// themselves (constraints.cpp), detail::Dual for their exact derivatives along a direction
// (constraint_derivatives.cpp).
//
// The small helpers are forced inline: they run in every evaluation of the constrained dynamics
// (constraint_equations), where calls to them cost ~5 % of the four-bar's v̇.
//
// Each formula hands its rows, in row order, to row(φ, holonomic, w, ẇ): the row's position
// value (0 on a velocity-only row), the wrench w it applies to body b (W, about Wo, [moment;
// force]) and w's rate ẇ along the frames' motion. The row's velocity value is then
// w · (V_b − V_a) and its acceleration value ẇ · (V_b − V_a) + w · (A_b − A_a).

#include <cmath>
#include <string>
#include <variant>

#include <fmt/format.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dual.hpp"
#include "momenta/common/error.hpp"
#include "momenta/dynamics/data.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta/math/spatial.hpp"
#include "momenta/math/types.hpp"
#include "momenta/model/constraint.hpp"

namespace momenta::dynamics::detail {

template <class S>
using Vec3Of = Eigen::Matrix<S, 3, 1>;
template <class S>
using Vec6Of = Eigen::Matrix<S, 6, 1>;
template <class S>
using Mat3Of = Eigen::Matrix<S, 3, 3>;

// Below this the direction a constraint acts along is not defined (a unit vector from a
// difference or cross product of near-parallel ones).
inline constexpr double kDegenerate = 1e-9;

// The motion of a frame F fixed in a body at one instant, in W: its pose (R = R_WF, p = p_WoFo),
// the body's spatial velocity V = [ω; velocity of the body point at Wo] and an acceleration A
// about Wo (its rate: the velocity-product part, or the whole acceleration).
template <class S>
struct FrameMotionOf {
  Mat3Of<S> R = Mat3Of<S>::Identity();
  Vec3Of<S> p = Vec3Of<S>::Zero();
  Vec6Of<S> V = Vec6Of<S>::Zero();
  Vec6Of<S> A = Vec6Of<S>::Zero();
  Vec3Of<S> w() const { return V.template head<3>(); }
  Vec3Of<S> point_velocity(const Vec3Of<S>& x) const { return V.template tail<3>() + w().cross(x); }
};

// Frame X_BF of `body` (the ground's where body is 0) at data's poses, and with `velocity` its
// spatial velocity; which acceleration goes with it (the velocity products, the whole) is the
// caller's (constraints.cpp's rows, contact_geometry.cpp's gap).
inline FrameMotionOf<double> frame_pose_and_velocity(const Data& data, int body,
                                                     const Transform& X_BF, bool velocity) {
  FrameMotionOf<double> m;
  const Transform& X_WB = data.X_WB[body];
  const Transform X_WF = X_WB * X_BF;
  m.R = X_WF.R;
  m.p = X_WF.p;
  if (velocity && body != 0) m.V = X_WB.act_motion(data.V_WB_B[body]);
  return m;
}

template <class S>
[[gnu::always_inline]] inline Vec6Of<S> spatial_of(const Vec3Of<S>& angular,
                                                   const Vec3Of<S>& linear) {
  Vec6Of<S> out;
  out << angular, linear;
  return out;
}

template <class S>
[[gnu::always_inline]] inline Vec6Of<S> force_at(const Vec3Of<S>& p, const Vec3Of<S>& f) {
  return spatial_of<S>(p.cross(f), f);
}

// ẇ of a force f at a point p, with rates ṗ and ḟ.
template <class S>
[[gnu::always_inline]] inline Vec6Of<S> force_rate(const Vec3Of<S>& p, const Vec3Of<S>& p_rate,
                                                   const Vec3Of<S>& f, const Vec3Of<S>& f_rate) {
  return spatial_of<S>(p_rate.cross(f) + p.cross(f_rate), f_rate);
}

// The rate of a unit vector u = x / |x| given ẋ and |x|.
template <class S>
[[gnu::always_inline]] inline Vec3Of<S> unit_rate(const Vec3Of<S>& u, const Vec3Of<S>& x_rate,
                                                  const S& norm) {
  return (x_rate - u * u.dot(x_rate)) / norm;
}

[[noreturn]] inline void degenerate(const std::string& name, const std::string& why) {
  throw NumericalError(fmt::format("constraint '{}': {}", name, why));
}

// Loop closure: translations along A's axes (all three, or the two across a slider's axis),
// then rotations n_A · m_B = 0 for the pairs of axes that are perpendicular when aligned, a unit
// multiplier being the moment −(n × m) on B.
template <class S, class Row>
void loop_rows(const model::LoopClosure& c, const FrameMotionOf<S>& ma, const FrameMotionOf<S>& mb,
               Row&& row) {
  const Vec3Of<S> d = mb.p - ma.p;
  const Vec3Of<S> pB_rate = mb.point_velocity(mb.p);
  const int translations = c.type == model::LoopType::slider ? 2 : 3;
  for (int k = 0; k < translations; ++k) {
    const Vec3Of<S> e = ma.R.col(k);
    const Vec3Of<S> e_rate = ma.w().cross(e);
    row(e.dot(d), true, force_at<S>(mb.p, e), force_rate<S>(mb.p, pB_rate, e, e_rate));
  }
  static constexpr int kAligned[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  static constexpr int kHinge[2][2] = {{0, 2}, {1, 2}};
  const auto rotation_row = [&](int i, int j) {
    const Vec3Of<S> n = ma.R.col(i);
    const Vec3Of<S> m = mb.R.col(j);
    const Vec3Of<S> n_rate = ma.w().cross(n);
    const Vec3Of<S> m_rate = mb.w().cross(m);
    const Vec3Of<S> moment = -n.cross(m);
    const Vec3Of<S> moment_rate = -(n_rate.cross(m) + n.cross(m_rate));
    row(n.dot(m), true, spatial_of<S>(moment, Vec3Of<S>::Zero()),
        spatial_of<S>(moment_rate, Vec3Of<S>::Zero()));
  };
  if (c.type == model::LoopType::hinge) {
    for (const auto& pair : kHinge) rotation_row(pair[0], pair[1]);
  } else if (c.type != model::LoopType::point) {
    for (const auto& pair : kAligned) rotation_row(pair[0], pair[1]);
  }
}

// Distance link: |p_b − p_a| − length along e = (p_b − p_a) / |p_b − p_a|.
template <class S, class Row>
void distance_rows(const model::DistanceLink& c, const FrameMotionOf<S>& ma,
                   const FrameMotionOf<S>& mb, Row&& row) {
  const Vec3Of<S> d = mb.p - ma.p;
  const S length = d.norm();
  if (!(value_of(length) > kDegenerate * c.length)) {
    degenerate(c.name, fmt::format("its two points coincide (distance {:.3g} m of {} m): the "
                                   "link has no direction",
                                   value_of(length), c.length));
  }
  const Vec3Of<S> e = d / length;
  const Vec3Of<S> pb_rate = mb.point_velocity(mb.p);
  const Vec3Of<S> e_rate = unit_rate<S>(e, pb_rate - ma.point_velocity(ma.p), length);
  row(length - c.length, true, force_at<S>(mb.p, e), force_rate<S>(mb.p, pb_rate, e, e_rate));
}

// Rolling contact of the body of mb on the ground: the contact's height, then no slip along
// the rolling direction and sideways.
template <class S, class Row>
void rolling_rows(const model::RollingContact& c, const FrameMotionOf<S>& mb, Row&& row) {
  const Vec3Of<S> n = c.plane_normal.cast<S>();
  const Vec3Of<S>& centre = mb.p;
  Vec3Of<S> u = -n, u_rate = Vec3Of<S>::Zero();         // from the centre to the contact
  Vec3Of<S> forward, forward_rate = Vec3Of<S>::Zero();  // rolling direction
  if (c.shape == model::RollingShape::disk) {
    const Vec3Of<S> axis = mb.R.col(2);
    const Vec3Of<S> axis_rate = mb.w().cross(axis);
    const Vec3Of<S> w = n - n.dot(axis) * axis;  // the normal's part in the disk's plane
    const S s = w.norm();
    if (!(value_of(s) > kDegenerate)) {
      degenerate(c.name,
                 "the disk lies flat on the plane (its axis is along the normal): its "
                 "rim touches everywhere and no rolling direction exists");
    }
    const Vec3Of<S> w_rate = -n.dot(axis_rate) * axis - n.dot(axis) * axis_rate;
    u = -w / s;
    u_rate = -unit_rate<S>(w / s, w_rate, s);
    forward = axis.cross(n) / s;  // |axis × n| = s
    forward_rate = unit_rate<S>(forward, axis_rate.cross(n), s);
  } else {
    // A sphere: any fixed tangent basis of the plane.
    forward = plane_tangent(c.plane_normal).cast<S>();
  }
  const Vec3Of<S> lateral = n.cross(forward);
  const Vec3Of<S> lateral_rate = n.cross(forward_rate);
  const Vec3Of<S> contact = centre + c.radius * u;
  const Vec3Of<S> contact_rate = mb.point_velocity(centre) + c.radius * u_rate;
  const Vec3Of<S> plane_point = c.plane_point.cast<S>();
  row(n.dot(contact - plane_point), true, force_at<S>(contact, n),
      force_rate<S>(contact, contact_rate, n, Vec3Of<S>::Zero()));
  row(S(0.0), false, force_at<S>(contact, forward),
      force_rate<S>(contact, contact_rate, forward, forward_rate));
  row(S(0.0), false, force_at<S>(contact, lateral),
      force_rate<S>(contact, contact_rate, lateral, lateral_rate));
}

// The tangents of a plane of unit normal n turning at n_rate, and their rates: t₁ the world's x
// projected on it (its y where n is within 25° of x: math/rotation.hpp's plane_tangent, which
// contact_geometry takes) and t₂ = n × t₁.
template <class S>
struct TangentsOf {
  Vec3Of<S> t1, t1_rate, t2, t2_rate;
};

template <class S>
TangentsOf<S> turning_tangents(const Vec3Of<S>& n, const Vec3Of<S>& n_rate) {
  const Vec3Of<S> x = std::abs(value_of(n.x())) < 0.9 ? Vec3Of<S>::UnitX() : Vec3Of<S>::UnitY();
  const S along = n.dot(x);
  const Vec3Of<S> p = x - n * along;
  const S norm = p.norm();
  TangentsOf<S> t;
  t.t1 = p / norm;
  t.t1_rate = unit_rate<S>(t.t1, Vec3Of<S>(-n_rate * along - n * n_rate.dot(x)), norm);
  t.t2 = n.cross(t.t1);
  t.t2_rate = n_rate.cross(t.t1) + n.cross(t.t1_rate);
  return t;
}

// Where body b of a contact (mb its frame) touches a plane of normal n turning at n_rate: the
// offset from its centre mb.p to the point of its surface nearest the plane, and the offset's
// rate. A sphere's −r n; a disk's rim point −r w / |w|, w = n − (n · a) a with a the disk's axis
// (the frame's z), which moves round the rim as the disk rolls — along the frame's x axis where
// the disk lies flat and no rim point is nearest (model::Contact).
template <class S>
struct SurfaceOffsetOf {
  Vec3Of<S> offset;
  Vec3Of<S> rate;
};

template <class S>
SurfaceOffsetOf<S> surface_offset(const model::Contact& c, const FrameMotionOf<S>& mb,
                                  const Vec3Of<S>& n, const Vec3Of<S>& n_rate) {
  if (c.shape == model::ContactShape::sphere) return {-c.radius * n, -c.radius * n_rate};
  const Vec3Of<S> axis = mb.R.col(2);
  const Vec3Of<S> axis_rate = mb.w().cross(axis);
  const S along = n.dot(axis);
  const Vec3Of<S> w = n - along * axis;  // the normal's part in the disk's plane
  const S s = w.norm();
  if (!(value_of(s) > kDegenerate)) {
    const Vec3Of<S> x = mb.R.col(0);
    return {c.radius * x, c.radius * mb.w().cross(x)};
  }
  const Vec3Of<S> w_rate =
      n_rate - (n_rate.dot(axis) + n.dot(axis_rate)) * axis - along * axis_rate;
  const Vec3Of<S> u = w / s;
  return {-c.radius * u, -c.radius * unit_rate<S>(u, w_rate, s)};
}

// Body b touching body a's sphere (ma: its centre s, radius r_a): the gap, the unit normal from
// a towards b and its rate, and the contact point s + r_a n on a's surface and its rate — where
// the force acts, along n on b and −n on a.
template <class S>
struct SphereTouchOf {
  S gap;
  Vec3Of<S> normal, normal_rate, contact, contact_rate;
};

template <class S>
SphereTouchOf<S> touching_sphere(const model::Contact& c, const FrameMotionOf<S>& ma, const S& gap,
                                 const Vec3Of<S>& normal, const Vec3Of<S>& normal_rate) {
  const Vec3Of<S> s_rate = ma.point_velocity(ma.p);
  return {gap, normal, normal_rate, Vec3Of<S>(ma.p + c.other_radius * normal),
          Vec3Of<S>(s_rate + c.other_radius * normal_rate)};
}

// Two spheres: the line of centres e = (c_b − c_a) / |c_b − c_a|, the gap |c_b − c_a| − r_a − r_b.
template <class S>
SphereTouchOf<S> sphere_against_sphere(const model::Contact& c, const FrameMotionOf<S>& ma,
                                       const FrameMotionOf<S>& mb) {
  const Vec3Of<S> d = mb.p - ma.p;
  const S length = d.norm();
  if (!(value_of(length) > kDegenerate)) {
    degenerate(c.name, "the spheres' centres coincide: no line of centres to push along");
  }
  const Vec3Of<S> e = d / length;
  const Vec3Of<S> e_rate =
      unit_rate<S>(e, Vec3Of<S>(mb.point_velocity(mb.p) - ma.point_velocity(ma.p)), length);
  return touching_sphere<S>(c, ma, S(length - (c.radius + c.other_radius)), e, e_rate);
}

// Body b's disk (mb: its centre c, its axis a the frame's z, radius r) against body a's sphere:
// the point of the disk, face or rim, nearest the sphere's centre s. With d = s − c, α = d · a
// and w = d − α a (d's part in the disk's plane):
//   face, |w| ≤ r: the point c + w under s; n = −sign(α) a; gap |α| − r_a;
//   rim,  |w| > r: the rim point p = c + r w / |w|; n = (p − s) / |p − s|; gap |p − s| − r_a.
// The two meet where |w| = r (there p − s = −α a). In either the gap's rate is n · (the material
// points' relative velocity) at the nearest point: the point's travel over the face or round
// the rim is across n.
template <class S>
SphereTouchOf<S> disk_against_sphere(const model::Contact& c, const FrameMotionOf<S>& ma,
                                     const FrameMotionOf<S>& mb) {
  const Vec3Of<S> axis = mb.R.col(2);
  const Vec3Of<S> axis_rate = mb.w().cross(axis);
  const Vec3Of<S> centre_rate = mb.point_velocity(mb.p);
  const Vec3Of<S> s_rate = ma.point_velocity(ma.p);
  const Vec3Of<S> d = ma.p - mb.p;
  const Vec3Of<S> d_rate = s_rate - centre_rate;
  const S along = d.dot(axis);
  const S along_rate = d_rate.dot(axis) + d.dot(axis_rate);
  const Vec3Of<S> w = d - along * axis;
  const S in_plane = w.norm();
  if (!(value_of(in_plane) > c.radius)) {  // over the face
    if (!(std::abs(value_of(along)) > kDegenerate)) {
      degenerate(c.name,
                 "the sphere's centre is in the disk's face: no side of the disk to push it to");
    }
    const double side = value_of(along) > 0.0 ? 1.0 : -1.0;  // the side of the face s is on
    return touching_sphere<S>(c, ma, S(side * along - c.other_radius), Vec3Of<S>(-side * axis),
                              Vec3Of<S>(-side * axis_rate));
  }
  const Vec3Of<S> w_rate = d_rate - along_rate * axis - along * axis_rate;
  const Vec3Of<S> u = w / in_plane;
  const Vec3Of<S> rim = mb.p + c.radius * u;
  const Vec3Of<S> rim_rate = centre_rate + c.radius * unit_rate<S>(u, w_rate, in_plane);
  const Vec3Of<S> e = rim - ma.p;
  const S length = e.norm();
  if (!(value_of(length) > kDegenerate)) {
    degenerate(c.name, "the sphere's centre is on the disk's rim: no line to push along");
  }
  const Vec3Of<S> n = e / length;
  return touching_sphere<S>(c, ma, S(length - c.other_radius), n,
                            unit_rate<S>(n, Vec3Of<S>(rim_rate - s_rate), length));
}

// A contact of the body of mb with the ground plane: the gap n · (contact − plane point) at the
// point of its sphere or disk rim nearest the plane (surface_offset; the point itself for radius
// 0), its force along n there; with friction, no slip along the plane's tangents t₁, t₂ there
// (dynamics/contact_geometry.hpp). On body a's plane the same, with the plane's normal and
// tangents turning with a. With another body's sphere (ma its centre): a sphere's gap
// |c_b − c_a| − r_a − r_b along the line of centres, a disk's to its point nearest the sphere's
// centre (disk_against_sphere), its force along the normal n at the contact point c_a + r_a n
// (on b; −n on a), the friction's tangents turning with n.
//
// The contact point's rate is that of the geometric point (the centre's velocity plus the
// offset's rate), what the wrench's rate needs; the gap's rate is still n · (the material
// points' relative velocity) there, since the point is where the gap is least.
template <class S, class Row>
void contact_rows(const model::Contact& c, const FrameMotionOf<S>& ma, const FrameMotionOf<S>& mb,
                  Row&& row) {
  if (c.on_ground()) {
    const Vec3Of<S> n = c.plane_normal.cast<S>();
    const SurfaceOffsetOf<S> offset = surface_offset<S>(c, mb, n, Vec3Of<S>::Zero());
    const Vec3Of<S> contact = mb.p + offset.offset;
    const Vec3Of<S> contact_rate = mb.point_velocity(mb.p) + offset.rate;
    row(n.dot(contact - c.plane_point.cast<S>()), true, force_at<S>(contact, n),
        force_rate<S>(contact, contact_rate, n, Vec3Of<S>::Zero()));
    if (!c.has_friction()) return;
    // Friction: the material point at the contact has no velocity along the plane's tangents
    // (velocity rows, as a rolling sphere's).
    const Vec3 t1 = plane_tangent(c.plane_normal);
    for (const Vec3& t : {t1, Vec3(c.plane_normal.cross(t1))}) {
      row(S(0.0), false, force_at<S>(contact, t.cast<S>()),
          force_rate<S>(contact, contact_rate, t.cast<S>(), Vec3Of<S>::Zero()));
    }
    return;
  }
  if (c.other_plane) {
    // Body a's plane (ma its frame: z the normal, x and y the tangents), turning with a at ω_a.
    const Vec3Of<S> n = ma.R.col(2);
    const Vec3Of<S> n_rate = ma.w().cross(n);
    const SurfaceOffsetOf<S> offset = surface_offset<S>(c, mb, n, n_rate);
    const Vec3Of<S> contact = mb.p + offset.offset;
    const Vec3Of<S> contact_rate = mb.point_velocity(mb.p) + offset.rate;
    const S gap = c.shape == model::ContactShape::sphere ? S(n.dot(mb.p - ma.p) - c.radius)
                                                         : S(n.dot(contact - ma.p));
    row(gap, true, force_at<S>(contact, n), force_rate<S>(contact, contact_rate, n, n_rate));
    if (!c.has_friction()) return;
    for (int k = 0; k < 2; ++k) {
      const Vec3Of<S> t = ma.R.col(k);
      row(S(0.0), false, force_at<S>(contact, t),
          force_rate<S>(contact, contact_rate, t, Vec3Of<S>(ma.w().cross(t))));
    }
    return;
  }
  const SphereTouchOf<S> touch = c.shape == model::ContactShape::disk
                                     ? disk_against_sphere<S>(c, ma, mb)
                                     : sphere_against_sphere<S>(c, ma, mb);
  row(touch.gap, true, force_at<S>(touch.contact, touch.normal),
      force_rate<S>(touch.contact, touch.contact_rate, touch.normal, touch.normal_rate));
  if (!c.has_friction()) return;
  // Friction: no slip of the material points at the contact along the tangents across the
  // normal, which turn with it.
  const TangentsOf<S> t = turning_tangents<S>(touch.normal, touch.normal_rate);
  row(S(0.0), false, force_at<S>(touch.contact, t.t1),
      force_rate<S>(touch.contact, touch.contact_rate, t.t1, t.t1_rate));
  row(S(0.0), false, force_at<S>(touch.contact, t.t2),
      force_rate<S>(touch.contact, touch.contact_rate, t.t2, t.t2_rate));
}

// Knife edge on the body of mb: no velocity of the point across the blade, s = n × x_B / |…|.
template <class S, class Row>
void knife_edge_rows(const model::KnifeEdge& c, const FrameMotionOf<S>& mb, Row&& row) {
  const Vec3Of<S> n = c.plane_normal.cast<S>();
  const Vec3Of<S> blade = mb.R.col(0);
  const Vec3Of<S> across = n.cross(blade);
  const S s = across.norm();
  if (!(value_of(s) > kDegenerate)) {
    degenerate(c.name, "the blade stands along the plane's normal: no direction across it");
  }
  const Vec3Of<S> side = across / s;
  const Vec3Of<S> side_rate = unit_rate<S>(side, n.cross(mb.w().cross(blade)), s);
  row(S(0.0), false, force_at<S>(mb.p, side),
      force_rate<S>(mb.p, mb.point_velocity(mb.p), side, side_rate));
}

// The two frames a constraint joins (every kind but a coupler): body a (0, the ground, for a
// rolling contact or a knife edge) with X_aF, and body b with X_bF.
struct JoinedFrames {
  int a = 0;
  Transform X_aF;
  int b = 0;
  Transform X_bF;
};

inline JoinedFrames joined_frames(const model::Constraint& constraint) {
  if (const auto* c = std::get_if<model::LoopClosure>(&constraint))
    return {c->a.body_index, c->a.X_BF, c->b.body_index, c->b.X_BF};
  if (const auto* c = std::get_if<model::DistanceLink>(&constraint))
    return {c->a.body_index, c->a.X_BF, c->b.body_index, c->b.X_BF};
  if (const auto* c = std::get_if<model::RollingContact>(&constraint))
    return {0, Transform::identity(), c->frame.body_index, c->frame.X_BF};
  if (const auto* c = std::get_if<model::Contact>(&constraint))
    return {c->other.body_index, c->other.X_BF, c->frame.body_index, c->frame.X_BF};
  const auto& c = std::get<model::KnifeEdge>(constraint);
  return {0, Transform::identity(), c.frame.body_index, c.frame.X_BF};
}

// The rows of a constraint (every kind but a coupler) from the motions of its two frames.
template <class S, class Row>
void wrench_rows(const model::Constraint& constraint, const FrameMotionOf<S>& ma,
                 const FrameMotionOf<S>& mb, Row&& row) {
  if (const auto* loop = std::get_if<model::LoopClosure>(&constraint)) {
    loop_rows(*loop, ma, mb, row);
  } else if (const auto* link = std::get_if<model::DistanceLink>(&constraint)) {
    distance_rows(*link, ma, mb, row);
  } else if (const auto* contact = std::get_if<model::RollingContact>(&constraint)) {
    rolling_rows(*contact, mb, row);
  } else if (const auto* touch = std::get_if<model::Contact>(&constraint)) {
    contact_rows(*touch, ma, mb, row);
  } else {
    knife_edge_rows(std::get<model::KnifeEdge>(constraint), mb, row);
  }
}

}  // namespace momenta::dynamics::detail
