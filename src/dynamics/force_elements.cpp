#include "momenta/dynamics/force_elements.hpp"

#include <type_traits>
#include <variant>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/math/rotation.hpp"

#include "force_element_geometry.hpp"

namespace momenta::dynamics {

namespace {

using detail::kMinDirectionLength;
using detail::load_scale;
using detail::relative_rotation_vector;
using model::AppliedForce;
using model::AppliedTorque;
using model::BodyPoint;
using model::FixedTendon;
using model::JointFriction;
using model::LinearSpringDamper;
using model::LoadFrame;
using model::TorsionalSpringDamper;

// Position and velocity of a body point in the world (the world's own points are at rest).
Vec3 point_position_W(const Data& data, const BodyPoint& P) {
  return data.X_WB[P.body_index].apply(P.p_BoP_B);
}
Vec3 point_velocity_W(const Data& data, const BodyPoint& P) {
  const Vec6& V = data.V_WB_B[P.body_index];
  return data.X_WB[P.body_index].R * (V.tail<3>() + V.head<3>().cross(P.p_BoP_B));
}

// Adds the world-frame force f_W acting at P to f_ext of P's body (nothing on the world).
void add_force_at(const Data& data, const BodyPoint& P, const Vec3& f_W, std::span<Vec6> f_ext) {
  if (P.body_index == 0) return;
  const Vec3 f_B = data.X_WB[P.body_index].R.transpose() * f_W;
  f_ext[P.body_index].head<3>() += P.p_BoP_B.cross(f_B);
  f_ext[P.body_index].tail<3>() += f_B;
}

// Linear spring: the force on b's point, in W (the opposite force acts on a's point).
Vec3 linear_spring_force_on_b(const Data& data, const LinearSpringDamper& e) {
  const Vec3 d = point_position_W(data, e.b) - point_position_W(data, e.a);
  const double length = d.norm();
  // T u = k (ℓ − ℓ0) u + c ℓ̇ u with u = d / ℓ. The k ℓ u = k d part needs no direction, so a
  // zero-free-length spring is exact (and smooth) even with coincident points. The rest needs u:
  // when the points coincide it is undefined, and so are the compressed spring's push k ℓ0 u and
  // the damper's c ℓ̇ u (ℓ̇ = u · Δv): they are left out there rather than made NaN.
  Vec3 f_b_W = -e.stiffness * d;
  if (length > kMinDirectionLength) {
    const Vec3 u = d / length;
    const double length_rate = u.dot(point_velocity_W(data, e.b) - point_velocity_W(data, e.a));
    f_b_W += (e.stiffness * e.free_length - e.damping * length_rate) * u;
  }
  return f_b_W;
}

void check_sizes(const Model& model, std::span<const double> signal_values,
                 std::span<const Vec6> f_ext) {
  if (static_cast<int>(f_ext.size()) != model.num_bodies()) {
    throw InvalidArgument(
        fmt::format("force_element_forces: f_ext has {} wrenches; the model has "
                    "{} bodies (world included)",
                    f_ext.size(), model.num_bodies()));
  }
  if (signal_values.size() < model.signals().size()) {
    throw InvalidArgument(fmt::format("force_element_forces: {} signal values for {} signals",
                                      signal_values.size(), model.signals().size()));
  }
}

// Adds one element's generalized forces to tau and its wrenches to f_ext.
void add_element(const Model& model, const Data& data, const model::ForceElement& element,
                 std::span<const double> signal_values, VecRef q, VecRef v, VecX& tau,
                 std::span<Vec6> f_ext) {
  std::visit(
      [&](const auto& e) {
        using T = std::decay_t<decltype(e)>;
        if constexpr (std::is_same_v<T, JointFriction>) {
          const model::Joint& j = model.joint(e.joint_index);
          tau.segment(j.v_index, j.nv()) -= e.viscous * v.segment(j.v_index, j.nv());
        } else if constexpr (std::is_same_v<T, FixedTendon>) {
          // τᵢ = −cᵢ T, T = k (L − L_rest) + c L̇.
          const double tension = e.stiffness * (tendon_length(model, e, q) - e.rest_length) +
                                 e.damping * tendon_rate(model, e, v);
          for (const model::TendonTerm& term : e.terms) {
            tau[model.joint(term.joint_index).v_index] -= term.coefficient * tension;
          }
        } else if constexpr (std::is_same_v<T, TorsionalSpringDamper>) {
          if (e.joint_index >= 0) {
            // On a 1-dof joint: τ = −k (q − rest) − c q̇.
            const model::Joint& j = model.joint(e.joint_index);
            tau[j.v_index] -=
                e.stiffness * (q[j.q_index] - e.rest_angle) + e.damping * v[j.v_index];
          } else {
            // Between two bodies: n_B = −k θ − c (ω_B − ω_A) on b, in B; −n_B on a.
            const int a = e.body_a_index, b = e.body_b_index;
            const Mat3 R_BA = data.X_WB[b].R.transpose() * data.X_WB[a].R;
            const Vec3 w_AB_B = data.V_WB_B[b].head<3>() - R_BA * data.V_WB_B[a].head<3>();
            const Vec3 n_B = -e.stiffness * relative_rotation_vector(data, e) - e.damping * w_AB_B;
            if (b != 0) f_ext[b].head<3>() += n_B;
            if (a != 0) f_ext[a].head<3>() -= R_BA.transpose() * n_B;
          }
        } else if constexpr (std::is_same_v<T, LinearSpringDamper>) {
          const Vec3 f_b_W = linear_spring_force_on_b(data, e);
          add_force_at(data, e.b, f_b_W, f_ext);
          add_force_at(data, e.a, -f_b_W, f_ext);
        } else if constexpr (std::is_same_v<T, AppliedForce>) {
          // A follower load turns with the body; a world load keeps its direction.
          const int b = e.at.body_index;
          const Vec3 f = load_scale(e.signal_index, signal_values) * e.vector;
          const Vec3 f_B = e.frame == LoadFrame::body ? f : Vec3(data.X_WB[b].R.transpose() * f);
          f_ext[b].head<3>() += e.at.p_BoP_B.cross(f_B);
          f_ext[b].tail<3>() += f_B;
        } else if constexpr (std::is_same_v<T, AppliedTorque>) {
          const int b = e.body_index;
          const Vec3 n = load_scale(e.signal_index, signal_values) * e.vector;
          f_ext[b].head<3>() +=
              e.frame == LoadFrame::body ? n : Vec3(data.X_WB[b].R.transpose() * n);
        }
      },
      element);
}

}  // namespace

void force_element_forces(const Model& model, const Data& data,
                          std::span<const double> signal_values, VecRef q, VecRef v, VecX& tau,
                          std::span<Vec6> f_ext) {
  check_sizes(model, signal_values, f_ext);
  tau.setZero(model.nv());
  for (Vec6& f : f_ext) f.setZero();

  // Each joint's own viscous damping, −c v on every velocity coordinate.
  for (const model::Joint& j : model.joints()) {
    if (j.damping != 0.0)
      tau.segment(j.v_index, j.nv()) -= j.damping * v.segment(j.v_index, j.nv());
  }

  for (const model::ForceElement& element : model.force_elements())
    add_element(model, data, element, signal_values, q, v, tau, f_ext);
}

void force_element_forces_of(const Model& model, const Data& data, int element,
                             std::span<const double> signal_values, VecRef q, VecRef v, VecX& tau,
                             std::span<Vec6> f_ext) {
  check_sizes(model, signal_values, f_ext);
  if (element < 0 || element >= static_cast<int>(model.force_elements().size())) {
    throw InvalidArgument(fmt::format("force_element_forces_of: element {} outside [0, {})",
                                      element, model.force_elements().size()));
  }
  tau.setZero(model.nv());
  for (Vec6& f : f_ext) f.setZero();
  add_element(model, data, model.force_elements()[element], signal_values, q, v, tau, f_ext);
}

double tendon_length(const Model& model, const FixedTendon& tendon, VecRef q) {
  double length = tendon.offset;
  for (const model::TendonTerm& term : tendon.terms) {
    length += term.coefficient * q[model.joint(term.joint_index).q_index];
  }
  return length;
}

double tendon_rate(const Model& model, const FixedTendon& tendon, VecRef v) {
  double rate = 0.0;
  for (const model::TendonTerm& term : tendon.terms) {
    rate += term.coefficient * v[model.joint(term.joint_index).v_index];
  }
  return rate;
}

double spring_potential_energy(const Model& model, const Data& data, VecRef q) {
  double V = 0.0;
  for (const model::ForceElement& element : model.force_elements()) {
    if (const auto* s = std::get_if<LinearSpringDamper>(&element)) {
      const double stretch =
          (point_position_W(data, s->b) - point_position_W(data, s->a)).norm() - s->free_length;
      V += 0.5 * s->stiffness * stretch * stretch;
    } else if (const auto* tendon = std::get_if<FixedTendon>(&element)) {
      const double stretch = tendon_length(model, *tendon, q) - tendon->rest_length;
      V += 0.5 * tendon->stiffness * stretch * stretch;
    } else if (const auto* t = std::get_if<TorsionalSpringDamper>(&element)) {
      if (t->joint_index >= 0) {
        const double angle = q[model.joint(t->joint_index).q_index] - t->rest_angle;
        V += 0.5 * t->stiffness * angle * angle;
      } else {
        V += 0.5 * t->stiffness * relative_rotation_vector(data, *t).squaredNorm();
      }
    }
  }
  return V;
}

double force_element_power(const Model& model, const Data& data, VecRef v, VecRef tau,
                           std::span<const Vec6> f_ext) {
  // τ·v on the joints; each wrench (in B about Bo) on its body's spatial velocity (in B).
  double power = tau.dot(v);
  for (int b = 1; b < model.num_bodies(); ++b) power += f_ext[b].dot(data.V_WB_B[b]);
  return power;
}

bool force_elements_conservative(const Model& model) {
  for (const model::Joint& j : model.joints()) {
    if (j.damping != 0.0) return false;
  }
  for (const model::ForceElement& element : model.force_elements()) {
    const bool conservative = std::visit(
        [](const auto& e) {
          using T = std::decay_t<decltype(e)>;
          if constexpr (std::is_same_v<T, LinearSpringDamper> ||
                        std::is_same_v<T, TorsionalSpringDamper> ||
                        std::is_same_v<T, FixedTendon>) {
            return e.damping == 0.0;
          } else if constexpr (std::is_same_v<T, JointFriction>) {
            return e.viscous == 0.0;
          } else {
            return false;  // applied forces and torques put work in from outside
          }
        },
        element);
    if (!conservative) return false;
  }
  return true;
}

}  // namespace momenta::dynamics
