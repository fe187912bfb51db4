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
  const JointTraits& traits = joint_traits(j.type);
  for (int k = 0; k < j.nq(); ++k) {
    q.push_back(j.name + "." + std::string(traits.q_names[static_cast<std::size_t>(k)]));
  }
  for (int k = 0; k < j.nv(); ++k) {
    v.push_back(j.name + "." + std::string(traits.v_names[static_cast<std::size_t>(k)]));
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

ModelBuilder& ModelBuilder::add_controller(Controller controller) {
  controllers_.push_back(std::move(controller));
  return *this;
}

ModelBuilder& ModelBuilder::add_constraint(Constraint constraint) {
  constraints_.push_back(std::move(constraint));
  return *this;
}

namespace {

using Kind = ModelItemRef::Kind;

// Runs `check`, attributing any error it throws to the item (kind, name) without changing the
// exception's type: a file reader then points at the item's line.
template <class F>
void for_item(Kind kind, const std::string& name, F&& check) {
  try {
    check();
  } catch (Error& e) {
    e.about(kind, name);
    throw;
  }
}

}  // namespace

namespace detail {

// The steps of ModelBuilder::build, in order; each reads what the earlier ones left.
class ModelAssembler {
 public:
  ModelAssembler(const Vec3& gravity, const std::vector<Body>& bodies,
                 const std::vector<Joint>& joints, const std::vector<ForceElement>& elements,
                 const std::vector<Signal>& signals, const std::vector<Constraint>& constraints,
                 const std::vector<Controller>& controllers)
      : bodies_(bodies),
        joints_(joints),
        elements_(elements),
        signals_(signals),
        constraints_(constraints),
        controllers_(controllers) {
    model_.gravity_ = gravity;
  }

  Model build() {
    check_bodies();
    check_signals();
    check_joints();
    order_tree();
    place_bodies_and_joints();
    fill_state_and_constants();
    check_inertia_along_joints();
    resolve_force_elements();
    resolve_constraints();
    model_.signals_ = signals_;
    resolve_controllers();
    return std::move(model_);
  }

 private:
  // Controllers: their names resolved against the model; no signal driven twice, no name twice.
  void resolve_controllers() {
    for (const Controller& c : controllers_) {
      for_item(Kind::controller, c.name, [&] {
        ResolvedController r = resolve_controller(c, model_);
        check_controller_fits(r, model_);
        model_.controllers_.push_back(std::move(r));
      });
    }
  }

  // Bodies: unique names, physical mass properties.
  void check_bodies() {
    body_names_.push_back(kWorldBodyName);
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const Body& b = bodies_[i];
      MOMENTA_REQUIRE(!b.name.empty(), "body #{} has an empty name", i + 1);
      for_item(Kind::body, b.name, [&] {
        MOMENTA_REQUIRE(b.name != kWorldBodyName,
                        "a body may not be called '{}': that name is the ground", kWorldBodyName);
        MOMENTA_REQUIRE(body_by_name_.emplace(b.name, static_cast<int>(i)).second,
                        "two bodies are named '{}'", b.name);
        if (!is_massless(b.mass_properties)) {
          b.mass_properties.check_physical(fmt::format("body '{}'", b.name));
        }
      });
      body_names_.push_back(b.name);
    }
  }

  // Signals: unique names.
  void check_signals() {
    for (std::size_t i = 0; i < signals_.size(); ++i) {
      const std::string& name = signals_[i].name();
      MOMENTA_REQUIRE(!name.empty(), "signal #{} has an empty name", i + 1);
      for_item(Kind::signal, name, [&] {
        MOMENTA_REQUIRE(signal_by_name_.emplace(name, static_cast<int>(i)).second,
                        "two signals are named '{}'", name);
      });
      signal_names_.push_back(name);
    }
  }

  int find_signal(const std::string& name, const std::string& who) const {
    auto it = signal_by_name_.find(name);
    MOMENTA_REQUIRE(it != signal_by_name_.end(), "{}: unknown signal '{}'{}", who, name,
                    did_you_mean(name, signal_names_));
    return it->second;
  }

  std::string unknown_body(std::string_view name) const { return did_you_mean(name, body_names_); }

  // Joints: parents and children exist, one joint per body, valid geometry and parameters.
  void check_joints() {
    std::set<std::string, std::less<>> joint_names;
    joint_of_child_.assign(bodies_.size(), -1);
    for (std::size_t k = 0; k < joints_.size(); ++k) {
      const Joint& j = joints_[k];
      MOMENTA_REQUIRE(!j.name.empty(), "joint #{} has an empty name", k + 1);
      for_item(Kind::joint, j.name, [&] {
        MOMENTA_REQUIRE(joint_names.insert(j.name).second, "two joints are named '{}'", j.name);
        check_connection(j, static_cast<int>(k));
        check_joint_parameters(j);
      });
    }
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      for_item(Kind::body, bodies_[i].name, [&] {
        MOMENTA_REQUIRE(joint_of_child_[i] >= 0,
                        "body '{}' is not attached to anything: add a joint with it as the child "
                        "(type fixed to weld it)",
                        bodies_[i].name);
      });
    }
  }

  void check_connection(const Joint& j, int k) {
    const std::string who = fmt::format("joint '{}'", j.name);
    MOMENTA_REQUIRE(j.parent == kWorldBodyName || body_by_name_.count(j.parent),
                    "{}: unknown parent body '{}'{}", who, j.parent, unknown_body(j.parent));
    MOMENTA_REQUIRE(j.child != kWorldBodyName,
                    "{}: the world cannot be a child (swap parent and child)", who);
    auto child = body_by_name_.find(j.child);
    MOMENTA_REQUIRE(child != body_by_name_.end(), "{}: unknown child body '{}'{}", who, j.child,
                    unknown_body(j.child));
    MOMENTA_REQUIRE(j.child != j.parent, "{}: connects body '{}' to itself", who, j.child);
    int& carrier = joint_of_child_[child->second];
    MOMENTA_REQUIRE(carrier < 0,
                    "body '{}' is the child of two joints, '{}' and '{}': the bodies must form "
                    "a tree (closed loops are not supported)",
                    j.child, joints_[carrier].name, j.name);
    carrier = k;
  }

  void check_joint_parameters(const Joint& j) const {
    const std::string who = fmt::format("joint '{}'", j.name);
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
    MOMENTA_REQUIRE(j.armature >= 0 && std::isfinite(j.armature),
                    "{}: armature {} must be zero or positive (a rotor's reflected inertia)", who,
                    j.armature);
    if (j.limits) check_limits(j, who);
    if (j.is_prescribed()) {
      MOMENTA_REQUIRE(j.nv() > 0, "{}: a fixed joint has no motion to prescribe", who);
      MOMENTA_REQUIRE(static_cast<int>(j.prescribed_signals.size()) == j.nv(),
                      "{}: {} prescribed signals given; a {} joint needs {} (one per velocity "
                      "coordinate; model/prescribed_motion.hpp)",
                      who, j.prescribed_signals.size(), joint_type_name(t), j.nv());
    }
  }

  // Stops: on a revolute or prismatic joint that moves by forces, lower < upper (not NaN, one
  // of them finite), e ∈ [0, 1], and the initial coordinate between them.
  static void check_limits(const Joint& j, const std::string& who) {
    const JointLimits& l = *j.limits;
    MOMENTA_REQUIRE(j.type == JointType::revolute || j.type == JointType::prismatic,
                    "{}: limits are stops on one coordinate: a revolute or prismatic joint's, not "
                    "a {} joint's",
                    who, joint_type_name(j.type));
    MOMENTA_REQUIRE(!j.is_prescribed(),
                    "{}: a prescribed joint moves as its signal says; a stop cannot hold it", who);
    MOMENTA_REQUIRE(!std::isnan(l.lower) && !std::isnan(l.upper) && l.lower < l.upper &&
                        (std::isfinite(l.lower) || std::isfinite(l.upper)),
                    "{}: limits lower {} and upper {} must satisfy lower < upper, one of them "
                    "finite",
                    who, l.lower, l.upper);
    MOMENTA_REQUIRE(l.restitution >= 0.0 && l.restitution <= 1.0,
                    "{}: the stops' restitution {} is outside [0, 1] (0: plastic, 1: elastic)", who,
                    l.restitution);
    const double q0 = j.q0.size() > 0 ? j.q0[0] : 0.0;
    MOMENTA_REQUIRE(q0 >= l.lower && q0 <= l.upper,
                    "{}: the initial coordinate {} is outside its limits [{}, {}]", who, q0,
                    l.lower, l.upper);
  }

  // Topological order from the world, depth first, each body's children in the order their
  // joints were added: a file's own order, and MuJoCo's and Pinocchio's (a branch's coordinates
  // together, before the next branch's). Unreached bodies lie on a cycle.
  void order_tree() {
    std::vector<char> placed(bodies_.size(), 0);
    std::vector<std::string_view> pending{kWorldBodyName};  // bodies whose children come next
    while (!pending.empty()) {
      const std::string_view parent = pending.back();
      pending.pop_back();
      if (parent != kWorldBodyName) {
        const int b = body_by_name_.find(std::string(parent))->second;
        placed[b] = 1;
        order_.push_back(b);
      }
      // Pushed last child first, so that the first child is placed (and its subtree) first.
      for (std::size_t k = joints_.size(); k-- > 0;) {
        if (joints_[k].parent == parent) pending.push_back(joints_[k].child);
      }
    }
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      if (!placed[i]) throw_cycle(static_cast<int>(i));
    }
  }

  // Walks up from an unplaced body to show the cycle it lies on.
  [[noreturn]] void throw_cycle(int start) const {
    std::string cycle = bodies_[start].name;
    int b = start;
    for (std::size_t step = 0; step <= bodies_.size(); ++step) {
      const Joint& j = joints_[joint_of_child_[b]];
      cycle += " <- " + j.parent;
      b = body_by_name_.find(j.parent)->second;
      if (b == start) break;
    }
    InvalidArgument error(fmt::format(
        "the joints form a cycle ({}): the bodies must form a tree rooted at the world", cycle));
    error.about(Kind::joint, joints_[joint_of_child_[start]].name);
    throw error;
  }

  // Bodies and joints in model order, with their indices and coordinate offsets.
  void place_bodies_and_joints() {
    model_index_.resize(bodies_.size());
    for (std::size_t m = 0; m < order_.size(); ++m) {
      model_index_[order_[m]] = static_cast<int>(m) + 1;
    }
    Body world;
    world.name = kWorldBodyName;
    world.index = 0;
    model_.bodies_.push_back(world);
    int nq = 0, nv = 0;
    for (std::size_t m = 0; m < order_.size(); ++m) {
      const int in = order_[m];
      Joint joint = joints_[joint_of_child_[in]];
      const int child = static_cast<int>(m) + 1;
      joint.index = child - 1;
      joint.child_index = child;
      joint.parent_index = joint.parent == kWorldBodyName
                               ? 0
                               : model_index_[body_by_name_.find(joint.parent)->second];
      joint.q_index = nq;
      joint.v_index = nv;
      nq += joint.nq();
      nv += joint.nv();
      joint.prescribed_signal_indices.clear();
      for_item(Kind::joint, joint.name, [&] {
        for (const auto& s : joint.prescribed_signals) {
          joint.prescribed_signal_indices.push_back(find_signal(s, "joint '" + joint.name + "'"));
        }
      });
      Body body = bodies_[in];
      body.index = child;
      body.parent_index = joint.parent_index;
      body.joint_index = joint.index;
      model_.bodies_.push_back(std::move(body));
      model_.joints_.push_back(std::move(joint));
    }
    model_.nq_ = nq;
    model_.nv_ = nv;
  }

  // Inertias, initial state, coordinate names, constants for the algorithms.
  void fill_state_and_constants() {
    model_.inertias_.resize(model_.bodies_.size());
    model_.total_mass_ = 0.0;
    for (std::size_t b = 1; b < model_.bodies_.size(); ++b) {
      model_.inertias_[b] = model_.bodies_[b].mass_properties.spatial_inertia();
      model_.total_mass_ += model_.bodies_[b].mass_properties.mass();
    }
    model_.q0_ = neutral(model_);
    model_.v0_ = VecX::Zero(model_.nv_);
    for (const Joint& j : model_.joints_) {
      for_item(Kind::joint, j.name, [&] { set_initial_state(j); });
      for (int i = 0; i < j.nq(); ++i) model_.joint_of_q_.push_back(j.index);
      for (int i = 0; i < j.nv(); ++i) model_.joint_of_v_.push_back(j.index);
      coordinate_names(j, model_.q_names_, model_.v_names_);
      model_.has_prescribed_ = model_.has_prescribed_ || j.is_prescribed();
      model_.constants_.push_back(joint_constants(j));
    }
  }

  void set_initial_state(const Joint& j) {
    if (j.q0.size() > 0) model_.q0_.segment(j.q_index, j.nq()) = j.q0;
    if (j.v0.size() > 0) model_.v0_.segment(j.v_index, j.nv()) = j.v0;
    const int k = j.type == JointType::spherical ? 0 : (j.type == JointType::free ? 3 : -1);
    if (k >= 0 && j.q0.size() > 0) {
      const Quat r = quaternion_from_wxyz(j.q0.segment<4>(k), "joint '" + j.name + "' q0");
      model_.q0_.segment<4>(j.q_index + k) << r.w(), r.x(), r.y(), r.z();
    }
  }

  JointConstants joint_constants(const Joint& j) const {
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
    c.armature = j.armature;
    if (c.nv == 1) {
      const Mat6 S_J = joint_motion_subspace(j, model_.q0_.data() + j.q_index);
      c.S_C = j.X_CJ.act_motion(S_J.col(0));
      for (int k = 0; k < 6; ++k) {
        Vec6 e = Vec6::Zero();
        e[k] = 1.0;
        if (c.S_C == e) c.S_basis = k;
      }
      c.turns_about_axis = j.type == JointType::revolute && c.child_at_joint && c.S_basis >= 0 &&
                           c.S_basis < 3 && j.X_PJ.R == Mat3::Identity();
    }
    return c;
  }

  // Singular mass matrix: every joint whose motion is free (not prescribed) must move some
  // inertia. Composite inertia of each subtree at the neutral configuration, in its body frame;
  // the joint's block Sᵀ I S must be positive definite there. A prescribed joint's motion is
  // given, so what it carries needs no inertia along it (a massless driven turntable).
  void check_inertia_along_joints() const {
    const VecX qn = neutral(model_);
    std::vector<SpatialInertia> composite = model_.inertias_;
    for (int j = model_.num_joints() - 1; j >= 0; --j) {
      const Joint& joint = model_.joints_[j];
      if (joint.parent_index == 0) continue;
      const Transform X_PC =
          joint.X_PJ * joint_transform(joint, qn.data() + joint.q_index) * joint.X_CJ.inverse();
      composite[joint.parent_index] += composite[joint.child_index].transformed(X_PC);
    }
    for (const Joint& joint : model_.joints_) {
      if (joint.nv() == 0 || joint.is_prescribed()) continue;
      for_item(Kind::joint, joint.name,
               [&] { check_inertia_along(joint, composite[joint.child_index], qn); });
    }
  }

  static void check_inertia_along(const Joint& joint, const SpatialInertia& I, const VecX& qn) {
    MOMENTA_REQUIRE(I.mass > 0 || !I.I_O.isZero(0.0),
                    "joint '{}' carries only massless bodies (body '{}' and its subtree): its "
                    "mass matrix would be singular; give them mass, make the joint fixed, or "
                    "prescribe its motion",
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

  int body_at(const std::string& name, const std::string& who) const {
    if (name == kWorldBodyName) return 0;
    auto it = body_by_name_.find(name);
    MOMENTA_REQUIRE(it != body_by_name_.end(), "{}: unknown body '{}'{}", who, name,
                    unknown_body(name));
    return model_index_[it->second];
  }

  int joint_at(const std::string& name, const std::string& who) const {
    auto i = model_.find_joint(name);
    if (!i) {
      std::vector<std::string_view> names;
      for (const Joint& j : model_.joints_) names.push_back(j.name);
      throw InvalidArgument(
          fmt::format("{}: unknown joint '{}'{}", who, name, did_you_mean(name, names)));
    }
    return *i;
  }

  static void nonnegative(double x, const std::string& who, const char* what) {
    MOMENTA_REQUIRE(x >= 0 && std::isfinite(x), "{}: {} {} must be zero or positive", who, what, x);
  }

  // Force elements: names unique, every body, joint and signal they name resolved.
  void resolve_force_elements() {
    // Body orientations in the world at the initial configuration: the rest orientation of the
    // two-body torsional springs (the world, body 0, is the identity).
    R_WB_initial_.assign(model_.bodies_.size(), Mat3::Identity());
    for (const Joint& j : model_.joints_) {
      const Transform X_PC =
          j.X_PJ * joint_transform(j, model_.q0_.data() + j.q_index) * j.X_CJ.inverse();
      R_WB_initial_[j.child_index] = R_WB_initial_[j.parent_index] * X_PC.R;
    }
    std::set<std::string, std::less<>> element_names;
    for (ForceElement element : elements_) {
      const std::string& name = force_element_name(element);
      require(!name.empty(), "a force element has an empty name");
      for_item(Kind::force_element, name, [&] {
        MOMENTA_REQUIRE(element_names.insert(name).second, "two force elements are named '{}'",
                        name);
        std::visit([&](auto& e) { resolve(e, fmt::format("force element '{}'", name)); }, element);
      });
      model_.force_elements_.push_back(std::move(element));
    }
  }

  void resolve(LinearSpringDamper& e, const std::string& who) const {
    e.a.body_index = body_at(e.a.body, who);
    e.b.body_index = body_at(e.b.body, who);
    require(e.a.p_BoP_B.allFinite() && e.b.p_BoP_B.allFinite(),
            who + ": attachment point is not finite");
    MOMENTA_REQUIRE(e.a.body_index != e.b.body_index, "{}: both ends are on body '{}'", who,
                    e.a.body);
    nonnegative(e.stiffness, who, "stiffness");
    nonnegative(e.damping, who, "damping");
    nonnegative(e.free_length, who, "free_length");
  }

  void resolve(TorsionalSpringDamper& e, const std::string& who) const {
    nonnegative(e.stiffness, who, "stiffness");
    nonnegative(e.damping, who, "damping");
    require(std::isfinite(e.rest_angle), who + ": rest_angle is not finite");
    if (!e.joint.empty()) {
      require(e.body_a.empty() && e.body_b.empty(),
              who + ": give either a joint or two bodies, not both");
      e.joint_index = joint_at(e.joint, who);
      e.R_AB_rest = Mat3::Identity();
      const Joint& j = model_.joints_[e.joint_index];
      MOMENTA_REQUIRE(j.nv() == 1,
                      "{}: joint '{}' is {} with {} degrees of freedom; a torsional spring needs "
                      "a 1-dof joint",
                      who, j.name, joint_type_name(j.type), j.nv());
      return;
    }
    require(!e.body_a.empty() && !e.body_b.empty(),
            who + ": give a joint, or two bodies body_a and body_b");
    e.body_a_index = body_at(e.body_a, who);
    e.body_b_index = body_at(e.body_b, who);
    MOMENTA_REQUIRE(e.body_a_index != e.body_b_index, "{}: both ends are on body '{}'", who,
                    e.body_a);
    e.R_AB_rest = R_WB_initial_[e.body_a_index].transpose() * R_WB_initial_[e.body_b_index];
  }

  void resolve(JointFriction& e, const std::string& who) const {
    e.joint_index = joint_at(e.joint, who);
    nonnegative(e.viscous, who, "viscous");
  }

  void resolve(FixedTendon& e, const std::string& who) const {
    require(!e.terms.empty(), who + ": a tendon needs at least one joint");
    std::set<int> seen;
    for (TendonTerm& term : e.terms) {
      term.joint_index = joint_at(term.joint, who);
      const Joint& j = model_.joints_[term.joint_index];
      MOMENTA_REQUIRE(j.nv() == 1,
                      "{}: joint '{}' is {} with {} degrees of freedom; a tendon's joints are "
                      "1-dof",
                      who, j.name, joint_type_name(j.type), j.nv());
      MOMENTA_REQUIRE(seen.insert(term.joint_index).second, "{}: joint '{}' is listed twice", who,
                      j.name);
      MOMENTA_REQUIRE(std::isfinite(term.coefficient) && term.coefficient != 0.0,
                      "{}: joint '{}''s coefficient {} must be finite and not zero", who, j.name,
                      term.coefficient);
    }
    nonnegative(e.stiffness, who, "stiffness");
    nonnegative(e.damping, who, "damping");
    require(std::isfinite(e.offset), who + ": offset is not finite");
    require(std::isfinite(e.rest_length), who + ": rest_length is not finite");
  }

  void resolve(AppliedForce& e, const std::string& who) const {
    e.at.body_index = body_at(e.at.body, who);
    require(e.at.body_index != 0, who + ": a load on the world does nothing");
    MOMENTA_REQUIRE(e.at.p_BoP_B.allFinite() && e.vector.allFinite(),
                    "{}: point or vector {} is not finite", who, vec_str(e.vector));
    if (!e.signal.empty()) e.signal_index = find_signal(e.signal, who);
  }

  void resolve(AppliedTorque& e, const std::string& who) const {
    e.body_index = body_at(e.body, who);
    require(e.body_index != 0, who + ": a load on the world does nothing");
    MOMENTA_REQUIRE(e.vector.allFinite(), "{}: vector {} is not finite", who, vec_str(e.vector));
    if (!e.signal.empty()) e.signal_index = find_signal(e.signal, who);
  }

  // Constraints: unique names (also among force elements: both name CSV columns), known bodies
  // and joints, physical sizes.
  void resolve_constraints() {
    std::set<std::string, std::less<>> names;
    for (const ForceElement& e : model_.force_elements_) names.insert(force_element_name(e));
    for (Constraint constraint : constraints_) {
      const std::string& name = constraint_name(constraint);
      require(!name.empty(), "a constraint has an empty name");
      for_item(Kind::constraint, name, [&] {
        MOMENTA_REQUIRE(names.insert(name).second,
                        "two constraints (or a constraint and a force element) are named '{}'",
                        name);
        std::visit([&](auto& c) { resolve(c, fmt::format("constraint '{}'", name)); }, constraint);
      });
      model_.constraint_rows_ += constraint_rows(constraint);
      model_.constraints_.push_back(std::move(constraint));
    }
  }

  void resolve_frame(BodyFrame& f, const std::string& who) const {
    f.body_index = body_at(f.body, who);
    check_transform(f.X_BF, fmt::format("{}: the frame on body '{}'", who, f.body));
  }

  void resolve_pair(BodyFrame& a, BodyFrame& b, const std::string& who) const {
    resolve_frame(a, who);
    resolve_frame(b, who);
    MOMENTA_REQUIRE(a.body_index != b.body_index,
                    "{}: both ends are on body '{}'; a constraint joins two bodies", who, a.body);
  }

  void resolve(LoopClosure& c, const std::string& who) const { resolve_pair(c.a, c.b, who); }

  void resolve(DistanceLink& c, const std::string& who) const {
    resolve_pair(c.a, c.b, who);
    MOMENTA_REQUIRE(c.length > 0.0 && std::isfinite(c.length),
                    "{}: length must be positive and finite, got {} m", who, c.length);
  }

  void check_plane_normal(const Vec3& n, const std::string& who) const {
    check_axis(n, who + ": the plane normal");
  }

  void resolve(RollingContact& c, const std::string& who) const {
    resolve_frame(c.frame, who);
    require(c.frame.body_index != 0, who + ": the world cannot roll; name the wheel's body");
    MOMENTA_REQUIRE(c.radius > 0.0 && std::isfinite(c.radius),
                    "{}: radius must be positive and finite, got {} m", who, c.radius);
    check_plane_normal(c.plane_normal, who);
    MOMENTA_REQUIRE(c.plane_point.allFinite(), "{}: plane point {} is not finite", who,
                    vec_str(c.plane_point));
  }

  void resolve(Contact& c, const std::string& who) const {
    resolve_frame(c.frame, who);
    require(c.frame.body_index != 0, who + ": the world cannot touch the ground; name a body");
    MOMENTA_REQUIRE(c.radius >= 0.0 && std::isfinite(c.radius),
                    "{}: radius must be zero (a point) or positive and finite, got {} m", who,
                    c.radius);
    if (c.shape == model::ContactShape::disk) {
      MOMENTA_REQUIRE(c.radius > 0.0, "{}: a disk's radius must be positive, got {} m", who,
                      c.radius);
    }
    if (c.on_plane()) {
      check_plane_normal(c.plane_normal, who);
      MOMENTA_REQUIRE(c.plane_point.allFinite(), "{}: plane point {} is not finite", who,
                      vec_str(c.plane_point));
    }
    if (c.on_ground()) {
      c.other.body_index = 0;
    } else if (c.other_plane) {
      // The plane's frame in body a: z its normal, x a's x axis projected on it.
      c.other.X_BF = Transform(plane_frame(c.plane_normal.normalized()), c.plane_point);
      resolve_frame(c.other, who);
      MOMENTA_REQUIRE(c.other.body_index != c.frame.body_index,
                      "{}: the point and the plane are both on body '{}'; a contact is between "
                      "two bodies",
                      who, c.frame.body);
    } else {
      resolve_frame(c.other, who);
      MOMENTA_REQUIRE(
          c.other.body_index != c.frame.body_index,
          "{}: both {} on body '{}'; a contact is between two bodies", who,
          c.shape == model::ContactShape::disk ? "the disk and the sphere are" : "spheres are",
          c.frame.body);
      MOMENTA_REQUIRE(c.other_radius >= 0.0 && std::isfinite(c.other_radius),
                      "{}: other_radius must be zero or positive and finite, got {} m", who,
                      c.other_radius);
      MOMENTA_REQUIRE(c.radius + c.other_radius > 0.0,
                      "{}: two points cannot touch; give either sphere a radius", who);
    }
    MOMENTA_REQUIRE(c.restitution >= 0.0 && c.restitution <= 1.0,
                    "{}: restitution must be in [0, 1] (0 plastic, 1 elastic), got {}", who,
                    c.restitution);
    MOMENTA_REQUIRE(c.static_friction >= 0.0 && std::isfinite(c.static_friction),
                    "{}: the static friction coefficient must be zero or positive and finite, "
                    "got {}",
                    who, c.static_friction);
    MOMENTA_REQUIRE(c.kinetic_friction >= 0.0 && c.kinetic_friction <= c.static_friction,
                    "{}: the kinetic friction coefficient {} must be in [0, μs = {}]: sliding "
                    "friction is no greater than the friction that can hold",
                    who, c.kinetic_friction, c.static_friction);
  }

  void resolve(KnifeEdge& c, const std::string& who) const {
    resolve_frame(c.frame, who);
    require(c.frame.body_index != 0, who + ": a knife edge on the world does nothing");
    check_plane_normal(c.plane_normal, who);
  }

  void resolve(JointCoupler& c, const std::string& who) const {
    c.joint_a_index = joint_at(c.joint_a, who);
    c.joint_b_index = joint_at(c.joint_b, who);
    MOMENTA_REQUIRE(c.joint_a_index != c.joint_b_index, "{}: joint '{}' is coupled to itself", who,
                    c.joint_a);
    for (const int j : {c.joint_a_index, c.joint_b_index}) {
      const Joint& joint = model_.joints_[j];
      MOMENTA_REQUIRE(joint.nv() == 1,
                      "{}: joint '{}' is {} with {} degrees of freedom; a coupler relates two "
                      "1-dof joints (revolute or prismatic)",
                      who, joint.name, joint_type_name(joint.type), joint.nv());
    }
    MOMENTA_REQUIRE(std::isfinite(c.ratio) && c.ratio != 0.0,
                    "{}: ratio must be finite and non-zero, got {}", who, c.ratio);
    MOMENTA_REQUIRE(std::isfinite(c.offset), "{}: offset is not finite", who);
  }

  const std::vector<Body>& bodies_;
  const std::vector<Joint>& joints_;
  const std::vector<ForceElement>& elements_;
  const std::vector<Signal>& signals_;
  const std::vector<Constraint>& constraints_;
  const std::vector<Controller>& controllers_;
  Model model_;
  std::map<std::string, int, std::less<>> body_by_name_;  // index into bodies_ (input order)
  std::vector<std::string_view> body_names_;
  std::map<std::string, int, std::less<>> signal_by_name_;
  std::vector<std::string_view> signal_names_;
  std::vector<int> joint_of_child_;  // input joint carrying each input body
  std::vector<int> order_;           // input body indices in model order (after the world)
  std::vector<int> model_index_;     // model index of each input body
  std::vector<Mat3> R_WB_initial_;
};

}  // namespace detail

Model ModelBuilder::build() const {
  return detail::ModelAssembler(gravity_, bodies_, joints_, force_elements_, signals_, constraints_,
                                controllers_)
      .build();
}

}  // namespace momenta::model
