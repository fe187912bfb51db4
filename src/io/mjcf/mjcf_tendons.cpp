// MJCF's <tendon> section: each <fixed> tendon as momenta's FixedTendon force element (its spring
// and damper, and an output column of its length), and <equality><tendon> as a joint coupler
// where it relates two joints.

#include <array>

#include <fmt/format.h>

#include "mjcf/mjcf_reader.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "xml/xml_support.hpp"

namespace momenta::io::detail {

void MjcfReader::read_tendons(const XMLElement* section) {
  for (const XMLElement* xml = section->FirstChildElement(); xml != nullptr;
       xml = xml->NextSiblingElement()) {
    const std::string_view kind = xml->Name();
    const char* given = xml->Attribute("name");
    const std::string name = given != nullptr ? given : fmt::format("tendon{}", tendon_count);
    ++tendon_count;
    if (kind != "fixed") {
      note(xml,
           fmt::format("<{}> tendon '{}': not modelled (momenta reads fixed tendons)", kind, name));
      continue;
    }
    check_attributes(xml,
                     {"name", "class", "group", "limited", "range", "solreflimit", "solimplimit",
                      "solreffriction", "solimpfriction", "frictionloss", "margin", "springlength",
                      "stiffness", "damping", "width", "rgba", "user"});
    const MjcfElement e{xml, "tendon", class_of(xml, "main")};
    // MuJoCo's length Σ cᵢ qposᵢ = Σ cᵢ (qᵢ + refᵢ): an offset Σ cᵢ refᵢ in momenta's q. Its
    // spring relaxes at springlength where that is given and not negative, else at the length
    // with every joint at its springref (MuJoCo 2.2's rule).
    model::FixedTendon tendon;
    tendon.name = name;
    double length_at_springref = 0.0;
    for (const XMLElement* term = xml->FirstChildElement(); term != nullptr;
         term = term->NextSiblingElement()) {
      if (std::string_view(term->Name()) != "joint") {
        fail(term, fmt::format("a fixed tendon holds <joint> elements, not <{}>", term->Name()));
      }
      check_attributes(term, {"joint", "coef"});
      const MjcfJoint& joint = joint_named(term, "joint", term->Attribute("joint"));
      const MjcfElement t{term, "", ""};
      const double coefficient = number(t, "coef", std::nullopt);  // MuJoCo requires it
      tendon.terms.push_back({joint.joint.name, coefficient, -1});
      tendon.offset += coefficient * joint.ref;
      length_at_springref += coefficient * joint.springref;
    }
    if (tendon.terms.empty()) fail(xml, fmt::format("fixed tendon '{}' has no <joint>", name));
    tendon.stiffness = number(e, "stiffness", 0.0);
    tendon.damping = number(e, "damping", 0.0);
    const double springlength = number(e, "springlength", -1.0);
    tendon.rest_length = springlength >= 0.0 ? springlength : length_at_springref;
    if (attribute(e, "range") &&
        keyword(e, "limited", {"true", "false", "auto"}, "auto") != "false") {
      note(xml, fmt::format("the range of tendon '{}' is not enforced", name));
    }
    if (number(e, "frictionloss", 0.0) != 0.0) {
      note(xml, fmt::format("the dry friction of tendon '{}' is not modelled", name));
    }
    builder.add_force_element(tendon);
    items.push_back(located_at(ModelItemRef::Kind::force_element, name, xml->GetLineNum(),
                               xml_column(text, xml)));
    model::OutputSpec length;
    length.name = name + "_length";
    length.quantity = model::OutputQuantity::spring_length;
    length.target = name;
    outputs.push_back(length);
    tendons.emplace(name, tendon);
  }
}

std::optional<model::JointCoupler> MjcfReader::tendon_coupler(const XMLElement* xml,
                                                              const MjcfElement& e,
                                                              const std::string& name) {
  check_attributes(
      xml, {"name", "class", "active", "solref", "solimp", "tendon1", "tendon2", "polycoef"});
  const auto tendon_named = [&](const char* attribute) -> const model::FixedTendon& {
    const char* tendon = xml->Attribute(attribute);
    if (tendon == nullptr) fail(xml, fmt::format("<tendon> needs the attribute '{}'", attribute));
    const auto it = tendons.find(tendon);
    if (it == tendons.end()) {
      std::vector<std::string_view> names;
      for (const auto& [known, read] : tendons) names.push_back(known);
      fail(xml, fmt::format("unknown fixed tendon '{}'{}", tendon, did_you_mean(tendon, names)),
           attribute);
    }
    return it->second;
  };
  // L1 − L1(qpos0) = a0 + a1 (L2 − L2(qpos0)), qpos0 being momenta's q = 0: Σ₁ cq = a0 + a1 Σ₂ cq.
  const model::FixedTendon& one = tendon_named("tendon1");
  model::JointCoupler coupler;
  coupler.name = name;
  if (xml->Attribute("tendon2") == nullptr && one.terms.size() == 2) {
    // c_a q_a + c_b q_b = a0 (MuJoCo reads a0 alone here).
    const double a0 = numbers(e, "polycoef", 5, 5, std::vector<double>{0, 1, 0, 0, 0})[0];
    const model::TendonTerm &a = one.terms[0], &b = one.terms[1];
    coupler.joint_a = a.joint;
    coupler.joint_b = b.joint;
    coupler.ratio = -b.coefficient / a.coefficient;
    coupler.offset = a0 / a.coefficient;
    return coupler;
  }
  const model::FixedTendon* two =
      xml->Attribute("tendon2") != nullptr ? &tendon_named("tendon2") : nullptr;
  if (two != nullptr && one.terms.size() == 1 && two->terms.size() == 1 &&
      one.terms[0].joint != two->terms[0].joint) {
    const std::array<double, 2> c = linear_polycoef(e, name);
    // c_a q_a = a0 + a1 c_b q_b.
    const model::TendonTerm &a = one.terms[0], &b = two->terms[0];
    coupler.joint_a = a.joint;
    coupler.joint_b = b.joint;
    coupler.ratio = c[1] * b.coefficient / a.coefficient;
    coupler.offset = c[0] / a.coefficient;
    return coupler;
  }
  note(xml, fmt::format("tendon equality '{}': not modelled (momenta couples two joints: one "
                        "tendon of two joints, or two tendons of one joint each)",
                        name));
  return std::nullopt;
}

}  // namespace momenta::io::detail
