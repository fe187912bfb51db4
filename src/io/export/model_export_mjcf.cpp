// momenta models as MJCF (io/model_export.hpp; docs/model-formats.md, "Writing models").

#include <algorithm>
#include <cmath>
#include <map>
#include <variant>

#include <fmt/format.h>

#include "export/mjcf_contact_geoms.hpp"
#include "export/model_export_common.hpp"
#include "momenta/common/error.hpp"
#include "momenta/io/model_export.hpp"
#include "xml/xml_support.hpp"

namespace momenta::io {
namespace {

using detail::number_text;
using detail::quaternion_text;
using detail::vector_text;

// One hinge or slide of the chain MuJoCo composes for a momenta joint: X_JJ'(q) as a product of
// one-axis motions M_1(q_1) · M_2(q_2) ⋯ in J.
struct Factor {
  bool hinge = true;
  Vec3 axis;     // in the frame the factors before it leave
  double drawn;  // its coordinate where the model is drawn
  std::string suffix;
};

std::vector<Factor> factors_of(const model::Joint& joint, const double* q) {
  switch (joint.type) {
    case model::JointType::revolute:
      return {{true, joint.axis, q[0], ""}};
    case model::JointType::prismatic:
      return {{false, joint.axis, q[0], ""}};
    case model::JointType::cylindrical:
      return {{true, joint.axis, q[0], "_angle"}, {false, joint.axis, q[1], "_slide"}};
    case model::JointType::universal:
      return {{true, joint.axis, q[0], "_1"}, {true, joint.axis2, q[1], "_2"}};
    case model::JointType::planar:
      return {{false, Vec3::UnitX(), q[0], "_x"},
              {false, Vec3::UnitY(), q[1], "_y"},
              {true, Vec3::UnitZ(), q[2], "_angle"}};
    case model::JointType::fixed:
    case model::JointType::spherical:
    case model::JointType::free:
      return {};  // none, or written as MJCF's own ball and free joints
  }
  return {};  // not reached: every type is named above
}

// A joint's stops as MuJoCo's range (qpos is momenta's q: ref is the drawn coordinate); a bound
// the joint does not have is written far away (xml/xml_support.hpp).
std::string range_text(const model::Joint& joint) {
  if (!joint.limits) return "";
  return fmt::format(" limited=\"true\" range=\"{} {}\"",
                     number_text(detail::bound_as_written(joint.limits->lower)),
                     number_text(detail::bound_as_written(joint.limits->upper)));
}

Transform factor_motion(const Factor& f, double value) {
  return f.hinge ? Transform::rotation(Eigen::AngleAxisd(value, f.axis).toRotationMatrix())
                 : Transform::translation(value * f.axis);
}

class MjcfWriter {
 public:
  MjcfWriter(const ModelFile& file, const VecX& q)
      : file_(file),
        model_(file.model),
        q_(q),
        contact_geoms_(detail::mjcf_contact_geoms(file.model, part_geom_names(file))) {}

  ExportedModel write() {
    check_representable();
    check_loops_closed();
    std::string body_text;
    const auto children = detail::joints_out_of(model_);
    for (int j : children[0]) body_text += body(j, children, 4);
    std::string out;
    out += fmt::format("<!-- Written by momenta export from {} (docs/model-formats.md). -->\n",
                       file_.file);
    std::vector<std::string> lost = detail::loads_not_written(model_, "MJCF");
    for (std::string& mesh : detail::meshes_not_written(file_)) lost.push_back(std::move(mesh));
    for (std::string& bounce : detail::restitution_not_written(model_, "MuJoCo's limits are soft"))
      lost.push_back(std::move(bounce));
    for (std::string& contact : contacts_not_written()) lost.push_back(std::move(contact));
    const std::string tendon_text = tendons(lost);
    for (const std::string& l : lost) out += fmt::format("<!-- Not written: {}. -->\n", l);
    out += fmt::format("<mujoco model=\"{}\">\n", file_.name);
    out += "  <compiler angle=\"radian\" autolimits=\"true\"/>\n";
    out += fmt::format("  <option gravity=\"{}\"/>\n", vector_text(model_.gravity()));
    out += "  <worldbody>\n" + ground_planes() + body_text + "  </worldbody>\n";
    out += tendon_text;
    out += equality();
    if (!qvel_.isZero(0.0)) {
      std::string velocities;
      for (Eigen::Index i = 0; i < qvel_.size(); ++i) {
        if (i > 0) velocities += ' ';
        velocities += number_text(qvel_[i]);
      }
      out +=
          "  <keyframe>\n    <key name=\"initial\" qvel=\"" + velocities + "\"/>\n  </keyframe>\n";
    }
    out += "</mujoco>\n";
    return {out, lost};
  }

