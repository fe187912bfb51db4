#include "momenta/model/model_builder.hpp"

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/math/rotation.hpp"

namespace momenta::model {
namespace {

// Unit-axis tolerance: axes are read from files with ~16 digits; 1e-9 admits round-off of a
// normalized vector written out, and rejects axes that were simply not normalized.
constexpr double kAxisTolerance = 1e-9;

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};

std::string vec_str(const Vec3& v) { return fmt::format("({}, {}, {})", v.x(), v.y(), v.z()); }

// Throws InvalidArgument with the formatted message when cond fails; the message is only
// formatted then (its arguments may be invalid otherwise).
#define MOMENTA_REQUIRE(cond, ...)                                \
  do {                                                            \
    if (!(cond)) throw InvalidArgument(fmt::format(__VA_ARGS__)); \
  } while (0)

void require(bool ok, const std::string& message) {
  if (!ok) throw InvalidArgument(message);
}

bool is_massless(const inertia::MassProperties& mp) {
  return mp.mass() == 0.0 && mp.inertia_about_com().isZero(0.0);
}

void check_transform(const Transform& X, const std::string& what) {
  check_rotation_matrix(X.R, what);
  MOMENTA_REQUIRE(X.p.allFinite(), "{}: position {} is not finite", what, vec_str(X.p));
}

void check_axis(const Vec3& a, const std::string& what) {
  MOMENTA_REQUIRE(a.allFinite() && std::abs(a.norm() - 1.0) <= kAxisTolerance,
                  "{} {} must be a unit vector (its norm is {:.17g})", what, vec_str(a), a.norm());
}

// Names of the configuration and velocity coordinates of one joint.
void coordinate_names(const Joint& j, std::vector<std::string>& q, std::vector<std::string>& v) {
  const auto add = [&](std::initializer_list<const char*> qs,
                       std::initializer_list<const char*> vs) {
    for (const char* s : qs) q.push_back(j.name + "." + s);
    for (const char* s : vs) v.push_back(j.name + "." + s);
  };
  switch (j.type) {
    case JointType::fixed:
      break;
    case JointType::revolute:
      add({"angle"}, {"angle_rate"});
      break;
    case JointType::prismatic:
      add({"position"}, {"position_rate"});
      break;
    case JointType::cylindrical:
      add({"angle", "position"}, {"angle_rate", "position_rate"});
      break;
    case JointType::universal:
      add({"angle1", "angle2"}, {"angle1_rate", "angle2_rate"});
      break;
    case JointType::spherical:
      add({"qw", "qx", "qy", "qz"}, {"wx", "wy", "wz"});
      break;
    case JointType::planar:
      add({"x", "y", "angle"}, {"x_rate", "y_rate", "angle_rate"});
      break;
    case JointType::free:
      add({"x", "y", "z", "qw", "qx", "qy", "qz"}, {"wx", "wy", "wz", "vx", "vy", "vz"});
      break;
  }
}

}  // namespace

ModelBuilder& ModelBuilder::set_gravity(const Vec3& g_W) {
  MOMENTA_REQUIRE(g_W.allFinite(), "gravity {} is not finite", vec_str(g_W));
  gravity_ = g_W;
  return *this;
}

ModelBuilder& ModelBuilder::add_body(Body body) {
  bodies_.push_back(std::move(body));
  return *this;
}

ModelBuilder& ModelBuilder::add_body(std::string name, const inertia::MassProperties& mp) {
  Body body;
  body.name = std::move(name);
  body.mass_properties = mp;
  return add_body(std::move(body));
}

ModelBuilder& ModelBuilder::add_joint(Joint joint) {
  joints_.push_back(std::move(joint));
  return *this;
}

ModelBuilder& ModelBuilder::add_force_element(ForceElement element) {
  force_elements_.push_back(std::move(element));
  return *this;
}

ModelBuilder& ModelBuilder::add_signal(Signal signal) {
  signals_.push_back(std::move(signal));
  return *this;
}

