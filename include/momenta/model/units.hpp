#pragma once
// The SI unit of every quantity a model's state and outputs carry, as text for a person: column
// headers, plot axes, tooltips. "rad", "m", "m/s", "N·m", ...; "1" for a dimensionless number (a
// quaternion component); "" where the model does not say (a signal that drives nothing).

#include <string>
#include <vector>

#include "momenta/model/model.hpp"
#include "momenta/model/output_spec.hpp"

namespace momenta::model {

/// Configuration coordinate i (an index into q): "rad", "m", or "1" for a quaternion component.
std::string q_unit(const Model& model, int i);
/// Velocity coordinate i (an index into v): "rad/s" or "m/s".
std::string v_unit(const Model& model, int i);
/// The generalized force along velocity coordinate i: "N·m" on an angle, "N" on a length.
std::string effort_unit(const Model& model, int i);
/// A joint's viscous damping (its effort per its speed): "N·m·s/rad" on a joint whose speeds
/// are all angular, "N·s/m" on one whose speeds are all lengths; "" where they are mixed (a
/// planar joint) or there are none.
std::string joint_damping_unit(const Model& model, const Joint& joint);
/// A joint's armature (its effort per its acceleration): "kg·m²" on a joint whose speeds are all
/// angular, "kg" on one whose speeds are all lengths; "" where they are mixed or there are none.
std::string joint_armature_unit(const Model& model, const Joint& joint);
/// A signal's value: the unit of the coordinate it prescribes (per s² when a controller drives
/// it: it commands the acceleration), "N" or "N·m" when it scales an
/// applied force or moment of unit direction, the measured coordinate's when a controller
/// follows it as its reference; "" when its use does not fix one.
std::string signal_unit(const Model& model, int signal_index);

/// The unit of a quotient, numerator / denominator, its factors cancelled and written as the
/// rest of this file writes units: "N·m" / "rad" → "N·m/rad", "N" / "m·s" → "N/(m·s)",
/// "rad/s²" / "rad" → "1/s²", "N·s" / "m" → "N·s/m"; "1" when everything cancels. Each factor a
/// name with an optional exponent ² or ³; a unit "" or "1" is a pure number.
std::string unit_ratio(const std::string& numerator, const std::string& denominator);

/// A fixed tendon's units: its length is in its first joint's coordinate unit (its coefficients
/// convert the others' to it), its tension is the effort conjugate to that length.
struct TendonUnits {
  std::string length;     ///< "rad" or "m"
  std::string rate;       ///< "rad/s" or "m/s"
  std::string tension;    ///< "N·m" or "N"
  std::string stiffness;  ///< "N·m/rad" or "N/m"
  std::string damping;    ///< "N·m·s/rad" or "N·s/m"
};
TendonUnits tendon_units(const Model& model, const FixedTendon& tendon);

/// One unit per value of `quantity` for a target resolved to index `target` (a joint, body,
/// signal, force element or constraint) and its `component`-th value (a coordinate, an axis, a
/// constraint force label's position).
std::string output_unit(const Model& model, OutputQuantity quantity, int target, int component);

}  // namespace momenta::model