 private:
  void check_representable() const {
    if (q_.size() != model_.nq() || !q_.allFinite()) {
      throw InvalidArgument(
          fmt::format("write_mjcf: the drawn configuration has {} finite "
                      "coordinates; the model has nq = {}",
                      q_.size(), model_.nq()));
    }
    for (const model::Joint& joint : model_.joints()) {
      if (joint.type != model::JointType::free) continue;
      if (joint.parent_index != 0 || !joint.X_CJ.p.isZero(0.0) ||
          joint.X_CJ.R != Mat3::Identity()) {
        throw InvalidArgument(fmt::format(
            "joint '{}': MJCF puts a free joint only on a body of the world, at the body's own "
            "frame",
            joint.name));
      }
    }
    for (const model::Constraint& c : model_.constraints()) {
      const bool kept = std::visit(
          [](const auto& k) {
            using T = std::decay_t<decltype(k)>;
            if constexpr (std::is_same_v<T, model::LoopClosure>) {
              return k.type != model::LoopType::slider;
            } else {
              return std::is_same_v<T, model::JointCoupler>;
            }
          },
          c);
      if (!kept && !model::is_unilateral(c)) {
        throw InvalidArgument(fmt::format(
            "constraint '{}' ({}): MJCF has no equality that keeps it (it keeps point, hinge and "
            "weld loops and couplers)",
            model::constraint_name(c), model::constraint_type_name(c)));
      }
    }
  }

  // MuJoCo's connect finds body2's point where the model is drawn: the loops must close there.
  void check_loops_closed() const {
    std::vector<Transform> X_WB(static_cast<std::size_t>(model_.num_bodies()));
    for (const model::Joint& joint : model_.joints()) {
      X_WB[static_cast<std::size_t>(joint.child_index)] =
          X_WB[static_cast<std::size_t>(joint.parent_index)] * joint.X_PJ *
          model::joint_transform(joint, q_.data() + joint.q_index) * joint.X_CJ.inverse();
    }
    for (const model::Constraint& c : model_.constraints()) {
      const auto* loop = std::get_if<model::LoopClosure>(&c);
      if (loop == nullptr || loop->type == model::LoopType::weld) continue;
      const Transform X_WA = X_WB[static_cast<std::size_t>(loop->a.body_index)] * loop->a.X_BF;
      const Transform X_WF = X_WB[static_cast<std::size_t>(loop->b.body_index)] * loop->b.X_BF;
      double gap = (X_WA.p - X_WF.p).norm();
      if (loop->type == model::LoopType::hinge) {
        gap = std::max(gap, (X_WA.R.col(2) - X_WF.R.col(2)).norm());  // the second point, 1 m out
      }
      if (gap > 1e-9) {
        throw InvalidArgument(fmt::format(
            "loop '{}' is open by {:.3g} m where the model is drawn: MJCF closes loops in the "
            "drawn configuration (momenta export draws the consistent initial state)",
            loop->name, gap));
      }
    }
  }

