#pragma once
// A body of a model seen as a rotor: what turns on its revolute joint (the body and every body
// welded to it) as one rigid part, and the joint's axis, both in the body's frame — the input of
// the balancing functions (inertia/balancing.hpp) for `momenta balance MODEL`.

#include <string>

#include "momenta/inertia/balancing.hpp"
#include "momenta/inertia/mass_properties.hpp"
#include "momenta/model/model.hpp"

namespace momenta::model {

struct RotorOnJoint {
  std::string body;
  std::string joint;              ///< the revolute joint it turns on
  inertia::MassProperties rotor;  ///< the body and its welded bodies, in the body frame C
  inertia::RotorAxis axis;        ///< the joint's axis through J'o, in C
};

/// Body `body` (index ≥ 1) and everything attached below it by fixed joints, at any depth, as
/// one MassProperties in C; the axis of the revolute joint carrying it, through the origin of
/// the child-side joint frame J'. Throws InvalidArgument naming the body, its joint and the
/// joint's type when that joint is not revolute.
RotorOnJoint rotor_on_joint(const Model& model, int body);

/// The rotor of a model with a single body on a revolute joint (welded bodies aside), or the one
/// named. Throws InvalidArgument (with a did-you-mean) for an unknown name, and when no body or
/// several turn on revolute joints and none is named (listing them).
RotorOnJoint find_rotor(const Model& model, const std::string& body_name = "");

}  // namespace momenta::model
