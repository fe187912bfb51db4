#include "momenta/system/rigid_body_integrator.hpp"

#include <string>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/model/model.hpp"
#include "momenta/system/multibody_system.hpp"

namespace momenta::system {

namespace {

constexpr std::string_view kNames[] = {"splitting", "splitting4", "lie_group", "exact"};

// What each method applies to, for error messages.
std::string_view applies_to(RigidBodyMethod method) {
  if (method == RigidBodyMethod::kExact) {
    return "a single body on a free joint to the world (gravity allowed) or on a spherical joint "
           "to the world without gravity torque, with no force elements or joint damping: "
           "torque-free rotation";
  }
  return "a single body on a free joint to the world, or on a spherical joint to the world (a "
         "heavy top), with no force elements or joint damping (gravity allowed)";
}

// A one-line account of the model's joints and force elements.
std::string describe(const model::Model& model) {
  std::string out =
      fmt::format("{} moving bod{}", model.num_bodies() - 1, model.num_bodies() == 2 ? "y" : "ies");
  if (model.num_joints() > 0) out += "; joints:";
  for (int j = 0; j < model.num_joints(); ++j) {
    const model::Joint& joint = model.joint(j);
    if (j == 4) {
      out += fmt::format(" ... ({} in all)", model.num_joints());
      break;
    }
    out += fmt::format("{} '{}' ({}, {} → {}{})", j == 0 ? "" : ",", joint.name,
                       model::joint_type_name(joint.type), joint.parent, joint.child,
                       joint.damping > 0 ? fmt::format(", damping {}", joint.damping) : "");
  }
  if (!model.force_elements().empty()) {
    out += "; force elements:";
    for (size_t k = 0; k < model.force_elements().size(); ++k) {
      out += fmt::format("{} '{}'", k == 0 ? "" : ",",
                         model::force_element_name(model.force_elements()[k]));
    }
  }
  return out;
}

// Hamilton quaternion [w, x, y, z] at q[0..3] as a rotation matrix (normalized first).
Mat3 rotation_of(const VecX& q, int i) {
  Quat quaternion(q[i], q[i + 1], q[i + 2], q[i + 3]);
  quaternion.normalize();
  return quaternion.toRotationMatrix();
}

// Writes the quaternion of R at q[i..i+3], on the same hemisphere as the one already there so
// that the coordinates stay continuous from step to step.
void write_quaternion(const Mat3& R, VecX& q, int i) {
  // From an orthonormal R (to a few ε) the quaternion is unit to a few ε without normalizing
  // (which would cost a square root and a division per step; readers normalize anyway).
  const Quat quaternion(R);
  const double dot = quaternion.w() * q[i] + quaternion.x() * q[i + 1] + quaternion.y() * q[i + 2] +
                     quaternion.z() * q[i + 3];
  const double sign = dot < 0 ? -1.0 : 1.0;
  q[i] = sign * quaternion.w();
  q[i + 1] = sign * quaternion.x();
  q[i + 2] = sign * quaternion.y();
  q[i + 3] = sign * quaternion.z();
}

}  // namespace

RigidBodyIntegrator::RigidBodyIntegrator(RigidBodyMethod method) : method_(method) {}

std::string_view RigidBodyIntegrator::name() const { return kNames[static_cast<int>(method_)]; }

int RigidBodyIntegrator::order() const {
  switch (method_) {
    case RigidBodyMethod::kSplitting4:
      return 4;
    case RigidBodyMethod::kExact:
      return model::kExactOrder;
    default:
      return 2;
  }
}

void RigidBodyIntegrator::initialize(integrate::SecondOrderSystem& system,
                                     const integrate::State& state) {
  const auto* multibody = dynamic_cast<const MultibodySystem*>(&system);
  if (multibody == nullptr) {
    throw InvalidArgument(fmt::format(
        "integrator '{}' applies to {}; it needs a multibody model (system::MultibodySystem), "
        "not another kind of system. Use rk4 or dopri5 instead",
        name(), applies_to(method_)));
  }
  const model::Model& model = multibody->model();
  case_ = Case::kNone;  // until every check has passed
  const auto reject = [&](std::string_view why) {
    throw InvalidArgument(
        fmt::format("integrator '{}' applies to {}; {}. This model has {}. Use "
                    "rk4 or dopri5 instead",
                    name(), applies_to(method_), why, describe(model)));
  };

  // One body on a free or spherical joint to the world, nothing else acting on it.
  if (model.num_bodies() != 2) reject("the model does not have exactly one moving body");
  const model::Joint& joint = model.joint(0);
  if (joint.parent_index != 0) reject("the body's joint does not connect it to the world");
  Case kind = Case::kNone;
  if (joint.type == model::JointType::free) {
    kind = Case::kFreeBody;
  } else if (joint.type == model::JointType::spherical) {
    kind = Case::kHeavyTop;
  } else {
    reject(fmt::format("its joint '{}' is {}, not free or spherical", joint.name,
                       model::joint_type_name(joint.type)));
  }
  if (!model.force_elements().empty()) reject("the model has force elements");
  if (joint.damping != 0) reject(fmt::format("joint '{}' is damped", joint.name));
  model::check_state_sizes(model, state.q, state.v, fmt::format("integrator '{}'", name()));

  // The joint's placement and the centre of mass from the child-side joint origin J'o.
  const model::Body& body = model.body(1);
  const inertia::MassProperties& mass_properties = body.mass_properties;
  R_WJ_ = joint.X_PJ.R;
  p_WoJo_W_ = joint.X_PJ.p;
  R_CJ_ = joint.X_CJ.R;
  p_BoJo_B_ = joint.X_CJ.p;
  r_B_ = mass_properties.center_of_mass() - p_BoJo_B_;
  rotated_joint_ = R_WJ_ != Mat3::Identity() || R_CJ_ != Mat3::Identity();
  g_W_ = model.gravity();

  // The rotation: about the centre of mass (free body, torque-free) or about the pivot J'o.
  const bool free_body = kind == Case::kFreeBody;
  const Mat3 I =
      free_body ? mass_properties.inertia_about_com() : mass_properties.inertia_about(p_BoJo_B_);
  const bool torque_free = free_body || g_W_ == Vec3::Zero() || r_B_ == Vec3::Zero();
  if (method_ == RigidBodyMethod::kExact && !torque_free) {
    reject(fmt::format(
        "it follows torque-free rotation only, and gravity ({}, {}, {}) m/s² acts {} m from the "
        "pivot of spherical joint '{}' (use splitting, splitting4 or lie_group for a heavy top)",
        g_W_.x(), g_W_.y(), g_W_.z(), r_B_.norm(), joint.name));
  }
  gravity_.reset();
  splitting_.reset();
  lie_group_.reset();
  exact_.reset();
  if (!torque_free) gravity_.emplace(mass_properties.mass(), r_B_, g_W_);
  const rigid_body::AttitudePotential* potential = gravity_ ? &*gravity_ : nullptr;
  try {
    switch (method_) {
      case RigidBodyMethod::kSplitting:
        splitting_.emplace(I, rigid_body::Composition::kStrang,
                           rigid_body::FreeFlow::kAxisRotations, potential);
        break;
      case RigidBodyMethod::kSplitting4:
        splitting_.emplace(I, rigid_body::Composition::kSuzuki4,
                           rigid_body::FreeFlow::kAxisRotations, potential);
        break;
      case RigidBodyMethod::kLieGroup:
        lie_group_.emplace(I, potential);
        break;
      case RigidBodyMethod::kExact:
        exact_.emplace(I);
        break;
    }
  } catch (const InvalidInertia& e) {
    // A body the model accepts (a point mass) may still have no rotational inertia.
    throw InvalidInertia(fmt::format("integrator '{}', body '{}' (inertia about the {}): {}",
                                     name(), body.name, free_body ? "centre of mass" : "pivot",
                                     e.what()));
  }
  case_ = kind;
  last_q_.resize(model.nq());
  last_v_.resize(model.nv());
  has_state_ = false;
  statistics_ = {};
}

void RigidBodyIntegrator::read_state(const VecX& q, const VecX& v) {
  // Attitude and angular velocity from the joint's quaternion and w_JJ'_J'.
  const int iq = case_ == Case::kFreeBody ? 3 : 0;
  const Mat3 R_JJp = rotation_of(q, iq);
  R_WB_ = R_WJ_ * R_JJp * R_CJ_.transpose();
  w_WB_B_ = R_CJ_ * v.head<3>();
  // The centre of mass and its velocity (the free joint's translation is in J).
  if (case_ == Case::kFreeBody) {
    const Vec3 r_W = R_WB_ * r_B_;
    p0_WBcm_W_ = p_WoJo_W_ + R_WJ_ * q.head<3>() + r_W;
    v0_WBcm_W_ = R_WJ_ * v.segment<3>(3) + R_WB_ * w_WB_B_.cross(r_B_);
  }
  elapsed_ = 0;
}

void RigidBodyIntegrator::write_state(VecX& q, VecX& v) const {
  const int iq = case_ == Case::kFreeBody ? 3 : 0;
  // R_JJ' = R_WJᵀ R_WB R_CJ and w_JJ'_J' = R_CJᵀ w_WB_B (two products saved without rotations).
  if (rotated_joint_) {
    write_quaternion(R_WJ_.transpose() * R_WB_ * R_CJ_, q, iq);
    v.head<3>() = R_CJ_.transpose() * w_WB_B_;
  } else {
    write_quaternion(R_WB_, q, iq);
    v.head<3>() = w_WB_B_;
  }
  if (case_ == Case::kFreeBody) {
    // The centre of mass on its parabola from the anchor: only the time since the anchor needs
    // the long double sum (it is the one quantity that accumulates); each position is then
    // rounded once, without feeding back.
    const double tau = static_cast<double>(elapsed_);
    const Vec3 p_WBcm_W = p0_WBcm_W_ + (v0_WBcm_W_ + 0.5 * tau * g_W_) * tau;
    const Vec3 v_WBcm_W = v0_WBcm_W_ + tau * g_W_;
    q.head<3>() = R_WJ_.transpose() * (p_WBcm_W - p_WoJo_W_ - R_WB_ * r_B_);
    v.segment<3>(3) = R_WJ_.transpose() * (v_WBcm_W - R_WB_ * w_WB_B_.cross(r_B_));
  }
}

double RigidBodyIntegrator::step(integrate::SecondOrderSystem& system, integrate::State& state,
                                 double h) {
  (void)system;
  if (case_ == Case::kNone) {
    throw InvalidArgument(
        fmt::format("integrator '{}': step() called before initialize()", name()));
  }
  // Continue from the kept state while the caller hands back what the last step returned.
  if (!has_state_ || state.q != last_q_ || state.v != last_v_) read_state(state.q, state.v);
  // The rotation by the rigid-body integrator; the centre of mass on its parabola.
  if (splitting_) splitting_->step(R_WB_, w_WB_B_, h);
  if (lie_group_) lie_group_->step(R_WB_, w_WB_B_, h);
  if (exact_) exact_->step(R_WB_, w_WB_B_, h);
  elapsed_ += h;
  write_state(state.q, state.v);
  last_q_ = state.q;
  last_v_ = state.v;
  has_state_ = true;
  state.t += h;
  ++statistics_.steps;
  return h;
}

const std::vector<std::string_view>& rigid_body_integrator_names() {
  static const std::vector<std::string_view> names(std::begin(kNames), std::end(kNames));
  return names;
}

std::unique_ptr<integrate::Integrator> make_rigid_body_integrator(std::string_view name) {
  for (int i = 0; i < 4; ++i) {
    if (name == kNames[i]) {
      return std::make_unique<RigidBodyIntegrator>(static_cast<RigidBodyMethod>(i));
    }
  }
  return nullptr;
}

}  // namespace momenta::system