  // The body of joint j with its subtree, indented.
  std::string body(int j, const std::vector<std::vector<int>>& children, int indent) {
    const model::Joint& joint = model_.joints()[static_cast<std::size_t>(j)];
    const model::Body& b = model_.bodies()[static_cast<std::size_t>(joint.child_index)];
    const std::string pad(static_cast<std::size_t>(indent), ' ');
    const double* q = q_.data() + joint.q_index;
    const VecX& v0 = model_.initial_v();
    const auto velocity = [&](int k) { return v0.size() > 0 ? v0[joint.v_index + k] : 0.0; };
    // Where the body is drawn: X_PB = X_PJ · X_JJ'(q) · X_CJ⁻¹.
    const Transform X_PB = joint.X_PJ * model::joint_transform(joint, q) * joint.X_CJ.inverse();
    std::string out = fmt::format("{}<body name=\"{}\" pos=\"{}\" quat=\"{}\">\n", pad, b.name,
                                  vector_text(X_PB.p), quaternion_text(X_PB.R));
    const std::string inner(static_cast<std::size_t>(indent + 2), ' ');
    // Its joints: the damping and spring of a one-axis joint ride on its MJCF joint.
    double damping = detail::joint_viscous_damping(model_, j), stiffness = 0.0, rest = 0.0;
    for (const model::ForceElement& element : model_.force_elements()) {
      if (const auto* s = std::get_if<model::TorsionalSpringDamper>(&element);
          s && s->joint_index == j) {
        damping += s->damping;
        stiffness = s->stiffness;
        rest = s->rest_angle;
      }
    }
    const std::string passive =
        (damping != 0.0 ? fmt::format(" damping=\"{}\"", number_text(damping)) : "") +
        (joint.armature != 0.0 ? fmt::format(" armature=\"{}\"", number_text(joint.armature))
                               : "") +
        (stiffness != 0.0 ? fmt::format(" stiffness=\"{}\" springref=\"{}\"",
                                        number_text(stiffness), number_text(rest))
                          : "");
    if (joint.type == model::JointType::free) {
      out += joint.armature == 0.0
                 ? fmt::format("{}<freejoint name=\"{}\"/>\n", inner, joint.name)
                 : fmt::format("{}<joint name=\"{}\" type=\"free\" armature=\"{}\"/>\n", inner,
                               joint.name, number_text(joint.armature));
      // MuJoCo's free velocity: the body origin's in the world, then ω in the body.
      const Vec3 w(velocity(0), velocity(1), velocity(2)), v(velocity(3), velocity(4), velocity(5));
      append_velocity(joint.X_PJ.R * v);
      append_velocity(w);
    } else if (joint.type == model::JointType::spherical) {
      out += fmt::format("{}<joint name=\"{}\" type=\"ball\" pos=\"{}\"{}/>\n", inner, joint.name,
                         vector_text(joint.X_CJ.p), passive);
      append_velocity(joint.X_CJ.R * Vec3(velocity(0), velocity(1), velocity(2)));
    } else {
      // Each factor's axis in the drawn body frame: turned back through the factors after it.
      const std::vector<Factor> factors = factors_of(joint, q);
      for (std::size_t k = 0; k < factors.size(); ++k) {
        Transform after = Transform::identity();
        for (std::size_t i = k + 1; i < factors.size(); ++i) {
          after = after * factor_motion(factors[i], factors[i].drawn);
        }
        const Vec3 axis_B = joint.X_CJ.R * (after.R.transpose() * factors[k].axis);
        const Vec3 anchor_B = joint.X_CJ.apply(after.inverse().p);
        out += fmt::format(
            "{}<joint name=\"{}{}\" type=\"{}\" pos=\"{}\" axis=\"{}\" ref=\"{}\"{}{}/>\n", inner,
            joint.name, factors[k].suffix, factors[k].hinge ? "hinge" : "slide",
            vector_text(anchor_B), vector_text(axis_B), number_text(factors[k].drawn),
            factors.size() == 1 ? passive : "", range_text(joint));
        qvel_.conservativeResize(qvel_.size() + 1);
        qvel_[qvel_.size() - 1] = velocity(static_cast<int>(k));
      }
    }
    // Its mass properties in B (the inertia about the centre of mass, the tensor's entries).
    const inertia::MassProperties& mp = b.mass_properties;
    const Mat3& I = mp.inertia_about_com();
    out += fmt::format("{}<inertial pos=\"{}\" mass=\"{}\" fullinertia=\"{} {} {} {} {} {}\"/>\n",
                       inner, vector_text(mp.center_of_mass()), number_text(mp.mass()),
                       number_text(I(0, 0)), number_text(I(1, 1)), number_text(I(2, 2)),
                       number_text(I(0, 1)), number_text(I(0, 2)), number_text(I(1, 2)));
    out += geoms(joint.child_index, inner);
    out += contact_geoms(joint.child_index, inner);
    for (int child : children[static_cast<std::size_t>(joint.child_index)]) {
      out += body(child, children, indent + 2);
    }
    return out + pad + "</body>\n";
  }

