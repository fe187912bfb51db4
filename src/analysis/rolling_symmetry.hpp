#pragma once
// Internal to momenta::analysis: the rolling body of a model and the symmetry motions of
// rolling_steady_motion.hpp — a turn about a vertical axis with a slide across the floor (a
// twist of the world) composed with a spin about the body's own axis (a twist of the body) —
// as joint velocities: the velocity they give the body at any configuration, and the rate at
// which they turn any joint velocity. Both are exact, for the free and the spherical joint.

#include "momenta/analysis/rolling_steady_motion.hpp"
#include "momenta/math/spatial.hpp"
#include "momenta/math/types.hpp"
#include "momenta/model/model.hpp"

namespace momenta::analysis::detail {

/// The model's rolling body, its geometry in its own frame B and the floor's.
struct RollingBody {
  RollingBodyInfo info;
  const model::Joint* joint = nullptr;
  Vec3 axis_B = Vec3::UnitZ();  ///< e: the disk's axis (unit)
  Vec3 p_BoD_B = Vec3::Zero();  ///< the disk's centre D
  Vec3 p_BoG_B = Vec3::Zero();  ///< the centre of mass G
  Vec3 up_W = Vec3::UnitZ();    ///< n: the floor's normal, against gravity
  double floor_height = 0.0;    ///< n · (a point of the floor), m
  double g = 0.0;               ///< m/s²
};

/// Throws as rolling_body_info() does.
RollingBody rolling_body(const model::Model& model);

/// The body's pose X_WB at configuration q (the one joint's coordinates).
Transform body_pose(const RollingBody& body, const VecX& q);

/// The one joint's coordinates that put the body at X_WB.
VecX configuration_of_pose(const RollingBody& body, const Transform& X_WB);

/// A steady motion's rates: Ω about n, σ about e relative to the turning frame, and the velocity
/// of G (horizontal), m/s.
struct TurnRates {
  double precession = 0.0;
  double relative_spin = 0.0;
  Vec3 v_WG_W = Vec3::Zero();
};

/// The symmetry motion with `rates` through the state whose centre of mass is at p_WoG_W: the
/// world twist (Ω n, the velocity of G) about G, then σ about e through G in B.
class SymmetryMotion {
 public:
  SymmetryMotion(const RollingBody& body, const TurnRates& rates, const Vec3& p_WoG_W);

  /// The joint velocity the motion gives the body at configuration q.
  void velocity(const VecX& q, VecX& v) const;

  /// The rate at which the motion turns the joint velocity v at configuration q: d/dt of
  /// (g(t)·(q, v))'s velocity at t = 0.
  void velocity_rate(const VecX& q, const VecX& v, VecX& rate) const;

 private:
  const RollingBody& body_;
  bool pivoted_;
  // In the joint frames: the world twist in J about J's origin (a_J, b_J), the body twist in J'
  // about J''s origin (c, d).
  Vec3 a_J_, b_J_, c_Jc_, d_Jc_;
};

}  // namespace momenta::analysis::detail
