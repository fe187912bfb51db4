#include "momenta/analysis/free_body.hpp"

#include <algorithm>
#include <array>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/contact_geometry.hpp"
#include "momenta/dynamics/force_elements.hpp"
#include "momenta/dynamics/point_kinematics.hpp"
#include "momenta/dynamics/reactions.hpp"

namespace momenta::analysis {

namespace {

// A wrench as it acts on the body: moment about J'o and force, both in J'.
struct JointWrench {
  Vec3 moment;
  Vec3 force;
};

// Below this fraction of the largest load a component counts as round-off: what the planarity
// test allows out of the plane, and what the joint-split leaves as "nothing along the motion".
constexpr double kRelativeRoundOff = 1e-9;

// The kinetic terms of body b from the evaluated data.
void fill_kinetics(FreeBodyDiagram& d, const model::Model& model, const dynamics::Data& data,
                   int b) {
  const auto& mp = model.body(b).mass_properties;
  const Transform& X_WB = data.X_WB[b];
  d.w_WB_W = X_WB.R * data.V_WB_B[b].head<3>();
  // The angular part of the spatial acceleration is ω̇ itself (in B; R ω̇_B in W).
  d.alpha_WB_W = X_WB.R * data.A_WB_B[b].head<3>();
  d.a_WG_W = dynamics::point_kinematics(model, data, b, mp.center_of_mass()).a_WP_W;
}

// A wrench on the body given as its moment about G and its force (W), as a force through the
// point of its line of action nearest to G plus the couple along it that remains (a screw's
// pitch); a pure moment (a force too small to have a line of action) as a couple at G.
Load wrench_on_its_line(LoadKind kind, std::string name, std::string description,
                        const Vec3& p_WoG_W, const Vec3& n_G, const Vec3& f) {
  Load load{kind, std::move(name), std::move(description), p_WoG_W, f, n_G, -1};
  const double f2 = f.squaredNorm();
  // 1 m lever: a force whose line would lie further than 1e9 m from G is a couple.
  if (f2 == 0.0 || f.norm() <= kRelativeRoundOff * n_G.norm()) return load;
  load.p_WoP_W = p_WoG_W + f.cross(n_G) / f2;
  load.couple_W = n_G - (load.p_WoP_W - p_WoG_W).cross(f);
  return load;
}

// S (SᵀS)⁻¹ x: the wrench along joint j's free motions whose generalized force is x (the
// minimum-norm one: a moment about a hinge's axis, a force along a slider's), in J'.
JointWrench along_motion(const Mat6& S_full, int nv, const VecX& x) {
  const auto S = S_full.leftCols(nv);
  const Eigen::Matrix<double, 6, 1> w = S * (S.transpose() * S).ldlt().solve(x);
  return {w.head<3>(), w.tail<3>()};
}

class DiagramBuilder {
 public:
  // After system.evaluate(): the state it evaluated is the diagram's.
  DiagramBuilder(system::MultibodySystem& system, int b, FreeBodyDiagram& d)
      : system_(system),
        model_(system.model()),
        data_(system.data()),
        b_(b),
        d_(d),
        q_(system.evaluated_q()),
        v_(system.evaluated_v()) {
    for (const model::SignalSample& s : system.signal_samples()) signals_.push_back(s.value);
  }

  void add_gravity() {
    d_.loads.push_back({LoadKind::gravity, "gravity",
                        fmt::format("weight m g (m = {:.6g} kg)", d_.mass), d_.p_WoG_W,
                        d_.mass * model_.gravity(), Vec3::Zero(), -1});
  }

  // Body-acting force elements (springs at their points, loads, two-body torsion springs).
  void add_body_elements() {
    VecX tau(model_.nv());
    std::vector<Vec6> f_ext(static_cast<std::size_t>(model_.num_bodies()));
    const auto& elements = model_.force_elements();
    for (int e = 0; e < static_cast<int>(elements.size()); ++e) {
      dynamics::force_element_forces_of(model_, data_, e, signals_, q_, v_, tau, f_ext);
      element_tau_.push_back(tau);
      const Vec6& w_B = f_ext[static_cast<std::size_t>(b_)];
      if (!touches_body(elements[e])) continue;
      const Mat3& R = data_.X_WB[b_].R;
      const Vec3 f = R * w_B.tail<3>();
      // Moment about G: about Bo, shifted by the lever of G.
      const Vec3 n_G = R * (w_B.head<3>() -
                            model_.body(b_).mass_properties.center_of_mass().cross(w_B.tail<3>()));
      Load load =
          wrench_on_its_line(element_kind(elements[e]), model::force_element_name(elements[e]),
                             element_description(elements[e]), d_.p_WoG_W, n_G, f);
      if (const auto* point = attachment_on_body(elements[e])) {
        // A point force: drawn at its own point, not only on its line.
        load.p_WoP_W = data_.X_WB[b_].apply(point->p_BoP_B);
        load.couple_W = n_G - (load.p_WoP_W - d_.p_WoG_W).cross(f);
      }
      d_.loads.push_back(std::move(load));
    }
  }