  void append_velocity(const Vec3& w) {
    const Eigen::Index n = qvel_.size();
    qvel_.conservativeResize(n + 3);
    qvel_.segment<3>(n) = w;
  }

  // The body's parts that MJCF has shapes for, drawn only (no contacts, no mass: the inertial
  // gives the body's).
  std::string geoms(int body, const std::string& pad) const {
    std::string out;
    for (const PartSummary& part : file_.parts_of(body)) {
      if (part.hole) continue;
      std::map<std::string, double> s(part.sizes.begin(), part.sizes.end());
      std::string type, size;
      if (part.kind == "sphere") {
        type = "sphere", size = number_text(s["radius"]);
      } else if (part.kind == "box") {
        type = "box", size = vector_text(Vec3(s["size.x"], s["size.y"], s["size.z"]) / 2.0);
      } else if (part.kind == "cylinder" || part.kind == "capsule") {
        type = part.kind, size = number_text(s["radius"]) + " " + number_text(s["length"] / 2.0);
      } else if (part.kind == "ellipsoid") {
        type = "ellipsoid",
        size = vector_text(Vec3(s["semi_axes.x"], s["semi_axes.y"], s["semi_axes.z"]));
      } else {
        continue;
      }
      out += fmt::format(
          "{}<geom name=\"{}\" type=\"{}\" size=\"{}\" pos=\"{}\" quat=\"{}\" "
          "contype=\"0\" conaffinity=\"0\"/>\n",
          pad, part.name, type, size, vector_text(part.p_BoSo_B), quaternion_text(part.R_BS));
    }
    return out;
  }

  // --- contacts -------------------------------------------------------------------------------
  // A contact with a ground plane is written as the geom momenta's MJCF reader poses as it
  // (mjcf_contact_geoms.hpp: a sphere's; a cylinder for two rims, a box for eight corners) on the
  // body, against a plane geom of the world, plane k's pairs alone colliding (the geom's contype
  // and the plane's conaffinity the bit 1 << k; the plane's friction 0 and condim 1, so that
  // MuJoCo's mixing — the larger of each — gives the geom's). The reader reads them back as
  // contacts `<geom>_ground<k>` (`<geom>_rim1_ground<k>`, `<geom>_corner1_ground<k>`, …).
  // MuJoCo's contacts are soft: a restitution, or a kinetic friction below the static one, is
  // not written.

  // The names the bodies' drawn parts take as geoms.
  static std::vector<std::string> part_geom_names(const ModelFile& file) {
    std::vector<std::string> names;
    for (int b = 0; b < file.model.num_bodies(); ++b) {
      for (const PartSummary& part : file.parts_of(b)) names.push_back(part.name);
    }
    return names;
  }

  std::string ground_planes() const {
    std::string out;
    for (std::size_t k = 0; k < contact_geoms_.planes.size(); ++k) {
      const auto& [normal, point] = contact_geoms_.planes[k];
      out += fmt::format(
          "    <geom name=\"ground{}\" type=\"plane\" size=\"0 0 1\" pos=\"{}\" zaxis=\"{}\" "
          "friction=\"0\" condim=\"1\" contype=\"0\" conaffinity=\"{}\"/>\n",
          k, vector_text(point), vector_text(normal), 1u << k);
    }
    return out;
  }

