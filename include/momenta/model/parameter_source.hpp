#pragma once
// Where a parameter of the equations of motion comes from in a model: a body's mass, a component
// of its centre of mass or of its inertia tensor, a joint frame's offset, a spring's stiffness …
// The symbolic layer (symbolic/equations.hpp) takes every parameter's value from its source, and
// keeps the source beside the symbol; the report's in-page engine, which has no symbolic layer,
// evaluates the same sources on the model a reader has changed, so the page's equations get the
// page's numbers (docs/report.md, "The live report").
//
// Units are SI, as the model holds them. A component of a position is the model's own number, in
// the frame the model gives it (a joint's offset X_PJ.p in the parent body, a constraint frame's
// origin X_BF.p in its body); `magnitude` takes its size, where the equations write a length
// along one axis and keep its sign themselves (`sign`, the sign the derivation saw).

#include <cstdint>
#include <optional>
#include <string_view>

#include "momenta/model/model.hpp"

namespace momenta::model {

struct ParameterSource {
  enum class Kind : std::uint8_t {
    gravity,                  ///< |g|, m/s²
    gravity_direction,        ///< row: axis; g/|g|
    body_mass,                ///< index: body; kg
    body_center_of_mass,      ///< index: body, row: axis; p_BoBcm_B, m (round-off of it 0)
    body_inertia,             ///< index: body, row, column; about the centre of mass in B, kg·m²
    body_shape_size,          ///< index: body, row: the size's place in its shape's sizes; m
    joint_parent_offset,      ///< index: joint, row: axis; X_PJ.p, m
    joint_child_offset,       ///< index: joint, row: axis; X_CJ.p, m
    joint_damping,            ///< index: joint
    joint_armature,           ///< index: joint
    element_stiffness,        ///< index: force element (spring, torsional spring, tendon)
    element_damping,          ///< index: force element (spring, torsional spring, tendon)
    element_rest,             ///< index: force element: a torsional spring's or tendon's rest
    element_free_length,      ///< index: force element: a linear spring's free length, m
    element_stretch_at_zero,  ///< index: linear spring along a line, row: its axis in W; m
    element_viscous,          ///< index: force element: joint friction's viscous coefficient
    element_offset,           ///< index: force element: a tendon's length at q = 0
    element_coefficient,      ///< index: force element, row: the tendon's term
    element_load,             ///< index: force element: |vector| of an applied force or torque
    element_load_direction,   ///< index: force element, row: axis; vector/|vector|
    constraint_frame_origin,  ///< index: constraint, row: axis, column: frame (0 a or the one, 1 b)
    constraint_length,        ///< index: constraint: a distance link's length, m
    constraint_radius,        ///< index: constraint: a rolling contact's radius, m
    constraint_ratio,         ///< index: constraint: a joint coupler's ratio
    constraint_offset,        ///< index: constraint: a joint coupler's offset
  };
  Kind kind = Kind::gravity;
  int index = 0;
  int row = 0;
  int column = 0;
  bool magnitude = false;  ///< the size of the value (a length along one axis)
  /// The value's sign where the derivation met it (`magnitude` sources and a spring's stretch
  /// at zero): the equations' form holds the sign, so another sign is another form.
  int sign = 1;
};

/// The source's value in `model`: the number the equations of motion give the parameter (the
/// size where `magnitude`). The stretch of a spring along a line at q = 0 is its length there —
/// every coordinate, prescribed ones too, at 0 — less its free length, 0 within 1e-12 of the
/// larger. Throws InvalidArgument for a source the model does not have (an index out of range,
/// a kind its element is not).
double parameter_value(const Model& model, const ParameterSource& source);

/// The signed value the source's form depends on: the value before `magnitude` takes its size.
double parameter_signed_value(const Model& model, const ParameterSource& source);

/// The kinds' names, as the report's data writes them ("body_mass", …), and back.
std::string_view parameter_source_kind_name(ParameterSource::Kind kind);
std::optional<ParameterSource::Kind> parameter_source_kind(std::string_view name);

}  // namespace momenta::model
