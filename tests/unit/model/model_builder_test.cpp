// ModelBuilder: topological ordering, coordinate layout, and every validation error with a
// message that names the culprit.
#include "momenta/model/model_builder.hpp"

#include <optional>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"

namespace momenta::model {
namespace {

inertia::MassProperties unit_body() {
  return inertia::MassProperties(1.0, Vec3(0, 0, -0.1), 0.01 * Mat3::Identity());
}

Joint joint(std::string name, JointType type, std::string parent, std::string child) {
  Joint j;
  j.name = std::move(name);
  j.type = type;
  j.parent = std::move(parent);
  j.child = std::move(child);
  return j;
}

// Throws InvalidArgument whose message contains every fragment.
void expect_error(const ModelBuilder& b, std::initializer_list<const char*> fragments) {
  try {
    b.build();
    ADD_FAILURE() << "no exception";
  } catch (const InvalidArgument& e) {
    for (const char* f : fragments) {
      EXPECT_NE(std::string(e.what()).find(f), std::string::npos) << e.what() << " lacks " << f;
    }
  }
}

TEST(ModelBuilder, OrdersBodiesFromTheWorldAndLaysOutCoordinates) {
  ModelBuilder b;
  // Given leaf first: the builder sorts them.
  b.add_body("hand", unit_body()).add_body("arm", unit_body()).add_body("base", unit_body());
  b.add_joint(joint("wrist", JointType::spherical, "arm", "hand"));
  b.add_joint(joint("elbow", JointType::revolute, "base", "arm"));
  b.add_joint(joint("root", JointType::free, "world", "base"));
  const Model m = b.build();
  ASSERT_EQ(m.num_bodies(), 4);
  EXPECT_EQ(m.body(1).name, "base");
  EXPECT_EQ(m.body(3).name, "hand");
  EXPECT_EQ(m.parent(3), 2);
  EXPECT_EQ(m.joint(2).name, "wrist");
  EXPECT_EQ(m.joint(2).child_index, 3);
  EXPECT_EQ(m.nq(), 7 + 1 + 4);
  EXPECT_EQ(m.nv(), 6 + 1 + 3);
  EXPECT_EQ(m.joint(1).q_index, 7);
  EXPECT_EQ(m.joint(2).v_index, 7);
  EXPECT_EQ(m.q_name(3), "root.qw");
  EXPECT_EQ(m.v_name(3), "root.vx");
  EXPECT_EQ(m.v_name(6), "elbow.angle_rate");
  EXPECT_EQ(m.joint_of_v(8), 2);
  EXPECT_EQ(m.initial_q(), neutral(m));
  EXPECT_DOUBLE_EQ(m.total_mass(), 3.0);
  EXPECT_EQ(m.body_index("arm"), 2);
  EXPECT_THROW(m.body_index("amr"), InvalidArgument);
}

// Depth first, each body's children in the order their joints were added: a branch's coordinates
// together, as MuJoCo's qpos and Pinocchio's q lay out the same tree (the side-by-side check:
// tests/validation/io/mjcf_mujoco_test.cpp, CoordinatesAreMuJoCos). Breadth first would give
// left_hip, right_hip, neck, left_knee, right_knee.
TEST(ModelBuilder, OrdersABranchedTreeDepthFirstInTheOrderJointsWereAdded) {
  ModelBuilder b;
  for (const char* body : {"trunk", "left", "right", "head", "left_shin", "right_shin"})
    b.add_body(body, unit_body());
  b.add_joint(joint("root", JointType::free, "world", "trunk"));
  b.add_joint(joint("left_hip", JointType::revolute, "trunk", "left"));
  b.add_joint(joint("right_hip", JointType::spherical, "trunk", "right"));
  b.add_joint(joint("neck", JointType::revolute, "trunk", "head"));
  b.add_joint(joint("right_knee", JointType::revolute, "right", "right_shin"));
  b.add_joint(joint("left_knee", JointType::prismatic, "left", "left_shin"));
  const Model m = b.build();
  std::vector<std::string> order;
  for (const Joint& j : m.joints()) order.push_back(j.name);
  EXPECT_EQ(order, (std::vector<std::string>{"root", "left_hip", "left_knee", "right_hip",
                                             "right_knee", "neck"}));
  EXPECT_EQ(m.joint(2).q_index, 8);   // root 7, left_hip 1
  EXPECT_EQ(m.joint(3).q_index, 9);   // right_hip's quaternion
  EXPECT_EQ(m.joint(5).q_index, 14);  // neck after right_knee
  EXPECT_EQ(m.parent(m.body_index("right_shin")), m.body_index("right"));
}

TEST(ModelBuilder, RejectsBrokenTopology) {
  {
    ModelBuilder b;
    b.add_body("a", unit_body()).add_body("a", unit_body());
    expect_error(b, {"two bodies", "'a'"});
  }
  {
    ModelBuilder b;
    b.add_body("arm", unit_body());
    b.add_joint(joint("j", JointType::revolute, "bse", "arm"));
    b.add_body("base", unit_body());
    b.add_joint(joint("k", JointType::revolute, "world", "base"));
    expect_error(b, {"joint 'j'", "unknown parent body 'bse'", "did you mean 'base'"});
  }
  {
    ModelBuilder b;
    b.add_body("a", unit_body()).add_body("b", unit_body());
    b.add_joint(joint("ab", JointType::revolute, "a", "b"));
    b.add_joint(joint("ba", JointType::revolute, "b", "a"));
    expect_error(b, {"cycle", "a <- b"});
  }
  {
    ModelBuilder b;
    b.add_body("a", unit_body());
    b.add_joint(joint("j1", JointType::revolute, "world", "a"));
    b.add_joint(joint("j2", JointType::revolute, "world", "a"));
    expect_error(b, {"body 'a' is the child of two joints", "'j1'", "'j2'"});
  }
  {
    ModelBuilder b;
    b.add_body("floating", unit_body());
    expect_error(b, {"body 'floating' is not attached"});
  }
  {
    ModelBuilder b;
    b.add_body("a", unit_body());
    b.add_joint(joint("j", JointType::revolute, "a", "world"));
    expect_error(b, {"joint 'j'", "world cannot be a child"});
  }
  {
    ModelBuilder b;
    b.add_body("world", unit_body());
    expect_error(b, {"may not be called 'world'"});
  }
}

TEST(ModelBuilder, RejectsBadParameters) {
  {
    ModelBuilder b;
    b.add_body("a", inertia::MassProperties(-1.0, Vec3::Zero(), Mat3::Identity()));
    b.add_joint(joint("j", JointType::revolute, "world", "a"));
    EXPECT_THROW(b.build(), InvalidInertia);
  }
  {
    ModelBuilder b;
    b.add_body("a", unit_body());
    Joint j = joint("j", JointType::revolute, "world", "a");
    j.axis = Vec3(0, 0, 2);
    b.add_joint(j);
    expect_error(b, {"joint 'j' axis", "unit vector", "norm is 2"});
  }
  {
    ModelBuilder b;
    b.add_body("a", unit_body());
    Joint j = joint("j", JointType::universal, "world", "a");
    j.axis = Vec3::UnitX();
    j.axis2 = -Vec3::UnitX();
    b.add_joint(j);
    expect_error(b, {"universal axes", "parallel"});
  }
  {
    ModelBuilder b;
    b.add_body("a", unit_body());
    Joint j = joint("j", JointType::spherical, "world", "a");
    j.q0 = Eigen::Vector4d(1, 1, 0, 0);
    b.add_joint(j);
    EXPECT_THROW(b.build(), InvalidArgument);  // not a unit quaternion
  }
  {
    ModelBuilder b;
    b.add_body("a", unit_body());
    Joint j = joint("j", JointType::revolute, "world", "a");
    j.q0 = VecX::Zero(2);
    b.add_joint(j);
    expect_error(b, {"q0 has 2 values", "revolute joint has 1"});
  }
  {
    ModelBuilder b;
    b.add_body("a", unit_body());
    Joint j = joint("j", JointType::spherical, "world", "a");
    j.prescribed_signals = {"s"};  // a ball joint takes its rotation vector: three signals
    b.add_joint(j);
    expect_error(b, {"1 prescribed signals given", "spherical joint needs 3"});
  }
  {
    ModelBuilder b;
    b.add_signal(Signal("spin", ConstantSignal{1.0}));
    b.add_body("a", unit_body());
    Joint j = joint("j", JointType::revolute, "world", "a");
    j.prescribed_signals = {"spn"};
    b.add_joint(j);
    expect_error(b, {"unknown signal 'spn'", "did you mean 'spin'"});
  }
}

// A massless body is accepted inside the tree but not where it alone carries a degree of
// freedom (its mass matrix would be singular).
// Errors say which item they are about as data, whatever their type (InvalidInertia stays
// InvalidInertia), so the model-file reader points at the item's line without reading the text.
TEST(ModelBuilder, ErrorsCarryTheItemTheyAreAbout) {
  const auto item_of = [](const ModelBuilder& b) -> std::optional<ModelItemRef> {
    try {
      b.build();
    } catch (const Error& e) {
      return e.item();
    }
    ADD_FAILURE() << "built";
    return std::nullopt;
  };
  {
    ModelBuilder b;
    b.add_body("a", inertia::MassProperties(-1.0, Vec3::Zero(), Mat3::Identity()));
    b.add_joint(joint("j", JointType::revolute, "world", "a"));
    EXPECT_THROW(b.build(), InvalidInertia);
    const auto item = item_of(b);
    ASSERT_TRUE(item.has_value());
    EXPECT_EQ(item->kind, ModelItemRef::Kind::body);
    EXPECT_EQ(item->name, "a");
  }
  {
    ModelBuilder b;
    b.add_body("a", unit_body());
    Joint j = joint("j", JointType::revolute, "world", "a");
    j.axis = Vec3(0, 0, 2);
    b.add_joint(j);
    const auto item = item_of(b);
    ASSERT_TRUE(item.has_value());
    EXPECT_EQ(item->kind, ModelItemRef::Kind::joint);
    EXPECT_EQ(item->name, "j");
  }
  {
    ModelBuilder b;
    b.add_body("a", unit_body());
    b.add_joint(joint("j", JointType::revolute, "world", "a"));
    model::JointFriction friction;
    friction.name = "drag";
    friction.joint = "k";
    b.add_force_element(friction);
    const auto item = item_of(b);
    ASSERT_TRUE(item.has_value());
    EXPECT_EQ(item->kind, ModelItemRef::Kind::force_element);
    EXPECT_EQ(item->name, "drag");
  }
}

TEST(ModelBuilder, MasslessBodies) {
  {
    ModelBuilder b;
    b.add_body("gimbal", inertia::MassProperties());
    b.add_body("rotor", unit_body());
    b.add_joint(joint("outer", JointType::revolute, "world", "gimbal"));
    Joint inner = joint("inner", JointType::revolute, "gimbal", "rotor");
    inner.axis = Vec3::UnitX();
    b.add_joint(inner);
    EXPECT_NO_THROW(b.build());
  }
  {
    ModelBuilder b;
    b.add_body("tip", inertia::MassProperties());
    b.add_joint(joint("j", JointType::revolute, "world", "tip"));
    expect_error(b, {"joint 'j' carries only massless bodies", "'tip'"});
  }
  {
    // A point mass on the axis of a spherical joint has no rotational inertia.
    ModelBuilder b;
    b.add_body("point", inertia::MassProperties(1.0, Vec3::Zero(), Mat3::Zero()));
    b.add_joint(joint("ball", JointType::spherical, "world", "point"));
    expect_error(b, {"joint 'ball'", "no inertia along some of its 3 degrees of freedom"});
  }
}

TEST(ModelBuilder, ValidatesForceElements) {
  const auto base = [] {
    ModelBuilder b;
    b.add_body("a", unit_body());
    b.add_joint(joint("j", JointType::revolute, "world", "a"));
    b.add_signal(Signal("u", ConstantSignal{1.0}));
    return b;
  };
  // Elements are filled field by field: GCC 12 misreports designated initializers of structs with
  // string members (-Wmissing-field-initializers, -Wmaybe-uninitialized false positives).
  const auto spring = [](const char* b_body, double stiffness) {
    LinearSpringDamper e;
    e.name = "spring";
    e.a.body = "world";
    e.b.body = b_body;
    e.b.p_BoP_B = Vec3(0, 0, -0.1);
    e.stiffness = stiffness;
    return e;
  };
  {
    ModelBuilder b = base();
    b.add_force_element(spring("a", 100.0));
    AppliedForce push;
    push.name = "push";
    push.at.body = "a";
    push.signal = "u";
    b.add_force_element(push);
    const Model m = b.build();
    const auto& s = std::get<LinearSpringDamper>(m.force_elements()[0]);
    EXPECT_EQ(s.a.body_index, 0);
    EXPECT_EQ(s.b.body_index, 1);
    EXPECT_EQ(std::get<AppliedForce>(m.force_elements()[1]).signal_index, 0);
  }
  {
    ModelBuilder b = base();
    b.add_force_element(spring("a", -1.0));
    expect_error(b, {"force element 'spring'", "stiffness -1"});
  }
  {
    ModelBuilder b = base();
    TorsionalSpringDamper t;
    t.name = "t";
    t.joint = "k";
    b.add_force_element(t);
    expect_error(b, {"force element 't'", "unknown joint 'k'"});
  }
  {
    ModelBuilder b = base();
    JointFriction f;
    f.name = "f";
    f.joint = "j";
    f.viscous = 0.1;
    b.add_force_element(f);
    f.viscous = 0.2;
    b.add_force_element(f);
    expect_error(b, {"two force elements are named 'f'"});
  }
  {
    ModelBuilder b = base();
    AppliedTorque m;
    m.name = "m";
    m.body = "b";
    b.add_force_element(m);
    expect_error(b, {"unknown body 'b'"});
  }
}

}  // namespace
}  // namespace momenta::model