  std::string contact_geoms(int body, const std::string& pad) const {
    std::string out;
    for (const detail::MjcfContactGeom& g : contact_geoms_.geoms) {
      if (g.body != body) continue;
      const std::string size =
          g.type == "sphere" ? number_text(g.size.x())
          : g.type == "cylinder"
              ? fmt::format("{} {}", number_text(g.size.x()), number_text(g.size.y()))
              : vector_text(g.size);
      const std::string quat =
          g.type == "sphere" ? "" : fmt::format(" quat=\"{}\"", quaternion_text(g.X_BG.R));
      out += fmt::format(
          "{}<geom name=\"{}\" type=\"{}\" size=\"{}\" pos=\"{}\"{} mass=\"0\" "
          "friction=\"{}\" condim=\"{}\" contype=\"{}\" conaffinity=\"0\"/>\n",
          pad, g.name, g.type, size, vector_text(g.X_BG.p), quat, number_text(g.friction),
          g.friction > 0.0 ? 3 : 1, 1u << g.plane);
    }
    return out;
  }

  std::vector<std::string> contacts_not_written() const {
    if (contact_geoms_.planes.size() > 31) {
      throw InvalidArgument(
          "MJCF export: contacts on more than 31 ground planes (MuJoCo's contype has 31 bits)");
    }
    std::vector<bool> written(model_.constraints().size(), false);
    for (const detail::MjcfContactGeom& g : contact_geoms_.geoms) {
      for (std::size_t i : g.contacts) written[i] = true;
    }
    std::vector<std::string> lost;
    for (std::size_t i = 0; i < model_.constraints().size(); ++i) {
      const auto* c = std::get_if<model::Contact>(&model_.constraints()[i]);
      if (c == nullptr) continue;
      if (!written[i]) {
        const char* what =
            !c->on_ground()
                ? (c->other_plane ? "with another body's plane" : "with another body's sphere")
            : c->shape == model::ContactShape::disk ? "a disk's rim with no coaxial partner"
            : c->radius == 0.0 ? "a point that is not one of eight corners of a box"
                               : "not one MuJoCo has";
        lost.push_back(
            fmt::format("contact '{}' (momenta writes a ground plane's contacts with a sphere, a "
                        "cylinder's two rims and a box's eight corners; this one is {})",
                        c->name, what));
        continue;
      }
      if (c->restitution != 0.0) {
        lost.push_back(
            fmt::format("the restitution {} of contact '{}' (MuJoCo's contacts are "
                        "soft: read back, it is plastic)",
                        c->restitution, c->name));
      }
      if (c->kinetic_friction != c->static_friction) {
        lost.push_back(
            fmt::format("the kinetic friction {} of contact '{}' (MuJoCo has one "
                        "coefficient: the static {} is written)",
                        c->kinetic_friction, c->name, c->static_friction));
      }
    }
    return lost;
  }

  // The fixed tendons. MuJoCo's length Σ cᵢ qposᵢ has no offset (qpos is momenta's q here):
  // its springlength is momenta's rest length less the offset — and MuJoCo 2.2 reads a negative
  // springlength as "the length at springref", so such a rest length is not written.
  std::string tendons(std::vector<std::string>& lost) const {
    std::string out;
    for (const model::ForceElement& element : model_.force_elements()) {
      const auto* tendon = std::get_if<model::FixedTendon>(&element);
      if (tendon == nullptr) continue;
      std::string attributes;
      if (tendon->stiffness != 0.0) {
        const double springlength = tendon->rest_length - tendon->offset;
        if (springlength >= 0.0) {
          attributes += fmt::format(" stiffness=\"{}\" springlength=\"{}\"",
                                    number_text(tendon->stiffness), number_text(springlength));
        } else {
          lost.push_back(
              fmt::format("tendon '{}''s spring (its rest length {} less its offset "
                          "is negative, which MJCF 2.2 reads as 'at springref')",
                          tendon->name, number_text(tendon->rest_length)));
        }
      }
      if (tendon->damping != 0.0) {
        attributes += fmt::format(" damping=\"{}\"", number_text(tendon->damping));
      }
      if (tendon->offset != 0.0) {
        lost.push_back(
            fmt::format("tendon '{}''s offset {} (MJCF's length has none: read back, "
                        "its length is less by that much, its forces the same)",
                        tendon->name, number_text(tendon->offset)));
      }
      out += fmt::format("    <fixed name=\"{}\"{}>\n", tendon->name, attributes);
      for (const model::TendonTerm& term : tendon->terms) {
        out += fmt::format("      <joint joint=\"{}\" coef=\"{}\"/>\n", term.joint,
                           number_text(term.coefficient));
      }
      out += "    </fixed>\n";
    }
    return out.empty() ? out : "  <tendon>\n" + out + "  </tendon>\n";
  }

