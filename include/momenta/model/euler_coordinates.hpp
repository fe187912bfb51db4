#pragma once
// A mechanism's ball and free joints with their rotation written as three Euler angles, as the
// notes write a top (precession φ, nutation θ, spin ψ for ZXZ) instead of a quaternion: for the
// equations of motion in symbols (`momenta equations --coordinates euler:ZXZ`). The same
// mechanism, not the same coordinates: Euler angles are singular where the middle angle locks
// the first and last axes together (θ = 0 or π for ZXZ), which the quaternion never is.

#include <string_view>

#include "momenta/model/model.hpp"

namespace momenta::model {

/// `model` with each spherical joint J → J' replaced by three revolute joints about the
/// sequence's axes (rotation_from_euler's intrinsic convention: "ZXZ" turns about J's z, then the
/// new x, then the newest z), joined by two massless frames; a free joint's translation comes
/// first, as three prismatic joints along J's x, y, z. The angles are named phi, theta, psi (with
/// a model of one such joint), else <joint>_phi, …; the translations <joint>_x, _y, _z. q0 and v0
/// are the same motion: the angles of the joint's initial rotation (euler_from_rotation) and
/// their rates from its ω in J'. Other joints, bodies, elements, signals and constraints are
/// kept. `sequence` must be an upper-case (intrinsic) Euler sequence. Throws InvalidArgument for
/// another sequence, a model without a ball or free joint, a prescribed or damped one, an initial
/// rotation at the sequence's gimbal lock (its rates undefined), or, naming the joint, an element
/// or constraint that acts on a replaced joint.
Model with_euler_coordinates(const Model& model, std::string_view sequence);

}  // namespace momenta::model
