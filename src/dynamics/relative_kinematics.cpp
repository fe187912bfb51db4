#include "momenta/dynamics/relative_kinematics.hpp"

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/point_kinematics.hpp"

namespace momenta::dynamics {

RelativeKinematics relative_kinematics(const Model& model, const Data& data, int body,
                                       const Vec3& p_BoP_B, int frame) {
  if (frame < 0 || frame >= model.num_bodies()) {
    throw InvalidArgument(fmt::format("relative_kinematics: frame body index {} outside [0, {})",
                                      frame, model.num_bodies()));
  }
  const PointKinematics P = point_kinematics(model, data, body, p_BoP_B);
  const PointKinematics Fo = point_kinematics(model, data, frame, Vec3::Zero());
  const Mat3& R_WF = data.X_WB[frame].R;
  const Mat3 R_FW = R_WF.transpose();
  const Vec6& V = data.V_WB_B[frame];
  const Vec6& A = data.A_WB_B[frame];

  RelativeKinematics k;
  k.w_WF_F = V.head<3>();
  // The spatial acceleration's angular part is the classical α (no ω × term for rotation).
  k.alpha_WF_F = A.head<3>();
  k.p_FoP_F = R_FW * (P.p_WoP_W - Fo.p_WoP_W);
  k.v_WFo_F = R_FW * Fo.v_WP_W;
  k.a_WFo_F = R_FW * Fo.a_WP_W;
  k.v_WP_F = R_FW * P.v_WP_W;
  k.a_WP_F = R_FW * P.a_WP_W;

  const Vec3& w = k.w_WF_F;
  const Vec3& r = k.p_FoP_F;
  k.v_rotation = w.cross(r);
  k.v_relative = k.v_WP_F - k.v_WFo_F - k.v_rotation;
  k.a_euler = k.alpha_WF_F.cross(r);
  k.a_centripetal = w.cross(w.cross(r));
  k.a_coriolis = 2.0 * w.cross(k.v_relative);
  k.a_relative = k.a_WP_F - k.a_WFo_F - k.a_euler - k.a_centripetal - k.a_coriolis;
  return k;
}

}  // namespace momenta::dynamics
