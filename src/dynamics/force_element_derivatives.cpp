#include "momenta/dynamics/force_element_derivatives.hpp"

#include <type_traits>
#include <variant>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/math/lie_group.hpp"

#include "force_element_geometry.hpp"
#include "joint_stages.hpp"

namespace momenta::dynamics {
namespace {

using model::AppliedForce;
using model::AppliedTorque;
using model::BodyPoint;
using model::LinearSpringDamper;
using model::LoadFrame;
using model::TorsionalSpringDamper;

// The first-order motion of a body along one direction of differentiation, in W: its pose moves
// by the twist dX (about Wo) and its spatial velocity by dV.
struct BodyMotion {
  Vec6 dX = Vec6::Zero();
  Vec6 dV = Vec6::Zero();
};

// A force at a point of a body, or a moment on it, in W, and its rate along the direction.
struct Load {
  int body = 0;
  bool is_force = true;
  Vec3 p_W = Vec3::Zero();  // the point, for a force
  Vec3 value = Vec3::Zero();
  Vec3 rate = Vec3::Zero();
};

// A body point's position and velocity in W, and their rates under the body's motion.
struct PointMotion {
  Vec3 p, p_rate, v, v_rate;
};
PointMotion point_motion(const Data& data, const BodyPoint& P, const BodyMotion& m) {
  const int b = P.body_index;
  const Vec3 p = data.X_WB[b].apply(P.p_BoP_B);
  const Vec6& V = data.dV_W[b];
  const Vec3 dp = m.dX.head<3>().cross(p) + m.dX.tail<3>();
  return {p, dp, V.tail<3>() + V.head<3>().cross(p),
          m.dV.tail<3>() + m.dV.head<3>().cross(p) + V.head<3>().cross(dp)};
}

// The loads of one body-level element and their rates under `motion` (a callable giving each
// body's BodyMotion); returns how many (0 to 2) it wrote. Values as force_element_forces has them.
template <class Motion>
int element_loads(const Data& data, const model::ForceElement& element,
                  std::span<const double> signal_values, Motion&& motion, Load out[2]) {
  return std::visit(
      [&](const auto& e) -> int {
        using T = std::decay_t<decltype(e)>;
        if constexpr (std::is_same_v<T, LinearSpringDamper>) {
          // f_b = −k d + (k ℓ0 − c ℓ̇) u, d = p_b − p_a, u = d / ℓ, ℓ̇ = u · ḋ; −f_b on a.
          const PointMotion a = point_motion(data, e.a, motion(e.a.body_index));
          const PointMotion b = point_motion(data, e.b, motion(e.b.body_index));
          const Vec3 d = b.p - a.p, d_rate = b.p_rate - a.p_rate;
          Vec3 f = -e.stiffness * d, f_rate = -e.stiffness * d_rate;
          const double length = d.norm();
          if (length > detail::kMinDirectionLength) {
            const Vec3 u = d / length;
            const Vec3 dd = b.v - a.v, dd_rate = b.v_rate - a.v_rate;
            const Vec3 u_rate = (d_rate - u * u.dot(d_rate)) / length;
            const double length_rate = u.dot(dd);
            const double length_rate_rate = u_rate.dot(dd) + u.dot(dd_rate);
            const double tension = e.stiffness * e.free_length - e.damping * length_rate;
            f += tension * u;
            f_rate += tension * u_rate - e.damping * length_rate_rate * u;
          }
          out[0] = {e.b.body_index, true, b.p, f, f_rate};
          out[1] = {e.a.body_index, true, a.p, -f, -f_rate};
          return 2;
        } else if constexpr (std::is_same_v<T, TorsionalSpringDamper>) {
          if (e.joint_index >= 0) return 0;  // on its joint's coordinate
          // n_b = R_B (−k θ) − c (ω_B − ω_A) in W; θ moves by J_r⁻¹(θ) R_Bᵀ (dθ_B − dθ_A).
          const int a = e.body_a_index, b = e.body_b_index;
          const BodyMotion ma = motion(a), mb = motion(b);
          const Mat3& R_B = data.X_WB[b].R;
          const Vec3 theta = detail::relative_rotation_vector(data, e);
          const Vec3 theta_rate = so3_right_jacobian_inverse(theta) * R_B.transpose() *
                                  (mb.dX.head<3>() - ma.dX.head<3>());
          const Vec3 spring_W = R_B * (-e.stiffness * theta);
          const Vec3 n = spring_W - e.damping * (data.dV_W[b].head<3>() - data.dV_W[a].head<3>());
          const Vec3 n_rate = mb.dX.head<3>().cross(spring_W) - e.stiffness * (R_B * theta_rate) -
                              e.damping * (mb.dV.head<3>() - ma.dV.head<3>());
          out[0] = {b, false, Vec3::Zero(), n, n_rate};
          out[1] = {a, false, Vec3::Zero(), -n, -n_rate};
          return 2;
        } else if constexpr (std::is_same_v<T, AppliedForce>) {
          // A world load keeps its direction; a follower load turns with its body.
          const int b = e.at.body_index;
          const double scale = detail::load_scale(e.signal_index, signal_values);
          const Vec3 f = e.frame == LoadFrame::body ? Vec3(data.X_WB[b].R * (scale * e.vector))
                                                    : Vec3(scale * e.vector);
          const BodyMotion m = motion(b);
          const Vec3 p = data.X_WB[b].apply(e.at.p_BoP_B);
          out[0] = {b, true, p, f,
                    e.frame == LoadFrame::body ? Vec3(m.dX.head<3>().cross(f)) : Vec3::Zero()};
          return 1;
        } else if constexpr (std::is_same_v<T, AppliedTorque>) {
          const int b = e.body_index;
          const double scale = detail::load_scale(e.signal_index, signal_values);
          const Vec3 n = e.frame == LoadFrame::body ? Vec3(data.X_WB[b].R * (scale * e.vector))
                                                    : Vec3(scale * e.vector);
          const BodyMotion m = motion(b);
          out[0] = {b, false, Vec3::Zero(), n,
                    e.frame == LoadFrame::body ? Vec3(m.dX.head<3>().cross(n)) : Vec3::Zero()};
          return 1;
        } else {
          return 0;  // joint friction, joint springs, tendons: on their joints' coordinates
        }
      },
      element);
}

// The joint-level elements: joint damping and friction −c v, joint springs −k (q − rest) − c v,
// fixed tendons −cᵢ (k (L − L_rest) + d L̇).
void add_joint_elements(const Model& model, Data& data) {
  for (const model::Joint& j : model.joints()) {
    for (int k = 0; k < j.nv(); ++k) data.dQ_dv(j.v_index + k, j.v_index + k) -= j.damping;
  }
  for (const model::ForceElement& element : model.force_elements()) {
    if (const auto* f = std::get_if<model::JointFriction>(&element)) {
      const model::Joint& j = model.joint(f->joint_index);
      for (int k = 0; k < j.nv(); ++k) data.dQ_dv(j.v_index + k, j.v_index + k) -= f->viscous;
    } else if (const auto* s = std::get_if<TorsionalSpringDamper>(&element);
               s && s->joint_index >= 0) {
      const int i = model.joint(s->joint_index).v_index;
      data.dQ_dq(i, i) -= s->stiffness;
      data.dQ_dv(i, i) -= s->damping;
    } else if (const auto* t = std::get_if<model::FixedTendon>(&element)) {
      // τᵢ = −cᵢ (k (L − L_rest) + d L̇): ∂τᵢ/∂qⱼ = −k cᵢ cⱼ, ∂τᵢ/∂vⱼ = −d cᵢ cⱼ (1-dof joints:
      // each coordinate's q and v share its index).
      for (const model::TendonTerm& a : t->terms) {
        const int i = model.joint(a.joint_index).v_index;
        for (const model::TendonTerm& b : t->terms) {
          const int j = model.joint(b.joint_index).v_index;
          data.dQ_dq(i, j) -= t->stiffness * a.coefficient * b.coefficient;
          data.dQ_dv(i, j) -= t->damping * a.coefficient * b.coefficient;
        }
      }
    }
  }
}

}  // namespace

void force_element_derivatives(const Model& model, Data& data,
                               std::span<const double> signal_values) {
  if (signal_values.size() < model.signals().size()) {
    throw InvalidArgument(fmt::format("force_element_derivatives: {} signal values for {} signals",
                                      signal_values.size(), model.signals().size()));
  }
  data.dQ_dq.setZero();
  data.dQ_dv.setZero();
  add_joint_elements(model, data);

  // Each body's load in W (about Wo), summed over its subtree: the rigid part below.
  const auto& elements = model.force_elements();
  for (Vec6& w : data.dLoad_W) w.setZero();
  Load loads[2];
  const auto at_rest = [](int) { return BodyMotion{}; };
  for (const model::ForceElement& element : elements) {
    const int count = element_loads(data, element, signal_values, at_rest, loads);
    for (int l = 0; l < count; ++l) {
      const Load& load = loads[l];
      if (load.is_force) {
        data.dLoad_W[load.body] += spatial(load.p_W.cross(load.value), load.value);
      } else {
        data.dLoad_W[load.body].head<3>() += load.value;
      }
    }
  }
  const auto& joints = model.joint_constants();
  for (int j = static_cast<int>(joints.size()) - 1; j >= 0; --j) {
    if (joints[j].parent != 0) data.dLoad_W[joints[j].parent] += data.dLoad_W[joints[j].child];
  }

  // Along each direction: the loads' rates beyond those of loads fixed in their bodies, on
  // every coordinate supporting the loaded body.
  const int nv = model.nv();
  for (int kind = 0; kind < 2; ++kind) {
    const bool configuration = kind == 0;
    MatX& dQ = configuration ? data.dQ_dq : data.dQ_dv;
    for (int k = 0; k < nv; ++k) {
      const Vec6 S_k = data.dS_W.col(k);
      const auto motion = [&](int b) {
        const detail::BodyMotionRate rate = detail::body_motion_rate(
            data, b, k, configuration ? detail::Along::configuration : detail::Along::velocity);
        return BodyMotion{rate.twist, rate.V};
      };
      for (const model::ForceElement& element : elements) {
        const int count = element_loads(data, element, signal_values, motion, loads);
        for (int l = 0; l < count; ++l) {
          const Load& load = loads[l];
          if (load.body == 0) continue;
          Vec3 rate = load.rate;
          if (configuration && detail::supports(data, load.body, k)) {
            rate -= S_k.head<3>().cross(load.value);  // what a load fixed in the body does
          }
          const Vec6 w =
              load.is_force ? spatial(load.p_W.cross(rate), rate) : spatial(rate, Vec3::Zero());
          for (const auto& [start, length] : data.support_ranges[load.body - 1]) {
            for (int m = start; m < start + length; ++m) dQ(m, k) += data.dS_W.col(m).dot(w);
          }
        }
      }
    }
  }

  // The rigid part: coordinate k moves the loads below its joint while a column m above it
  // stays, so Q_m changes by S_mᵀ (S_k ×* w) with w the loads of k's subtree.
  for (int j = 0; j < static_cast<int>(joints.size()); ++j) {
    const auto& c = joints[j];
    const Vec6& w = data.dLoad_W[c.child];
    for (int k = 0; k < c.nv; ++k) {
      const int vk = c.v_index + k;
      const int stage_k = detail::joint_stage(c.type, k);
      const Vec6 moved = cross_force(data.dS_W.col(vk), w);
      for (const auto& [start, length] : data.support_ranges[j]) {
        for (int m = start; m < start + length; ++m) {
          if (detail::support_stage(c, m) >= stage_k) continue;  // m is not above k
          data.dQ_dq(m, vk) += data.dS_W.col(m).dot(moved);
        }
      }
    }
  }
}

}  // namespace momenta::dynamics
