#include "momenta/model/constraint.hpp"

namespace momenta::model {

const std::string& constraint_name(const Constraint& constraint) {
  return std::visit([](const auto& c) -> const std::string& { return c.name; }, constraint);
}

std::string_view loop_type_name(LoopType type) {
  switch (type) {
    case LoopType::weld:
      return "weld";
    case LoopType::point:
      return "point";
    case LoopType::hinge:
      return "hinge";
    case LoopType::slider:
      return "slider";
  }
  return "";
}

namespace {
struct TypeName {
  std::string_view operator()(const LoopClosure& c) const { return loop_type_name(c.type); }
  std::string_view operator()(const DistanceLink&) const { return "distance"; }
  std::string_view operator()(const RollingContact&) const { return "rolling"; }
  std::string_view operator()(const KnifeEdge&) const { return "knife_edge"; }
  std::string_view operator()(const JointCoupler&) const { return "coupler"; }
  std::string_view operator()(const Contact&) const { return "contact"; }
};

struct Rows {
  int operator()(const LoopClosure& c) const {
    switch (c.type) {
      case LoopType::weld:
        return 6;
      case LoopType::point:
        return 3;
      case LoopType::hinge:
      case LoopType::slider:
        return 5;
    }
    return 0;
  }
  int operator()(const DistanceLink&) const { return 1; }
  int operator()(const RollingContact&) const { return 3; }
  int operator()(const KnifeEdge&) const { return 1; }
  int operator()(const JointCoupler&) const { return 1; }
  int operator()(const Contact& c) const { return c.has_friction() ? 3 : 1; }
};
// A contact's rows and forces: the normal, and with friction the two tangents.
std::vector<std::string_view> contact_labels(const Contact& c) {
  if (c.has_friction()) return {"normal", "tangent_1", "tangent_2"};
  return {"normal"};
}
}  // namespace

std::string_view constraint_type_name(const Constraint& constraint) {
  return std::visit(TypeName{}, constraint);
}

int constraint_rows(const Constraint& constraint) { return std::visit(Rows{}, constraint); }

bool is_unilateral(const Constraint& constraint) {
  return std::holds_alternative<Contact>(constraint);
}

int constraint_position_rows(const Constraint& constraint) {
  if (std::holds_alternative<RollingContact>(constraint)) return 1;
  if (std::holds_alternative<Contact>(constraint)) return 1;
  if (std::holds_alternative<KnifeEdge>(constraint)) return 0;
  return constraint_rows(constraint);
}

std::vector<std::string_view> constraint_row_labels(const Constraint& constraint) {
  if (const auto* loop = std::get_if<LoopClosure>(&constraint)) {
    switch (loop->type) {
      case LoopType::weld:
        return {"x", "y", "z", "rx", "ry", "rz"};
      case LoopType::point:
        return {"x", "y", "z"};
      case LoopType::hinge:
        return {"x", "y", "z", "rx", "ry"};
      case LoopType::slider:
        return {"x", "y", "rx", "ry", "rz"};
    }
  }
  if (std::holds_alternative<DistanceLink>(constraint)) return {"length"};
  if (std::holds_alternative<RollingContact>(constraint))
    return {"normal", "longitudinal", "lateral"};
  if (std::holds_alternative<KnifeEdge>(constraint)) return {"lateral"};
  if (const auto* c = std::get_if<Contact>(&constraint)) return contact_labels(*c);
  return {"ratio"};
}

std::vector<std::string_view> constraint_force_labels(const Constraint& constraint) {
  if (std::holds_alternative<LoopClosure>(constraint)) {
    return {"reaction.Fx", "reaction.Fy", "reaction.Fz",
            "reaction.Mx", "reaction.My", "reaction.Mz"};
  }
  if (std::holds_alternative<DistanceLink>(constraint)) return {"tension"};
  if (std::holds_alternative<RollingContact>(constraint))
    return {"normal", "longitudinal", "lateral"};
  if (std::holds_alternative<KnifeEdge>(constraint)) return {"lateral"};
  if (const auto* c = std::get_if<Contact>(&constraint)) return contact_labels(*c);
  return {"effort_a", "effort_b"};
}

}  // namespace momenta::model
