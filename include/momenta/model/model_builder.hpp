#pragma once
// ModelBuilder: collects bodies, joints, force elements and signals in any order, then validates
// them and builds an immutable Model.

#include <string>
#include <vector>

#include "momenta/model/model.hpp"

namespace momenta::model {

class ModelBuilder {
 public:
  /// Gravitational acceleration in the world frame (m/s²); default (0, 0, −9.81).
  ModelBuilder& set_gravity(const Vec3& g_W);

  /// Adds a body (its name must not be "world"). Returns *this for chaining.
  ModelBuilder& add_body(Body body);
  /// Convenience: a body from a name and mass properties.
  ModelBuilder& add_body(std::string name, const inertia::MassProperties& mass_properties);
  /// Adds a joint connecting joint.parent to joint.child.
  ModelBuilder& add_joint(Joint joint);
  ModelBuilder& add_force_element(ForceElement element);
  ModelBuilder& add_signal(Signal signal);
  /// Adds a constraint closing a loop, a link, a rolling contact, a knife edge or a coupler.
  ModelBuilder& add_constraint(Constraint constraint);
  /// Adds a feedback controller (model/controller.hpp) driving some of the signals.
  ModelBuilder& add_controller(Controller controller);

  /// Validates and builds the Model. Throws InvalidArgument (InvalidInertia for mass properties)
  /// naming the offending body, joint, element or signal, with the values, when:
  /// - a name is empty or repeated among bodies, joints, elements or signals, or a body is called
  ///   "world";
  /// - a joint's parent or child does not exist (with a "did you mean"), its child is the world,
  ///   a body is the child of two joints, a body has no joint, or the joints form a cycle;
  /// - a body's mass properties fail check_physical() (mass 0 with zero inertia is accepted as
  ///   massless), or a massless subtree hangs on a joint with degrees of freedom (singular);
  /// - an axis is not unit length (to 1e-9) or not finite, the universal joint's axes are
  ///   parallel, a transform's rotation is not a rotation matrix, q0/v0 have the wrong size or
  ///   a quaternion in q0 is not unit (to 1e-6), damping is negative;
  /// - a prescribed joint has not one signal per coordinate or nq ≠ nv, or a signal is unknown;
  /// - a force element names an unknown body, joint or signal, or has a negative stiffness,
  ///   damping or free length, a torsional spring's joint is not 1-dof, or a loaded vector is not
  ///   finite;
  /// - a constraint names an unknown body or joint, joins a body to itself, has a non-positive
  ///   length or radius, a non-unit plane normal, a coupler's joint that is not 1-dof, or a
  ///   ratio that is zero or not finite;
  /// - a controller fails resolve_controller (model/controller.hpp), or two drive one signal.
  Model build() const;

 private:
  Vec3 gravity_ = Vec3(0, 0, -9.81);
  std::vector<Body> bodies_;
  std::vector<Joint> joints_;
  std::vector<ForceElement> force_elements_;
  std::vector<Signal> signals_;
  std::vector<Constraint> constraints_;
  std::vector<Controller> controllers_;
};

}  // namespace momenta::model