  std::string equality() const {
    std::string out;
    const auto name_of = [&](int body) {
      return model_.bodies()[static_cast<std::size_t>(body)].name;
    };
    for (const model::Constraint& c : model_.constraints()) {
      if (const auto* loop = std::get_if<model::LoopClosure>(&c)) {
        // body1 is b (a, if b is the world); body2 its partner (left out for the world).
        const bool swap = loop->b.body_index == 0;
        const model::BodyFrame& one = swap ? loop->a : loop->b;
        const model::BodyFrame& two = swap ? loop->b : loop->a;
        const std::string body2 =
            two.body_index == 0 ? "" : fmt::format(" body2=\"{}\"", name_of(two.body_index));
        if (loop->type == model::LoopType::weld) {
          // relpose: body2's frame in body1's when the two frames coincide.
          const Transform X_12 = one.X_BF * two.X_BF.inverse();
          out += fmt::format("    <weld name=\"{}\" body1=\"{}\"{} relpose=\"{} {}\"/>\n",
                             loop->name, name_of(one.body_index), body2, vector_text(X_12.p),
                             quaternion_text(X_12.R));
          continue;
        }
        // A point, and for a hinge a second point 1 m along its axis: MuJoCo finds body2's
        // points where the model is drawn (assembled).
        out += fmt::format("    <connect name=\"{}\" body1=\"{}\"{} anchor=\"{}\"/>\n", loop->name,
                           name_of(one.body_index), body2, vector_text(one.X_BF.p));
        if (loop->type == model::LoopType::hinge) {
          out += fmt::format("    <connect name=\"{}_axis\" body1=\"{}\"{} anchor=\"{}\"/>\n",
                             loop->name, name_of(one.body_index), body2,
                             vector_text(one.X_BF.apply(Vec3::UnitZ())));
        }
      } else if (const auto* coupler = std::get_if<model::JointCoupler>(&c)) {
        // MuJoCo relates joint1 − ref1 to joint2 − ref2: the offset moves with the drawn values.
        const auto drawn = [&](int j) {
          return q_[model_.joints()[static_cast<std::size_t>(j)].q_index];
        };
        const double offset = coupler->ratio * drawn(coupler->joint_b_index) + coupler->offset -
                              drawn(coupler->joint_a_index);
        out += fmt::format(
            "    <joint name=\"{}\" joint1=\"{}\" joint2=\"{}\" polycoef=\"{} {} 0 0 0\"/>\n",
            coupler->name, coupler->joint_a, coupler->joint_b, number_text(offset),
            number_text(coupler->ratio));
      }
    }
    return out.empty() ? out : "  <equality>\n" + out + "  </equality>\n";
  }

  const ModelFile& file_;
  const model::Model& model_;
  const VecX& q_;
  VecX qvel_;  // the initial velocities in MuJoCo's order (the file's, depth first)
  detail::MjcfContactGeoms contact_geoms_;  // the geoms standing for its ground contacts
};

}  // namespace

ExportedModel write_mjcf(const ModelFile& file, const VecX& q_drawn) {
  return MjcfWriter(file, q_drawn).write();
}

}  // namespace momenta::io
