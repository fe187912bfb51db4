#include "momenta/model/rotor.hpp"

#include <vector>

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta::model {
namespace {

// Adds to `rotor` (in C) every body welded below body b, whose pose in C is X_CB.
void add_welded(const Model& model, int b, const Transform& X_CB, inertia::MassProperties& rotor) {
  for (const Joint& j : model.joints()) {
    if (j.parent_index != b || j.type != JointType::fixed) continue;
    // A fixed joint holds J' on J: X_BK = X_PJ · X_KJ⁻¹.
    const Transform X_CK = X_CB * (j.X_PJ * j.X_CJ.inverse());
    rotor += model.body(j.child_index).mass_properties.transformed(X_CK.R, X_CK.p);
    add_welded(model, j.child_index, X_CK, rotor);
  }
}

}  // namespace

RotorOnJoint rotor_on_joint(const Model& model, int body) {
  if (body == 0) throw InvalidArgument("the world does not turn: name the rotor's body");
  const Body& b = model.body(body);
  const Joint& j = model.joint(b.joint_index);
  if (j.type != JointType::revolute) {
    throw InvalidArgument(fmt::format(
        "body '{}' turns on joint '{}', a {} joint: a rotor to balance turns on a revolute joint",
        b.name, j.name, joint_type_name(j.type)));
  }
  RotorOnJoint r{b.name, j.name, b.mass_properties, {}};
  add_welded(model, body, Transform(), r.rotor);
  // The axis is fixed in J and in J' alike (a rotation about it leaves it): in C, R_CJ' axis.
  r.axis.p_BoAo_B = j.X_CJ.p;
  r.axis.direction_B = j.X_CJ.R * j.axis;
  return r;
}

RotorOnJoint find_rotor(const Model& model, const std::string& body_name) {
  if (!body_name.empty()) return rotor_on_joint(model, model.body_index(body_name));
  std::vector<int> candidates;
  for (int b = 1; b < model.num_bodies(); ++b) {
    if (model.joint(model.body(b).joint_index).type == JointType::revolute) candidates.push_back(b);
  }
  if (candidates.size() == 1) return rotor_on_joint(model, candidates.front());
  std::vector<std::string> names;
  for (int b : candidates) names.push_back(model.body(b).name);
  throw InvalidArgument(OptionMessage{
      candidates.empty()
          ? std::string("no body of the model turns on a revolute joint: a rotor to balance does")
          : fmt::format("{} bodies turn on revolute joints ({}): name the rotor with ‹body›",
                        candidates.size(), fmt::join(names, ", "))});
}

}  // namespace momenta::model