  // The joint that carries the body (sign +1) and the joints it carries (−1: what the body
  // feels is the opposite of what it transmits to its child). Computes the reactions: rnea
  // overwrites the workspace that add_body_elements reads, so this comes last.
  void add_joints() {
    const VecX vdot = data_.vdot;
    dynamics::joint_reactions(model_, data_, q_, v_, vdot, system_.external_wrenches());
    add_joint(model_.body(b_).joint_index, +1.0);
    for (const model::Joint& j : model_.joints()) {
      if (j.parent_index == b_) add_joint(j.index, -1.0);
    }
  }

  // Constraint forces on the body, each constraint's rows summed, on its line of action; a
  // closed contact's whole force at its point.
  void add_constraints() {
    for (int k = 0; k < static_cast<int>(model_.constraints().size()); ++k) {
      std::optional<Load> load = constraint_load(system_, k, b_);
      const auto* contact = std::get_if<model::Contact>(&model_.constraints()[k]);
      if (contact != nullptr) load = contact_load(*contact, k, load);
      if (load) d_.loads.push_back(*load);
    }
  }

 private:
  // A contact's force on the body — its rows' (the normal force, and the friction while it
  // sticks) and the kinetic friction −μk N ŝ while it slides (a load the system applies) — drawn
  // at the contact point; −that on the body A of a contact between two bodies.
  std::optional<Load> contact_load(const model::Contact& c, int k,
                                   const std::optional<Load>& rows) const {
    const double sign = c.frame.body_index == b_ ? 1.0 : c.other.body_index == b_ ? -1.0 : 0.0;
    const Vec3 friction = sign * system_.contact_friction(k);
    if (sign == 0.0 || (!rows && friction.isZero(0.0))) return rows;
    // A contact transmits a force at its point and no couple: its rows' wrench has its line
    // through the point.
    Load load;
    load.kind = LoadKind::reaction;
    load.name = model::constraint_name(model_.constraints()[static_cast<std::size_t>(k)]);
    load.p_WoP_W = dynamics::contact_geometry(c, data_).point_W;
    load.force_W = friction + (rows ? rows->force_W : Vec3::Zero());
    const char* friction_text = c.static_friction == 0.0 ? ""
                                : friction.isZero(0.0)
                                    ? " and the friction that holds it (sticking)"
                                    : " and kinetic friction μk N against the slip (sliding)";
    load.description = fmt::format("contact {}: its normal force{}", load.name, friction_text);
    return load;
  }

  bool touches_body(const model::ForceElement& element) const {
    return std::visit(
        [&](const auto& e) {
          using T = std::decay_t<decltype(e)>;
          if constexpr (std::is_same_v<T, model::LinearSpringDamper>) {
            return e.a.body_index == b_ || e.b.body_index == b_;
          } else if constexpr (std::is_same_v<T, model::TorsionalSpringDamper>) {
            return e.joint_index < 0 && (e.body_a_index == b_ || e.body_b_index == b_);
          } else if constexpr (std::is_same_v<T, model::AppliedForce>) {
            return e.at.body_index == b_;
          } else if constexpr (std::is_same_v<T, model::AppliedTorque>) {
            return e.body_index == b_;
          } else {
            return false;  // joint friction and tendons act through their joints
          }
        },
        element);
  }

  const model::BodyPoint* attachment_on_body(const model::ForceElement& element) const {
    if (const auto* s = std::get_if<model::LinearSpringDamper>(&element)) {
      if (s->a.body_index == b_ && s->b.body_index != b_) return &s->a;
      if (s->b.body_index == b_ && s->a.body_index != b_) return &s->b;
    }
    if (const auto* f = std::get_if<model::AppliedForce>(&element)) return &f->at;
    return nullptr;
  }

  static LoadKind element_kind(const model::ForceElement& element) {
    return std::holds_alternative<model::AppliedForce>(element) ||
                   std::holds_alternative<model::AppliedTorque>(element)
               ? LoadKind::applied
               : LoadKind::element;
  }

