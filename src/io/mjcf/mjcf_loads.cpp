// MJCF's <equality> constraints (connect, weld, joint; tendon in mjcf_tendons.cpp) as momenta's
// loop closures and couplers, and its <actuator> motors on hinges, slides and fixed tendons as
// torque or force pairs driven by input signals.

#include <algorithm>
#include <array>

#include <fmt/format.h>

#include "mjcf/mjcf_reader.hpp"
#include "momenta/common/error.hpp"
#include "xml/xml_support.hpp"

namespace momenta::io::detail {
namespace {

// The pose of `body` in the world at the drawn configuration (the world's is the identity).
Transform world_pose(const MjcfReader& reader, const char* body) {
  if (body == nullptr || std::string_view(body) == model::kWorldBodyName) {
    return Transform::identity();
  }
  return reader.bodies.at(body).X_WB;
}

}  // namespace

void MjcfReader::read_equality(const XMLElement* section) {
  for (const XMLElement* xml = section->FirstChildElement(); xml != nullptr;
       xml = xml->NextSiblingElement()) {
    const std::string_view kind = xml->Name();
    const char* given = xml->Attribute("name");
    const std::string name =
        given != nullptr ? given : fmt::format("{}{}", kind, xml->GetLineNum());
    if (kind != "connect" && kind != "weld" && kind != "joint" && kind != "tendon") {
      note(xml, fmt::format("<{}> equality '{}': not modelled", kind, name));
      continue;
    }
    const MjcfElement e{xml, "equality", class_of(xml, "main")};
    if (kind == "joint") {
      check_attributes(
          xml, {"name", "class", "active", "solref", "solimp", "joint1", "joint2", "polycoef"});
    } else if (kind != "tendon") {
      check_attributes(xml, {"name", "class", "active", "solref", "solimp", "body1", "body2",
                             "anchor", "relpose", "torquescale"});
    }
    if (!flag(e, "active", true)) {
      note(xml, fmt::format("equality '{}' is inactive: left out", name));
      continue;
    }
    model::Constraint constraint;
    if (kind == "tendon") {
      const std::optional<model::JointCoupler> coupler = tendon_coupler(xml, e, name);
      if (!coupler) continue;
      constraint = *coupler;
    } else if (kind == "joint") {
      // joint1 = a0 + a1 joint2 (+ higher powers), each counted from its reference, which is
      // where momenta's coordinates start: a coupler of ratio a1 and offset a0.
      const MjcfJoint& a = joint_named(xml, "joint1", xml->Attribute("joint1"));
      if (xml->Attribute("joint2") == nullptr) {
        fail(xml, fmt::format("equality '{}' holds joint '{}' still: make it a fixed joint", name,
                              a.joint.name));
      }
      const MjcfJoint& b = joint_named(xml, "joint2", xml->Attribute("joint2"));
      const std::array<double, 2> c = linear_polycoef(e, name);
      model::JointCoupler coupler;
      coupler.name = name;
      coupler.joint_a = a.joint.name;
      coupler.joint_b = b.joint.name;
      coupler.ratio = c[1];
      coupler.offset = c[0];
      constraint = coupler;
    } else {
      // Body b is body1, its partner body2 (the world when not given); the frames coincide where
      // the file draws them, or at the weld's relpose.
      const char* body1 = xml->Attribute("body1");
      const char* body2 = xml->Attribute("body2");
      const std::string b_name = body_named(xml, "body1", body1).name;
      const std::string a_name =
          body2 != nullptr ? body_named(xml, "body2", body2).name : model::kWorldBodyName;
      const Transform X_W1 = world_pose(*this, body1), X_W2 = world_pose(*this, body2);
      model::LoopClosure loop;
      loop.name = name;
      loop.a.body = a_name;
      loop.b.body = b_name;
      if (kind == "connect") {
        // The anchor, a point of body1, and the point of body2 there.
        loop.type = model::LoopType::point;
        const Vec3 anchor = vector3(e, "anchor", Vec3::Zero());
        loop.b.X_BF = Transform::translation(anchor);
        loop.a.X_BF = Transform::translation(X_W2.inverse().apply(X_W1.apply(anchor)));
      } else {
        loop.type = model::LoopType::weld;
        const std::vector<double> relpose =
            numbers(e, "relpose", 7, 7, std::vector<double>{0, 1, 0, 0, 0, 0, 0});
        Transform X_12 = X_W1.inverse() * X_W2;  // body2 in body1 where the file draws them
        const Quat quat(relpose[3], relpose[4], relpose[5], relpose[6]);
        if (quat.norm() > 0.0) {
          X_12 = Transform(quat.normalized().toRotationMatrix(),
                           Vec3(relpose[0], relpose[1], relpose[2]));
        }
        if (xml->Attribute("anchor") != nullptr || xml->Attribute("torquescale") != nullptr) {
          note(xml, fmt::format("weld '{}': anchor and torquescale are not used (the bodies' "
                                "frames are welded)",
                                name));
        }
        // Body1's frame (b) coincides with the frame of body2 (a) that sits at X_21.
        loop.a.X_BF = X_12.inverse();
      }
      constraint = loop;
    }
    builder.add_constraint(constraint);
    items.push_back(
        located_at(ModelItemRef::Kind::constraint, name, xml->GetLineNum(), xml_column(text, xml)));
  }
}

std::array<double, 2> MjcfReader::linear_polycoef(const MjcfElement& e,
                                                  const std::string& name) const {
  const std::vector<double> c = numbers(e, "polycoef", 5, 5, std::vector<double>{0, 1, 0, 0, 0});
  if (c[2] != 0.0 || c[3] != 0.0 || c[4] != 0.0) {
    fail(e.xml,
         fmt::format("equality '{}': momenta couples joints linearly (polycoef's powers above 1 "
                     "are {}, {}, {})",
                     name, c[2], c[3], c[4]),
         "polycoef");
  }
  return {c[0], c[1]};
}

void MjcfReader::read_actuators(const XMLElement* section) {
  int number_of = 0;
  for (const XMLElement* xml = section->FirstChildElement(); xml != nullptr;
       xml = xml->NextSiblingElement(), ++number_of) {
    const std::string_view kind = xml->Name();
    const char* given = xml->Attribute("name");
    const std::string name = given != nullptr ? given : fmt::format("actuator{}", number_of);
    const MjcfElement e{xml, "actuator", class_of(xml, "main")};
    const bool plain_general =
        kind == "general" &&
        keyword(e, "dyntype", {"none", "integrator", "filter", "filterexact", "muscle", "user"},
                "none") == "none" &&
        keyword(e, "gaintype", {"fixed", "affine", "muscle", "user"}, "fixed") == "fixed" &&
        keyword(e, "biastype", {"none", "affine", "muscle", "user"}, "none") == "none";
    if (kind != "motor" && !plain_general) {
      note(xml, fmt::format("<{}> actuator '{}': not modelled (momenta reads motors and plain "
                            "general actuators)",
                            kind, name));
      continue;
    }
    // What it drives: a joint (scale 1), or each joint of a fixed tendon (scale its coefficient:
    // MuJoCo's moment arm of a fixed tendon).
    std::vector<std::pair<const model::Joint*, double>> targets;
    if (const char* joint_name = xml->Attribute("joint")) {
      targets.emplace_back(&joint_named(xml, "joint", joint_name).joint, 1.0);
    } else if (const char* tendon_name = xml->Attribute("tendon");
               tendon_name != nullptr && tendons.count(tendon_name) != 0) {
      for (const model::TendonTerm& term : tendons.at(tendon_name).terms) {
        targets.emplace_back(&joints.at(term.joint).joint, term.coefficient);
      }
    } else {
      note(xml, fmt::format("actuator '{}' drives a spatial tendon or a site: not modelled", name));
      continue;
    }
    const auto unmodelled = std::find_if(targets.begin(), targets.end(), [](const auto& target) {
      return target.first->type != model::JointType::revolute &&
             target.first->type != model::JointType::prismatic;
    });
    if (unmodelled != targets.end()) {
      const model::Joint& joint = *unmodelled->first;
      note(xml, fmt::format("actuator '{}' drives {} joint '{}': not modelled (hinges and slides "
                            "only)",
                            name, model::joint_type_name(joint.type), joint.name));
      continue;
    }
    // force = gain · gear · u, u an input named after the actuator (0 until a run gives it).
    const double gear = numbers(e, "gear", 1, 6, std::vector<double>{1.0}).front();
    const double gain =
        kind == "general" ? numbers(e, "gainprm", 1, 10, std::vector<double>{1.0}).front() : 1.0;
    if (attribute(e, "ctrlrange") || attribute(e, "forcerange")) {
      note(xml,
           fmt::format("the control and force ranges of actuator '{}' are not enforced", name));
    }
    builder.add_signal(model::Signal(name, model::ConstantSignal{0.0}));
    items.push_back(
        located_at(ModelItemRef::Kind::signal, name, xml->GetLineNum(), xml_column(text, xml)));
    for (const auto& [joint, scale] : targets) {
      const std::string drive = targets.size() == 1 && xml->Attribute("joint") != nullptr
                                    ? name
                                    : fmt::format("{}_{}", name, joint->name);
      add_joint_drive(*joint, drive, name, gear * gain * scale);
      items.push_back(located_at(ModelItemRef::Kind::force_element, drive, xml->GetLineNum(),
                                 xml_column(text, xml)));
    }
  }
}

void MjcfReader::add_joint_drive(const model::Joint& joint, const std::string& name,
                                 const std::string& signal, double scale) {
  // The pair: on the joint's child along the axis (in J' = the child's axes), the reaction on
  // its parent (along the axis in J, fixed in the parent) — equal and opposite, so no other
  // joint feels it; a slide's forces act at the joint's two origins, on the axis.
  const Vec3 axis_C = joint.X_CJ.R * joint.axis * scale;
  const Vec3 axis_P = joint.X_PJ.R * joint.axis * scale;
  const bool on_parent = joint.parent != model::kWorldBodyName;
  const auto add_with_reaction = [&](auto drive, auto onto_parent) {
    builder.add_force_element(drive);
    if (!on_parent) return;
    drive.name = name + "_reaction";
    onto_parent(drive);
    builder.add_force_element(drive);
  };
  if (joint.type == model::JointType::revolute) {
    model::AppliedTorque drive;
    drive.name = name;
    drive.body = joint.child;
    drive.frame = model::LoadFrame::body;
    drive.vector = axis_C;
    drive.signal = signal;
    add_with_reaction(drive, [&](model::AppliedTorque& reaction) {
      reaction.body = joint.parent;
      reaction.vector = -axis_P;
    });
  } else {
    model::AppliedForce drive;
    drive.name = name;
    drive.at = model::BodyPoint{joint.child, joint.X_CJ.p, -1};
    drive.frame = model::LoadFrame::body;
    drive.vector = axis_C;
    drive.signal = signal;
    add_with_reaction(drive, [&](model::AppliedForce& reaction) {
      reaction.at = model::BodyPoint{joint.parent, joint.X_PJ.p, -1};
      reaction.vector = -axis_P;
    });
  }
}

}  // namespace momenta::io::detail
