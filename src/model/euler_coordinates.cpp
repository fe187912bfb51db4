#include "momenta/model/euler_coordinates.hpp"

#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta/model/model_builder.hpp"

namespace momenta::model {
namespace {

Vec3 axis_of(char letter) {
  switch (letter) {
    case 'X':
      return Vec3::UnitX();
    case 'Y':
      return Vec3::UnitY();
    default:
      return Vec3::UnitZ();
  }
}

bool rotates(const Joint& j) { return j.type == JointType::spherical || j.type == JointType::free; }

// A joint from `parent` to `child` with the given type and axis, its frames where the chain's
// first and last links need them.
Joint link(std::string name, JointType type, const Vec3& axis, std::string parent,
           std::string child) {
  Joint j;
  j.name = std::move(name);
  j.type = type;
  j.axis = axis;
  j.parent = std::move(parent);
  j.child = std::move(child);
  return j;
}

// The chain that replaces one ball or free joint: (x, y, z,) φ, θ, ψ, with their q0 and v0.
void add_chain(ModelBuilder& builder, const Joint& j, std::string_view sequence,
               const std::string& prefix) {
  const bool free = j.type == JointType::free;
  const int r = free ? 3 : 0;  // where the quaternion and ω start in q and v
  const Quat rotation = j.q0.size() == j.nq()
                            ? Quat(j.q0[r], j.q0[r + 1], j.q0[r + 2], j.q0[r + 3]).normalized()
                            : Quat::Identity();
  const Mat3 R = rotation.toRotationMatrix();
  const Vec3 angles = euler_from_rotation(sequence, R);
  // ω of J' in J, given in J' (the ball joint's v), in J.
  const Vec3 w_J = j.v0.size() == j.nv() ? Vec3(R * j.v0.segment<3>(0)) : Vec3(Vec3::Zero());
  // ω (in J) = E ȧ; E is singular at gimbal lock, where the rates have no value.
  const Mat3 E = euler_rate_matrix(sequence, angles);
  const Eigen::FullPivLU<Mat3> lu(E);
  if (!lu.isInvertible() || std::abs(E.determinant()) < 1e-9) {
    throw InvalidArgument(fmt::format(
        "joint '{}': its initial rotation is at the {} sequence's gimbal lock (middle angle {} "
        "rad), where Euler angles' rates are undefined; start it off that angle, or keep the "
        "quaternion",
        j.name, sequence, angles[1]));
  }
  const Vec3 rates = lu.solve(w_J);

  std::vector<Joint> chain;
  std::vector<std::string> frames;
  const auto frame = [&](int k) { return fmt::format("{}_frame{}", j.name, k); };
  for (int k = 1; k <= (free ? 5 : 2); ++k) frames.push_back(frame(k));
  const auto from = [&](std::size_t k) { return k == 0 ? j.parent : frames[k - 1]; };
  const auto to = [&](std::size_t k) { return k == frames.size() ? j.child : frames[k]; };
  if (free) {
    const char* axes[] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
      Joint slide = link(prefix + axes[k], JointType::prismatic, Vec3::Unit(k), from(k), to(k));
      slide.q0 = VecX::Constant(1, j.q0.size() == j.nq() ? j.q0[k] : 0.0);
      slide.v0 = VecX::Constant(1, j.v0.size() == j.nv() ? j.v0[3 + k] : 0.0);
      chain.push_back(std::move(slide));
    }
  }
  const char* names[] = {"phi", "theta", "psi"};
  for (int k = 0; k < 3; ++k) {
    const std::size_t at = chain.size();
    Joint turn =
        link(prefix + names[k], JointType::revolute,
             axis_of(static_cast<char>(sequence[static_cast<std::size_t>(k)])), from(at), to(at));
    turn.q0 = VecX::Constant(1, angles[k]);
    turn.v0 = VecX::Constant(1, rates[k]);
    chain.push_back(std::move(turn));
  }
  chain.front().X_PJ = j.X_PJ;
  chain.back().X_CJ = j.X_CJ;
  for (const std::string& name : frames) {
    Body massless;
    massless.name = name;
    builder.add_body(std::move(massless));
  }
  for (Joint& link_joint : chain) builder.add_joint(std::move(link_joint));
}

}  // namespace

Model with_euler_coordinates(const Model& model, std::string_view sequence) {
  check_euler_sequence(sequence);
  if (std::islower(static_cast<unsigned char>(sequence[0]))) {
    throw InvalidArgument(fmt::format(
        "Euler sequence '{}' is extrinsic (lower case); the coordinates turn about the moving "
        "axes: give '{}{}{}'",
        sequence, static_cast<char>(std::toupper(static_cast<unsigned char>(sequence[0]))),
        static_cast<char>(std::toupper(static_cast<unsigned char>(sequence[1]))),
        static_cast<char>(std::toupper(static_cast<unsigned char>(sequence[2])))));
  }
  int replaced = 0;
  for (const Joint& j : model.joints()) {
    if (!rotates(j)) continue;
    if (j.is_prescribed() || j.damping != 0.0) {
      throw InvalidArgument(fmt::format(
          "joint '{}': a {} ball or free joint is not written in Euler angles (its {} is given "
          "per component of ω); keep the quaternion",
          j.name, j.is_prescribed() ? "prescribed" : "damped",
          j.is_prescribed() ? "motion" : "damping"));
    }
    ++replaced;
  }
  if (replaced == 0) {
    throw InvalidArgument(
        "the model has no ball (spherical) or free joint to write in Euler angles");
  }

  ModelBuilder builder;
  builder.set_gravity(model.gravity());
  for (const Body& body : model.bodies()) {
    if (body.index == 0) continue;
    Body kept;
    kept.name = body.name;
    kept.mass_properties = body.mass_properties;
    kept.inertia_scales_with_mass = body.inertia_scales_with_mass;
    kept.shape = body.shape;
    builder.add_body(std::move(kept));
  }
  for (const Joint& j : model.joints()) {
    if (!rotates(j)) {
      builder.add_joint(j);
      continue;
    }
    add_chain(builder, j, sequence, replaced == 1 ? std::string() : j.name + "_");
  }
  for (const ForceElement& element : model.force_elements()) builder.add_force_element(element);
  for (const Signal& signal : model.signals()) builder.add_signal(signal);
  for (const Constraint& constraint : model.constraints()) builder.add_constraint(constraint);
  try {
    return builder.build();
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(
        fmt::format("with the ball and free joints in Euler angles {}: {}", sequence, e.what()));
  }
}

}  // namespace momenta::model