  std::string element_description(const model::ForceElement& element) const {
    return std::visit(
        [&](const auto& e) -> std::string {
          using T = std::decay_t<decltype(e)>;
          if constexpr (std::is_same_v<T, model::LinearSpringDamper>) {
            const std::string& other = e.a.body_index == b_ ? e.b.body : e.a.body;
            return fmt::format("spring-damper {} (to {})", e.name, other);
          } else if constexpr (std::is_same_v<T, model::TorsionalSpringDamper>) {
            if (e.joint_index >= 0)
              return fmt::format("torsional spring {} on joint {}", e.name, e.joint);
            const std::string& other = e.body_a_index == b_ ? e.body_b : e.body_a;
            return fmt::format("torsional spring {} (to {})", e.name, other);
          } else if constexpr (std::is_same_v<T, model::JointFriction>) {
            return fmt::format("friction {} on joint {}", e.name, e.joint);
          } else if constexpr (std::is_same_v<T, model::FixedTendon>) {
            return fmt::format("tendon {} through joint {}", e.name,
                               model_.joint(joint_index_).name);
          } else if constexpr (std::is_same_v<T, model::AppliedForce>) {
            return fmt::format("applied force {}", e.name);
          } else {
            return fmt::format("applied moment {}", e.name);
          }
        },
        element);
  }

  // Joint j's items on the body, `sign` = +1 when the body is its child.
  void add_joint(int j, double sign) {
    joint_index_ = j;
    const model::Joint& joint = model_.joint(j);
    const auto& c = model_.joint_constants()[static_cast<std::size_t>(j)];
    const dynamics::JointReaction r =
        dynamics::joint_reaction(model_, data_, j, model::ReactionFrame::joint);
    // J' in the world: the child's pose times X_CJ.
    const Transform X_WJ = data_.X_WB[c.child] * c.X_JC.inverse();
    const std::string other = model_.body(sign > 0 ? joint.parent_index : joint.child_index).name;
    const std::string side = sign > 0 ? "from " + other : "on " + other + ", reversed";

    JointWrench reaction{r.moment, r.force};
    const int nv = joint.nv();
    if (nv > 0) {
      const Mat6 S = model::joint_motion_subspace(joint, q_.data() + joint.q_index);
      const auto St = S.leftCols(nv).transpose();
      Eigen::Matrix<double, 6, 1> w;
      w << r.moment, r.force;
      const VecX tau_total = St * w;  // the joint's generalized force
      const JointWrench motion = along_motion(S, nv, tau_total);
      reaction.moment -= motion.moment;
      reaction.force -= motion.force;
      VecX rest = tau_total;
      // The joint's own damping, then each element acting through it.
      if (joint.damping != 0.0) {
        const VecX tau = -joint.damping * v_.segment(joint.v_index, nv);
        rest -= tau;
        push_joint_load(LoadKind::element, joint.name,
                        fmt::format("damping of joint {} ({})", joint.name, side), X_WJ,
                        along_motion(S, nv, tau), sign);
      }
      const auto& elements = model_.force_elements();
      for (std::size_t e = 0; e < elements.size(); ++e) {
        const VecX tau = element_tau_[e].segment(joint.v_index, nv);
        if (tau.isZero(0.0)) continue;
        rest -= tau;
        push_joint_load(LoadKind::element, model::force_element_name(elements[e]),
                        element_description(elements[e]) + " (" + side + ")", X_WJ,
                        along_motion(S, nv, tau), sign);
      }
      // What remains along the motion: a prescribed joint's drive, or a coupler's force.
      // (Round-off against the whole transmitted wrench and the loads already on the body: a
      // joint that carries no torque has a τ of round-off only.)
      if (rest.norm() > kRelativeRoundOff * std::max({tau_total.norm(), r.force.norm(),
                                                      r.moment.norm(), loads_scale(), 1e-300})) {
        const bool drive = joint.is_prescribed();
        push_joint_load(drive ? LoadKind::drive : LoadKind::reaction, joint.name,
                        fmt::format("{} of joint {} ({})",
                                    drive ? "drive effort (prescribed motion)"
                                          : "coupler force along the motion",
                                    joint.name, side),
                        X_WJ, along_motion(S, nv, rest), sign);
      }
    }
    push_joint_load(LoadKind::reaction, joint.name,
                    fmt::format("reaction of joint {} ({})", joint.name, side), X_WJ, reaction,
                    sign);
  }

