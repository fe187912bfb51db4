#include "momenta/model/output_spec.hpp"

namespace momenta::model {

OutputTargetKind output_target_kind(OutputQuantity quantity) {
  switch (quantity) {
    case OutputQuantity::joint_position:
    case OutputQuantity::joint_velocity:
    case OutputQuantity::joint_effort:
    case OutputQuantity::reaction_force:
    case OutputQuantity::reaction_moment:
      return OutputTargetKind::joint;
    case OutputQuantity::body_position:
    case OutputQuantity::body_velocity:
    case OutputQuantity::body_acceleration:
    case OutputQuantity::body_angular_velocity:
    case OutputQuantity::body_angular_acceleration:
    case OutputQuantity::body_euler_angles:
    case OutputQuantity::body_euler_rates:
    case OutputQuantity::transport_velocity:
    case OutputQuantity::transport_acceleration:
    case OutputQuantity::coriolis_acceleration:
    case OutputQuantity::centripetal_acceleration:
    case OutputQuantity::euler_acceleration:
      return OutputTargetKind::body;
    case OutputQuantity::signal:
      return OutputTargetKind::signal;
    case OutputQuantity::spring_length:
    case OutputQuantity::spring_tension:
      return OutputTargetKind::force_element;
    case OutputQuantity::constraint_force:
      return OutputTargetKind::constraint;
  }
  return OutputTargetKind::joint;
}

bool is_rotating_frame_term(OutputQuantity quantity) {
  return quantity == OutputQuantity::transport_velocity ||
         quantity == OutputQuantity::transport_acceleration ||
         quantity == OutputQuantity::coriolis_acceleration ||
         quantity == OutputQuantity::centripetal_acceleration ||
         quantity == OutputQuantity::euler_acceleration;
}

std::string_view output_target_kind_name(OutputTargetKind kind) {
  switch (kind) {
    case OutputTargetKind::joint:
      return "joint";
    case OutputTargetKind::body:
      return "body";
    case OutputTargetKind::signal:
      return "signal";
    case OutputTargetKind::force_element:
      return "force element";
    case OutputTargetKind::constraint:
      return "constraint";
  }
  return "";
}

std::string_view output_quantity_name(OutputQuantity quantity) {
  switch (quantity) {
    case OutputQuantity::joint_position:
    case OutputQuantity::body_position:
      return "position";
    case OutputQuantity::joint_velocity:
    case OutputQuantity::body_velocity:
      return "velocity";
    case OutputQuantity::joint_effort:
      return "effort";
    case OutputQuantity::body_acceleration:
      return "acceleration";
    case OutputQuantity::body_angular_velocity:
      return "angular_velocity";
    case OutputQuantity::body_angular_acceleration:
      return "angular_acceleration";
    case OutputQuantity::body_euler_angles:
      return "euler_angles";
    case OutputQuantity::body_euler_rates:
      return "euler_rates";
    case OutputQuantity::transport_velocity:
      return "transport_velocity";
    case OutputQuantity::transport_acceleration:
      return "transport_acceleration";
    case OutputQuantity::coriolis_acceleration:
      return "coriolis_acceleration";
    case OutputQuantity::centripetal_acceleration:
      return "centripetal_acceleration";
    case OutputQuantity::euler_acceleration:
      return "euler_acceleration";
    case OutputQuantity::reaction_force:
      return "reaction_force";
    case OutputQuantity::reaction_moment:
      return "reaction_moment";
    case OutputQuantity::signal:
      return "signal";
    case OutputQuantity::constraint_force:
      return "force";
    case OutputQuantity::spring_length:
      return "spring_length";
    case OutputQuantity::spring_tension:
      return "spring_tension";
  }
  return "";
}

bool is_euler_quantity(OutputQuantity quantity) {
  return quantity == OutputQuantity::body_euler_angles ||
         quantity == OutputQuantity::body_euler_rates;
}

}  // namespace momenta::model
