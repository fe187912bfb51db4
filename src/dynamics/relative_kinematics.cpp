#include "momenta/dynamics/relative_kinematics.hpp"

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/point_kinematics.hpp"

namespace momenta::dynamics {

namespace {
void check_frame(const Model& model, int frame, const char* what) {
  if (frame < 0 || frame >= model.num_bodies()) {
    throw InvalidArgument(
        fmt::format("{}: frame body index {} outside [0, {})", what, frame, model.num_bodies()));
  }
}
}  // namespace

RelativeRotation relative_rotation(const Model& model, const Data& data, int body, int frame) {
  check_frame(model, frame, "relative_rotation");
  check_frame(model, body, "relative_rotation");
  // A body's spatial velocity and acceleration in its own axes start with ω and its rate α.
  const Mat3& R_WF = data.X_WB[frame].R;
  const Mat3& R_WB = data.X_WB[body].R;
  const Vec3 w_WB_W = R_WB * data.V_WB_B[body].head<3>();
  const Vec3 w_WF_W = R_WF * data.V_WB_B[frame].head<3>();
  const Vec3 a_WB_W = R_WB * data.A_WB_B[body].head<3>();
  const Vec3 a_WF_W = R_WF * data.A_WB_B[frame].head<3>();
  const Mat3 R_FW = R_WF.transpose();
  return {R_FW * (w_WB_W - w_WF_W), R_FW * ((a_WB_W - a_WF_W) - w_WF_W.cross(w_WB_W - w_WF_W))};
}

RelativeKinematics relative_kinematics(const Model& model, const Data& data, int body,
                                       const Vec3& p_BoP_B, int frame) {
  check_frame(model, frame, "relative_kinematics");
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
