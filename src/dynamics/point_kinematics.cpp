#include "momenta/dynamics/point_kinematics.hpp"

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/kinematics.hpp"

namespace momenta::dynamics {
namespace {
void check_body(const Model& model, int b, const char* what) {
  if (b < 0 || b >= model.num_bodies()) {
    throw InvalidArgument(
        fmt::format("{}: body index {} outside [0, {})", what, b, model.num_bodies()));
  }
}
}  // namespace

PointKinematics point_kinematics(const Model& model, const Data& data, int b, const Vec3& p_BoP_B) {
  check_body(model, b, "point_kinematics");
  const Transform& X = data.X_WB[b];
  const Vec6& V = data.V_WB_B[b];
  const Vec6& A = data.A_WB_B[b];
  const Vec6& Ab = data.A_bias_B[b];
  const Vec3 w = X.R * V.head<3>();
  const Vec3 r = X.R * p_BoP_B;
  PointKinematics k;
  k.p_WoP_W = X.p + r;
  k.v_WP_W = X.R * V.tail<3>() + w.cross(r);
  // Classical acceleration of Bo from the spatial one: a = linear(A) + ω × v (in B).
  const Vec3 wxv = V.head<3>().cross(V.tail<3>());
  k.a_WBo_W = X.R * (A.tail<3>() + wxv);
  k.tangential = (X.R * A.head<3>()).cross(r);
  k.centripetal = w.cross(w.cross(r));
  k.a_WP_W = k.a_WBo_W + k.tangential + k.centripetal;
  // The same with v̇ = 0 is the velocity-product part J̇ v.
  k.velocity_product = X.R * (Ab.tail<3>() + wxv) + (X.R * Ab.head<3>()).cross(r) + k.centripetal;
  k.from_vdot = k.a_WP_W - k.velocity_product;
  return k;
}

PointKinematics point_kinematics(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot,
                                 int b, const Vec3& p_BoP_B) {
  check_body(model, b, "point_kinematics");
  forward_kinematics(model, data, q, v, vdot);
  return point_kinematics(model, static_cast<const Data&>(data), b, p_BoP_B);
}

void frame_jacobian(const Model& model, const Data& data, int b, const Vec3& p_BoP_B,
                    Eigen::Ref<MatX> J) {
  check_body(model, b, "frame_jacobian");
  if (J.rows() != 6 || J.cols() != model.nv()) {
    throw InvalidArgument(
        fmt::format("frame_jacobian: J is {}×{}; expected 6×{}", J.rows(), J.cols(), model.nv()));
  }
  J.setZero();
  const Vec3 p_WoP_W = data.X_WB[b].apply(p_BoP_B);
  // Each supporting joint's subspace in W about Wo, moved to P: v_P = v_Wo + ω × p_WoP.
  for (int body = b; body > 0; body = model.parent(body)) {
    const auto& c = model.joint_constants()[body - 1];
    for (int k = 0; k < c.nv; ++k) {
      const Vec6 s = data.X_WB[body].act_motion(data.S[body - 1].col(k));
      J.col(c.v_index + k) << s.head<3>(), s.tail<3>() + s.head<3>().cross(p_WoP_W);
    }
  }
}

}  // namespace momenta::dynamics