Model ModelBuilder::build() const {
  Model model;
  model.gravity_ = gravity_;

  // --- Bodies: unique names, physical mass properties --------------------------------------------
  std::map<std::string, int, std::less<>> body_by_name;  // index into bodies_ (input order)
  std::vector<std::string_view> body_names{kWorldBodyName};
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const Body& b = bodies_[i];
    MOMENTA_REQUIRE(!b.name.empty(), "body #{} has an empty name", i + 1);
    MOMENTA_REQUIRE(b.name != kWorldBodyName,
                    "a body may not be called '{}': that name is the ground", kWorldBodyName);
    MOMENTA_REQUIRE(body_by_name.emplace(b.name, static_cast<int>(i)).second,
                    "two bodies are named '{}'", b.name);
    if (!is_massless(b.mass_properties)) {
      b.mass_properties.check_physical(fmt::format("body '{}'", b.name));
    }
    body_names.push_back(b.name);
  }
  const auto unknown_body = [&](std::string_view name) { return did_you_mean(name, body_names); };

  // --- Signals: unique names ---------------------------------------------------------------------
  std::map<std::string, int, std::less<>> signal_by_name;
  std::vector<std::string_view> signal_names;
  for (std::size_t i = 0; i < signals_.size(); ++i) {
    MOMENTA_REQUIRE(!signals_[i].name().empty(), "signal #{} has an empty name", i + 1);
    MOMENTA_REQUIRE(signal_by_name.emplace(signals_[i].name(), static_cast<int>(i)).second,
                    "two signals are named '{}'", signals_[i].name());
    signal_names.push_back(signals_[i].name());
  }
  const auto find_signal = [&](const std::string& name, const std::string& who) {
    auto it = signal_by_name.find(name);
    MOMENTA_REQUIRE(it != signal_by_name.end(), "{}: unknown signal '{}'{}", who, name,
                    did_you_mean(name, signal_names));
    return it->second;
  };

  // --- Joints: parents and children exist, one joint per body ------------------------------------
  std::set<std::string, std::less<>> joint_names;
  std::vector<int> joint_of_child(bodies_.size(), -1);  // input joint carrying input body
  for (std::size_t k = 0; k < joints_.size(); ++k) {
    const Joint& j = joints_[k];
    MOMENTA_REQUIRE(!j.name.empty(), "joint #{} has an empty name", k + 1);
    MOMENTA_REQUIRE(joint_names.insert(j.name).second, "two joints are named '{}'", j.name);
    const std::string who = fmt::format("joint '{}'", j.name);
    MOMENTA_REQUIRE(j.parent == kWorldBodyName || body_by_name.count(j.parent),
                    "{}: unknown parent body '{}'{}", who, j.parent, unknown_body(j.parent));
    MOMENTA_REQUIRE(j.child != kWorldBodyName,
                    "{}: the world cannot be a child (swap parent and child)", who);
    auto child = body_by_name.find(j.child);
    MOMENTA_REQUIRE(child != body_by_name.end(), "{}: unknown child body '{}'{}", who, j.child,
                    unknown_body(j.child));
    MOMENTA_REQUIRE(j.child != j.parent, "{}: connects body '{}' to itself", who, j.child);
    int& carrier = joint_of_child[child->second];
    MOMENTA_REQUIRE(carrier < 0,
                    "body '{}' is the child of two joints, '{}' and '{}': the bodies must form "
                    "a tree (closed loops are not supported)",
                    j.child, joints_[carrier].name, j.name);
    carrier = static_cast<int>(k);

    // Geometry, initial state and parameters.
    check_transform(j.X_PJ, who + " X_PJ");
    check_transform(j.X_CJ, who + " X_CJ");
    const JointType t = j.type;
    if (t == JointType::revolute || t == JointType::prismatic || t == JointType::cylindrical ||
        t == JointType::universal) {
      check_axis(j.axis, who + " axis");
    }
    if (t == JointType::universal) {
      check_axis(j.axis2, who + " axis2");
      MOMENTA_REQUIRE(j.axis.cross(j.axis2).norm() > 1e-6,
                      "{}: universal axes {} and {} are parallel", who, vec_str(j.axis),
                      vec_str(j.axis2));
    }
    MOMENTA_REQUIRE(j.q0.size() == 0 || j.q0.size() == j.nq(),
                    "{}: q0 has {} values; a {} joint has {}", who, j.q0.size(), joint_type_name(t),
                    j.nq());
    MOMENTA_REQUIRE(j.v0.size() == 0 || j.v0.size() == j.nv(),
                    "{}: v0 has {} values; a {} joint has {}", who, j.v0.size(), joint_type_name(t),
                    j.nv());
    MOMENTA_REQUIRE(j.q0.allFinite() && j.v0.allFinite(), "{}: q0 or v0 is not finite", who);
    MOMENTA_REQUIRE(j.damping >= 0 && std::isfinite(j.damping),
                    "{}: damping {} must be zero or positive", who, j.damping);
    if (j.is_prescribed()) {
      MOMENTA_REQUIRE(j.nq() == j.nv() && j.nv() > 0,
                      "{}: a {} joint cannot be prescribed by signals (only joints with "
                      "nq == nv: revolute, prismatic, cylindrical, universal, planar)",
                      who, joint_type_name(t));
      MOMENTA_REQUIRE(static_cast<int>(j.prescribed_signals.size()) == j.nv(),
                      "{}: {} prescribed signals given; a {} joint needs one per coordinate, {}",
                      who, j.prescribed_signals.size(), joint_type_name(t), j.nv());
    }
  }
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    MOMENTA_REQUIRE(joint_of_child[i] >= 0,
                    "body '{}' is not attached to anything: add a joint with it as the child "
                    "(type fixed to weld it)",
                    bodies_[i].name);
  }

  // --- Topological order from the world (breadth first); unreached bodies lie on a cycle --------
  std::vector<int> order;  // input body indices in model order (after the world)
  {
    std::vector<std::string_view> frontier{kWorldBodyName};
    std::vector<char> placed(bodies_.size(), 0);
    for (std::size_t f = 0; f < frontier.size(); ++f) {
      for (std::size_t k = 0; k < joints_.size(); ++k) {
        if (joints_[k].parent != frontier[f]) continue;
        const int c = body_by_name.find(joints_[k].child)->second;
        placed[c] = 1;
        order.push_back(c);
        frontier.push_back(bodies_[c].name);
      }
    }
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      if (placed[i]) continue;
      // Walk up from an unplaced body to show the cycle.
      std::string cycle = bodies_[i].name;
      int b = static_cast<int>(i);
      for (std::size_t step = 0; step <= bodies_.size(); ++step) {
        const Joint& j = joints_[joint_of_child[b]];
        cycle += " <- " + j.parent;
        b = body_by_name.find(j.parent)->second;
        if (b == static_cast<int>(i)) break;
      }
      throw InvalidArgument(fmt::format(
          "the joints form a cycle ({}): the bodies must form a tree rooted at the world", cycle));
    }
  }

  // --- Bodies and joints in model order ----------------------------------------------------------
  std::vector<int> model_index(bodies_.size());
  for (std::size_t m = 0; m < order.size(); ++m) model_index[order[m]] = static_cast<int>(m) + 1;
  {
    Body world;
    world.name = kWorldBodyName;
    world.index = 0;
    model.bodies_.push_back(world);
  }
  int nq = 0, nv = 0;
  for (std::size_t m = 0; m < order.size(); ++m) {
    const int in = order[m];
    Joint joint = joints_[joint_of_child[in]];
    const int child = static_cast<int>(m) + 1;
    joint.index = child - 1;
    joint.child_index = child;
    joint.parent_index =
        joint.parent == kWorldBodyName ? 0 : model_index[body_by_name.find(joint.parent)->second];
    joint.q_index = nq;
    joint.v_index = nv;
    nq += joint.nq();
    nv += joint.nv();
    joint.prescribed_signal_indices.clear();
    for (const auto& s : joint.prescribed_signals) {
      joint.prescribed_signal_indices.push_back(find_signal(s, "joint '" + joint.name + "'"));
    }
    Body body = bodies_[in];
    body.index = child;
    body.parent_index = joint.parent_index;
    body.joint_index = joint.index;
    model.bodies_.push_back(std::move(body));
    model.joints_.push_back(std::move(joint));
  }
  model.nq_ = nq;
  model.nv_ = nv;

  // --- Inertias, initial state, coordinate names, constants for the algorithms -----------------
  model.inertias_.resize(model.bodies_.size());
  model.total_mass_ = 0.0;
  for (std::size_t b = 1; b < model.bodies_.size(); ++b) {
    model.inertias_[b] = SpatialInertia::from_mass_properties(model.bodies_[b].mass_properties);
    model.total_mass_ += model.bodies_[b].mass_properties.mass();
  }
  model.q0_ = neutral(model);
  model.v0_ = VecX::Zero(nv);
  for (const Joint& j : model.joints_) {
    if (j.q0.size() > 0) model.q0_.segment(j.q_index, j.nq()) = j.q0;
    if (j.v0.size() > 0) model.v0_.segment(j.v_index, j.nv()) = j.v0;
    const int k = j.type == JointType::spherical ? 0 : (j.type == JointType::free ? 3 : -1);
    if (k >= 0 && j.q0.size() > 0) {
      const Quat r = quaternion_from_wxyz(j.q0.segment<4>(k), "joint '" + j.name + "' q0");
      model.q0_.segment<4>(j.q_index + k) << r.w(), r.x(), r.y(), r.z();
    }
    for (int i = 0; i < j.nq(); ++i) model.joint_of_q_.push_back(j.index);
    for (int i = 0; i < j.nv(); ++i) model.joint_of_v_.push_back(j.index);
    coordinate_names(j, model.q_names_, model.v_names_);
    model.has_prescribed_ = model.has_prescribed_ || j.is_prescribed();

    JointConstants c;
    c.type = j.type;
    c.nq = j.nq();
    c.nv = j.nv();
    c.q_index = j.q_index;
    c.v_index = j.v_index;
    c.parent = j.parent_index;
    c.child = j.child_index;
    c.X_PJ = j.X_PJ;
    c.X_JC = j.X_CJ.inverse();
    c.child_at_joint = j.X_CJ.R == Mat3::Identity() && j.X_CJ.p.isZero(0.0);
    c.axis = j.axis;
    c.axis2 = j.axis2;
    if (c.nv == 1) {
      const Mat6 S_J = joint_motion_subspace(j, model.q0_.data() + j.q_index);
      c.S_C = j.X_CJ.act_motion(S_J.col(0));
      for (int k2 = 0; k2 < 6; ++k2) {
        Vec6 e = Vec6::Zero();
        e[k2] = 1.0;
        if (c.S_C == e) c.S_basis = k2;
      }
    }
    model.constants_.push_back(c);
  }

  // --- Singular mass matrix: every joint with degrees of freedom must move some inertia ---------
  // Composite inertia of each subtree at the neutral configuration, in its body frame; the
  // joint's block Sᵀ I S must be positive definite there.
  {
    const VecX qn = neutral(model);
    std::vector<SpatialInertia> composite = model.inertias_;
    for (int j = model.num_joints() - 1; j >= 0; --j) {
      const Joint& joint = model.joints_[j];
      if (joint.parent_index == 0) continue;
      const Transform X_PC =
          joint.X_PJ * joint_transform(joint, qn.data() + joint.q_index) * joint.X_CJ.inverse();
      composite[joint.parent_index] += composite[joint.child_index].transformed(X_PC);
    }
    for (const Joint& joint : model.joints_) {
      if (joint.nv() == 0) continue;
      const SpatialInertia& I = composite[joint.child_index];
      MOMENTA_REQUIRE(I.mass > 0 || !I.I_O.isZero(0.0),
                      "joint '{}' carries only massless bodies (body '{}' and its subtree): "
                      "its mass matrix would be singular; give them mass or make the joint "
                      "fixed",
                      joint.name, joint.child);
      const Mat6 S_J = joint_motion_subspace(joint, qn.data() + joint.q_index);
      const int n = joint.nv();
      Mat6 S_C = Mat6::Zero();
      for (int k = 0; k < n; ++k) S_C.col(k) = joint.X_CJ.act_motion(S_J.col(k));
      const MatX D = S_C.leftCols(n).transpose() * I.matrix() * S_C.leftCols(n);
      const Eigen::SelfAdjointEigenSolver<MatX> eig(D);
      const double largest = eig.eigenvalues().cwiseAbs().maxCoeff();
      MOMENTA_REQUIRE(eig.eigenvalues().minCoeff() > 1e-12 * largest && largest > 0,
                      "joint '{}': the bodies it carries have no inertia along some of its {} "
                      "degrees of freedom (smallest eigenvalue {:.3g} of Sᵀ I S, largest "
                      "{:.3g}): the mass matrix would be singular",
                      joint.name, n, eig.eigenvalues().minCoeff(), largest);
    }
  }

  // --- Force elements ----------------------------------------------------------------------------
  std::set<std::string, std::less<>> element_names;
  const auto body_at = [&](const std::string& name, const std::string& who) {
    if (name == kWorldBodyName) return 0;
    auto it = body_by_name.find(name);
    MOMENTA_REQUIRE(it != body_by_name.end(), "{}: unknown body '{}'{}", who, name,
                    unknown_body(name));
    return model_index[it->second];
  };
  std::vector<std::string_view> joint_name_list;
  for (const Joint& j : model.joints_) joint_name_list.push_back(j.name);
  const auto joint_at = [&](const std::string& name, const std::string& who) {
    auto i = model.find_joint(name);
    MOMENTA_REQUIRE(i.has_value(), "{}: unknown joint '{}'{}", who, name,
                    did_you_mean(name, joint_name_list));
    return *i;
  };
  const auto nonnegative = [](double x, const std::string& who, const char* what) {
    MOMENTA_REQUIRE(x >= 0 && std::isfinite(x), "{}: {} {} must be zero or positive", who, what, x);
  };
  // Body orientations in the world at the initial configuration: the rest orientation of the
  // two-body torsional springs (the world, body 0, is the identity).
  std::vector<Mat3> R_WB_initial(model.bodies_.size(), Mat3::Identity());
  for (const Joint& j : model.joints_) {
    const Transform X_PC =
        j.X_PJ * joint_transform(j, model.q0_.data() + j.q_index) * j.X_CJ.inverse();
    R_WB_initial[j.child_index] = R_WB_initial[j.parent_index] * X_PC.R;
  }
  for (ForceElement element : force_elements_) {
    const std::string& name = force_element_name(element);
    require(!name.empty(), "a force element has an empty name");
    MOMENTA_REQUIRE(element_names.insert(name).second, "two force elements are named '{}'", name);
    const std::string who = fmt::format("force element '{}'", name);
    std::visit(
        Overloaded{[&](LinearSpringDamper& e) {
                     e.a.body_index = body_at(e.a.body, who);
                     e.b.body_index = body_at(e.b.body, who);
                     require(e.a.p_BoP_B.allFinite() && e.b.p_BoP_B.allFinite(),
                             who + ": attachment point is not finite");
                     MOMENTA_REQUIRE(e.a.body_index != e.b.body_index,
                                     "{}: both ends are on body '{}'", who, e.a.body);
                     nonnegative(e.stiffness, who, "stiffness");
                     nonnegative(e.damping, who, "damping");
                     nonnegative(e.free_length, who, "free_length");
                   },
                   [&](TorsionalSpringDamper& e) {
                     nonnegative(e.stiffness, who, "stiffness");
                     nonnegative(e.damping, who, "damping");
                     require(std::isfinite(e.rest_angle), who + ": rest_angle is not finite");
                     if (!e.joint.empty()) {
                       require(e.body_a.empty() && e.body_b.empty(),
                               who + ": give either a joint or two bodies, not both");
                       e.joint_index = joint_at(e.joint, who);
                       e.R_AB_rest = Mat3::Identity();
                       const Joint& j = model.joints_[e.joint_index];
                       MOMENTA_REQUIRE(j.nv() == 1,
                                       "{}: joint '{}' is {} with {} degrees of "
                                       "freedom; a torsional spring needs a 1-dof joint",
                                       who, j.name, joint_type_name(j.type), j.nv());
                     } else {
                       require(!e.body_a.empty() && !e.body_b.empty(),
                               who + ": give a joint, or two bodies body_a and body_b");
                       e.body_a_index = body_at(e.body_a, who);
                       e.body_b_index = body_at(e.body_b, who);
                       MOMENTA_REQUIRE(e.body_a_index != e.body_b_index,
                                       "{}: both ends are on body '{}'", who, e.body_a);
                       e.R_AB_rest =
                           R_WB_initial[e.body_a_index].transpose() * R_WB_initial[e.body_b_index];
                     }
                   },
                   [&](JointFriction& e) {
                     e.joint_index = joint_at(e.joint, who);
                     nonnegative(e.viscous, who, "viscous");
                   },
                   [&](AppliedForce& e) {
                     e.at.body_index = body_at(e.at.body, who);
                     require(e.at.body_index != 0, who + ": a load on the world does nothing");
                     MOMENTA_REQUIRE(e.at.p_BoP_B.allFinite() && e.vector.allFinite(),
                                     "{}: point or vector {} is not finite", who,
                                     vec_str(e.vector));
                     if (!e.signal.empty()) e.signal_index = find_signal(e.signal, who);
                   },
                   [&](AppliedTorque& e) {
                     e.body_index = body_at(e.body, who);
                     require(e.body_index != 0, who + ": a load on the world does nothing");
                     MOMENTA_REQUIRE(e.vector.allFinite(), "{}: vector {} is not finite", who,
                                     vec_str(e.vector));
                     if (!e.signal.empty()) e.signal_index = find_signal(e.signal, who);
                   }},
        element);
    model.force_elements_.push_back(std::move(element));
  }
  model.signals_ = signals_;
  return model;
}

}  // namespace momenta::model