  // The largest force (N) and moment about G (N·m) among the loads so far, summed.
  double loads_scale() const {
    double force = 0.0, moment = 0.0;
    for (const Load& load : d_.loads) {
      force = std::max(force, load.force_W.norm());
      moment = std::max(moment,
                        (load.couple_W + (load.p_WoP_W - d_.p_WoG_W).cross(load.force_W)).norm());
    }
    return force + moment;
  }

  void push_joint_load(LoadKind kind, std::string name, std::string description,
                       const Transform& X_WJ, const JointWrench& w, double sign) {
    d_.loads.push_back({kind, std::move(name), std::move(description), X_WJ.p,
                        sign * (X_WJ.R * w.force), sign * (X_WJ.R * w.moment), joint_index_});
  }

 private:
  system::MultibodySystem& system_;
  const model::Model& model_;
  dynamics::Data& data_;
  int b_;
  FreeBodyDiagram& d_;
  const VecX q_, v_;               // the evaluated state (prescribed coordinates applied)
  std::vector<double> signals_;    // the signals' values at the instant
  std::vector<VecX> element_tau_;  // per force element, its generalized forces
  int joint_index_ = -1;           // the joint add_joint is at
};

}  // namespace

const char* load_kind_name(LoadKind kind) {
  switch (kind) {
    case LoadKind::gravity:
      return "gravity";
    case LoadKind::reaction:
      return "reaction";
    case LoadKind::element:
      return "element";
    case LoadKind::applied:
      return "applied";
    case LoadKind::drive:
      return "drive";
  }
  return "";
}

Vec3 sum_of_forces(std::span<const Load> loads) {
  Vec3 sum = Vec3::Zero();
  for (const Load& load : loads) sum += load.force_W;
  return sum;
}

Vec3 sum_of_moments_about(std::span<const Load> loads, const Vec3& p_WoO_W) {
  Vec3 sum = Vec3::Zero();
  for (const Load& load : loads)
    sum += (load.p_WoP_W - p_WoO_W).cross(load.force_W) + load.couple_W;
  return sum;
}

Vec3 FreeBodyDiagram::sum_of_forces() const { return analysis::sum_of_forces(loads); }

Vec3 FreeBodyDiagram::sum_of_moments_about_G() const {
  return sum_of_moments_about(loads, p_WoG_W);
}

std::optional<Load> constraint_load(const system::MultibodySystem& system, int constraint,
                                    int body) {
  const system::ConstraintSolver* solver = system.constraints();
  if (solver == nullptr) return std::nullopt;
  return constraint_load(system.model(), system.data(), solver->rows(), solver->multipliers(),
                         constraint, body);
}

std::optional<Load> constraint_load(const model::Model& model, const dynamics::Data& data,
                                    const dynamics::ConstraintRows& rows, const VecX& multipliers,
                                    int constraint, int body) {
  Vec6 w_O = Vec6::Zero();  // on the body, in W about Wo
  bool acts = false;
  for (int i = 0; i < rows.count; ++i) {
    const auto row = static_cast<std::size_t>(i);
    if (rows.constraint[row] != constraint) continue;
    const double sign = rows.body_b[row] == body ? 1.0 : rows.body_a[row] == body ? -1.0 : 0.0;
    if (sign == 0.0 || rows.wrench_W[row].isZero(0.0)) continue;
    acts = true;
    w_O += sign * multipliers[i] * rows.wrench_W[row];
  }
  if (!acts) return std::nullopt;
  const model::Constraint& c = model.constraints()[static_cast<std::size_t>(constraint)];
  const Vec3 p_WoG_W = data.X_WB[body].apply(model.body(body).mass_properties.center_of_mass());
  const Vec3 f = w_O.tail<3>();
  const Vec3 n_G = w_O.head<3>() - p_WoG_W.cross(f);
  const std::string& name = model::constraint_name(c);
  return wrench_on_its_line(
      LoadKind::reaction, name,
      fmt::format("reaction of the {} constraint {}", model::constraint_type_name(c), name),
      p_WoG_W, n_G, f);
}

std::optional<Vec3> plane_of_loads(const model::Model& model, int b, const Mat3& R_WB,
                                   const Vec3& p_WoG_W, std::span<const Load> loads,
                                   std::span<const Vec3> forces, std::span<const Vec3> moments) {
  std::vector<Vec3> candidates = {Vec3::UnitZ(), Vec3::UnitY(), Vec3::UnitX()};
  const model::Joint& joint = model.joint(model.body(b).joint_index);
  if (joint.type == model::JointType::revolute || joint.type == model::JointType::cylindrical) {
    // The axis is the same in J and J'; J' turns with the body (R_WJ' = R_WB R_BJ').
    const auto& c = model.joint_constants()[static_cast<std::size_t>(joint.index)];
    candidates.push_back((R_WB * c.X_JC.R.transpose() * joint.axis).normalized());
  }
  // From the loads themselves: the largest moment about G, and the normal of the two largest
  // forces (a rotor's bearing couple turns with it, off every world axis).
  double force_scale = 0.0, moment_scale = 0.0;
  Vec3 largest_moment = Vec3::Zero(), largest_force = Vec3::Zero(), second_force = Vec3::Zero();
  const auto consider_force = [&](const Vec3& f) {
    if (f.norm() > force_scale) {
      second_force = largest_force;
      largest_force = f;
    } else if (f.norm() > second_force.norm()) {
      second_force = f;
    }
    force_scale = std::max(force_scale, f.norm());
  };
  const auto consider_moment = [&](const Vec3& m) {
    if (m.norm() > moment_scale) largest_moment = m;
    moment_scale = std::max(moment_scale, m.norm());
  };
  for (const Vec3& f : forces) consider_force(f);
  for (const Vec3& m : moments) consider_moment(m);
  for (const Load& load : loads) {
    consider_moment((load.p_WoP_W - p_WoG_W).cross(load.force_W) + load.couple_W);
    consider_force(load.force_W);
  }
  if (largest_moment.norm() > 0.0) candidates.push_back(largest_moment.normalized());
  const Vec3 across = largest_force.cross(second_force);
  if (across.norm() > kRelativeRoundOff * largest_force.norm() * second_force.norm() &&
      across.norm() > 0.0) {
    candidates.push_back(across.normalized());
  }
  const double force_tol = kRelativeRoundOff * force_scale;
  const double moment_tol = kRelativeRoundOff * moment_scale;
  for (const Vec3& n : candidates) {
    const auto in_plane = [&](const Vec3& f) { return std::abs(f.dot(n)) <= force_tol; };
    const auto normal = [&](const Vec3& m) { return (m - m.dot(n) * n).norm() <= moment_tol; };
    bool planar = std::all_of(forces.begin(), forces.end(), in_plane) &&
                  std::all_of(moments.begin(), moments.end(), normal);
    for (const Load& load : loads) {
      planar = planar && in_plane(load.force_W) &&
               normal((load.p_WoP_W - p_WoG_W).cross(load.force_W) + load.couple_W);
    }
    if (planar) return n;
  }
  return std::nullopt;
}

int diagram_body_index(const model::Model& model, const std::string& name, std::string_view diagram,
                       std::string_view why) {
  const int b = model.body_index(name);  // throws with a did-you-mean
  if (b == 0) {
    throw InvalidArgument(fmt::format("the world has no {}: {} (name a body)", diagram, why));
  }
  return b;
}

DiagramBody diagram_body(const model::Model& model, const dynamics::Data& data, int b, double t) {
  const auto& mp = model.body(b).mass_properties;
  const Transform& X_WB = data.X_WB[b];
  DiagramBody d;
  d.body = model.body(b).name;
  d.t = t;
  d.mass = mp.mass();
  d.R_WB = X_WB.R;
  d.p_WoBo_W = X_WB.p;
  d.p_WoG_W = X_WB.apply(mp.center_of_mass());
  d.I_G_W = X_WB.R * mp.inertia_about_com() * X_WB.R.transpose();
  return d;
}

FreeBodyDiagram free_body_diagram(system::MultibodySystem& system, const std::string& body,
                                  double t, const VecX& q, const VecX& v) {
  const model::Model& model = system.model();
  const int b = diagram_body_index(model, body, "free-body diagram",
                                   "it is the ground everything is held against");
  system.evaluate(t, q, v);
  dynamics::Data& data = system.data();
  FreeBodyDiagram d;
  static_cast<DiagramBody&>(d) = diagram_body(model, data, b, t);
  fill_kinetics(d, model, data, b);

  DiagramBuilder builder(system, b, d);
  builder.add_gravity();
  builder.add_body_elements();
  builder.add_constraints();
  builder.add_joints();
  const std::array<Vec3, 1> forces{d.m_a_G()}, moments{d.H_G_dot()};
  d.plane_normal = plane_of_loads(model, b, d.R_WB, d.p_WoG_W, d.loads, forces, moments);
  return d;
}

}  // namespace momenta::analysis
