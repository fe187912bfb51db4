// Writing models out (io/model_export.hpp): every example model, written as MJCF and read back by
// momenta's MJCF reader, has the same bodies with the same masses, the same frames in the world
// and inertias where it is drawn, and the same mass matrix there; the tree examples likewise
// through URDF (centres of mass and inertias: URDF's link frames are the joints' child frames).
// What a format cannot keep is refused, naming it.

#include "momenta/io/model_export.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/io/mjcf_file.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/io/urdf_file.hpp"
#include "momenta/simulate/state_at.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::io::export_test {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> example_models() {
  std::vector<fs::path> paths;
  for (const char* folder : {"/examples", "/examples/constraints"}) {
    for (const auto& entry : fs::directory_iterator(test::source_dir() + folder)) {
      if (entry.path().extension() == ".yaml") paths.push_back(entry.path());
    }
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

std::vector<Transform> world_poses(const model::Model& model, const VecX& q) {
  dynamics::Data data(model);
  dynamics::forward_kinematics(model, data, q);
  return data.X_WB;
}

double relative(const auto& a, const auto& b) {
  EXPECT_TRUE(a.allFinite() && b.allFinite());
  return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

// The largest relative difference between the bodies of `original` drawn at q and those of the
// same name in `back` at its initial configuration: masses, centres of mass and inertias in the
// world, and (same_frames) the bodies' frames.
double body_difference(const model::Model& original, const VecX& q, const model::Model& back,
                       bool same_frames) {
  const std::vector<Transform> X = world_poses(original, q),
                               Y = world_poses(back, back.initial_q());
  double worst = 0.0;
  for (std::size_t b = 1; b < original.bodies().size(); ++b) {
    const model::Body& body = original.bodies()[b];
    const int k = back.body_index(body.name);
    EXPECT_GE(k, 0) << body.name;
    if (k < 0) continue;
    const inertia::MassProperties& m = body.mass_properties;
    const inertia::MassProperties& n = back.bodies()[static_cast<std::size_t>(k)].mass_properties;
    const Transform& A = X[b];
    const Transform& B = Y[static_cast<std::size_t>(k)];
    worst = std::max(worst, std::abs(m.mass() - n.mass()) / std::max(1.0, m.mass()));
    worst = std::max(worst, relative(B.apply(n.center_of_mass()), A.apply(m.center_of_mass())));
    const Mat3 I_W = A.R * m.inertia_about_com() * A.R.transpose();
    const Mat3 J_W = B.R * n.inertia_about_com() * B.R.transpose();
    worst = std::max(worst, relative(J_W, I_W));
    if (same_frames) worst = std::max({worst, relative(B.R, A.R), relative(B.p, A.p)});
  }
  return worst;
}

// Whether `written` lists contact `name` as not written.
bool listed_as_not_written(const ExportedModel& written, const std::string& name) {
  return std::any_of(written.not_written.begin(), written.not_written.end(),
                     [&](const std::string& l) { return l.starts_with("contact '" + name + "'"); });
}

// The contacts of `original` with ground planes that `written` does not list as lost come back in
// `back`, read by momenta's MJCF reader from MuJoCo's geoms (spheres, cylinders' rims, boxes'
// corners), each once: on the same body, of the same shape and radius, at the same point (a
// disk's axis along the same line), on the same plane, with the same friction — and nothing else
// comes back. Returns how many.
int expect_ground_contacts_come_back(const model::Model& original, const ExportedModel& written,
                                     const model::Model& back) {
  std::vector<const model::Contact*> read;
  for (const model::Constraint& constraint : back.constraints()) {
    const auto* r = std::get_if<model::Contact>(&constraint);
    EXPECT_TRUE(r != nullptr || !model::is_unilateral(constraint));
    if (r != nullptr) read.push_back(r);
  }
  int come_back = 0;
  for (const model::Constraint& constraint : original.constraints()) {
    const auto* c = std::get_if<model::Contact>(&constraint);
    if (c == nullptr || listed_as_not_written(written, c->name)) continue;
    SCOPED_TRACE(c->name);
    EXPECT_TRUE(c->on_ground());
    const auto same = std::find_if(read.begin(), read.end(), [&](const model::Contact* r) {
      return r->frame.body == c->frame.body && r->shape == c->shape &&
             (r->frame.X_BF.p - c->frame.X_BF.p).norm() < 1e-9;
    });
    if (same == read.end()) {
      ADD_FAILURE() << "not read back";
      continue;
    }
    const model::Contact& r = **same;
    EXPECT_NEAR(r.radius, c->radius, 1e-15 * c->radius);
    EXPECT_MATRIX_NEAR(r.frame.X_BF.p, c->frame.X_BF.p, 1e-15);
    if (c->shape == model::ContactShape::disk) {
      EXPECT_LT(r.frame.X_BF.R.col(2).cross(c->frame.X_BF.R.col(2)).norm(), 1e-15);
    }
    EXPECT_MATRIX_NEAR(r.plane_normal, c->plane_normal.normalized(), 1e-15);
    EXPECT_MATRIX_NEAR(r.plane_point, c->plane_point, 1e-15);
    EXPECT_EQ(r.static_friction, c->static_friction);
    read.erase(same);
    ++come_back;
  }
  EXPECT_TRUE(read.empty()) << read.size() << " more, the first " << read.front()->name;
  return come_back;
}

// v_back = P v for the MJCF written from `model`: its joints by name (a chain's by suffix), a
// ball's rate turned into the body's axes, a free joint's linear rate into the world's.
MatX velocity_map(const model::Model& model, const model::Model& back) {
  MatX P = MatX::Zero(back.nv(), model.nv());
  const std::map<model::JointType, std::vector<std::string>> suffixes = {
      {model::JointType::cylindrical, {"_angle", "_slide"}},
      {model::JointType::universal, {"_1", "_2"}},
      {model::JointType::planar, {"_x", "_y", "_angle"}}};
  for (const model::Joint& joint : model.joints()) {
    if (joint.nv() == 0) continue;
    if (const auto it = suffixes.find(joint.type); it != suffixes.end()) {
      for (int c = 0; c < joint.nv(); ++c) {
        const int k = back.joint_index(joint.name + it->second[static_cast<std::size_t>(c)]);
        P(back.joints()[static_cast<std::size_t>(k)].v_index, joint.v_index + c) = 1.0;
      }
      continue;
    }
    const model::Joint& twin =
        back.joints()[static_cast<std::size_t>(back.joint_index(joint.name))];
    if (joint.type == model::JointType::spherical) {
      P.block<3, 3>(twin.v_index, joint.v_index) = joint.X_CJ.R;
    } else if (joint.type == model::JointType::free) {
      P.block<3, 3>(twin.v_index, joint.v_index).setIdentity();
      P.block<3, 3>(twin.v_index + 3, joint.v_index + 3) = joint.X_PJ.R;
    } else {
      P(twin.v_index, joint.v_index) = 1.0;
    }
  }
  return P;
}

TEST(ModelExport, EveryExampleThroughMjcfAndBack) {
  std::set<std::string> refused;
  double worst_bodies = 0.0, worst_mass_matrix = 0.0;
  for (const fs::path& path : example_models()) {
    SCOPED_TRACE(path.string());
    const ModelFile original = read_model_file(path);
    const VecX q = simulate::state_at(original.model, 0.0, {}).q;
    ExportedModel written;
    try {
      written = write_mjcf(original, q);
    } catch (const InvalidArgument& e) {
      const std::string what = e.what();
      EXPECT_TRUE(what.find("MJCF has no equality that keeps it") != std::string::npos) << what;
      refused.insert(path.stem().string());
      continue;
    }
    const ModelFile back = parse_mjcf(written.text, path.stem().string() + ".xml");
    const double bodies = body_difference(original.model, q, back.model, true);
    EXPECT_LT(bodies, 1e-15) << written.text;
    worst_bodies = std::max(worst_bodies, bodies);
    // The same mechanism: M(q) of the original is Pᵀ M' P of the one read back, drawn there.
    const MatX P = velocity_map(original.model, back.model);
    dynamics::Data a(original.model), b(back.model);
    const MatX M = dynamics::crba(original.model, a, q);
    const MatX M_back = dynamics::crba(back.model, b, back.model.initial_q());
    const double mass_matrix = relative(MatX(P.transpose() * M_back * P), M);
    EXPECT_LT(mass_matrix, 1e-15);
    worst_mass_matrix = std::max(worst_mass_matrix, mass_matrix);
    expect_ground_contacts_come_back(original.model, written, back.model);
    // The loads MJCF does not keep are said.
    EXPECT_EQ(written.text.find("Not written") != std::string::npos, !written.not_written.empty());
  }
  std::printf("MJCF and back, %zu examples: bodies %.2e, M %.2e (relative)\n",
              example_models().size() - refused.size(), worst_bodies, worst_mass_matrix);
  // Rolling, knife edges, distance links and slider loops have no MJCF equality (contacts are
  // listed as not written).
  EXPECT_EQ(refused, (std::set<std::string>{"chaplygin_sleigh", "rod_on_rotating_shaft",
                                            "rod_on_shaft_spinning_down", "rolling_coin",
                                            "rolling_disk_on_axle"}));
}

TEST(ModelExport, TreeExamplesThroughUrdfAndBack) {
  int written_count = 0;
  for (const fs::path& path : example_models()) {
    SCOPED_TRACE(path.string());
    const ModelFile original = read_model_file(path);
    ExportedModel written;
    try {
      written = write_urdf(original);
    } catch (const InvalidArgument& e) {
      const std::string what = e.what();
      EXPECT_TRUE(what.find("URDF has no such joint") != std::string::npos ||
                  what.find("URDF describes trees") != std::string::npos)
          << what;
      continue;
    }
    ++written_count;
    const ModelFile back = parse_urdf(written.text, path.stem().string() + ".urdf");
    VecX q = VecX::Zero(original.model.nq());
    // URDF draws at q = 0 (quaternions at the identity).
    for (const model::Joint& joint : original.model.joints()) {
      if (joint.type == model::JointType::free) q[joint.q_index + 3] = 1.0;
      if (joint.type == model::JointType::spherical) q[joint.q_index] = 1.0;
    }
    VecX q_back = VecX::Zero(back.model.nq());
    for (const model::Joint& joint : back.model.joints()) {
      if (joint.type == model::JointType::free) q_back[joint.q_index + 3] = 1.0;
    }
    const std::vector<Transform> X = world_poses(original.model, q);
    const std::vector<Transform> Y = world_poses(back.model, q_back);
    for (std::size_t i = 1; i < original.model.bodies().size(); ++i) {
      const model::Body& body = original.model.bodies()[i];
      const int k = back.model.body_index(body.name);
      ASSERT_GE(k, 0) << body.name;
      const auto& m = body.mass_properties;
      const auto& n = back.model.bodies()[static_cast<std::size_t>(k)].mass_properties;
      EXPECT_LT(std::abs(m.mass() - n.mass()), 1e-15 * std::max(1.0, m.mass())) << body.name;
      EXPECT_LT(relative(Y[static_cast<std::size_t>(k)].apply(n.center_of_mass()),
                         X[i].apply(m.center_of_mass())),
                1e-15)
          << body.name;
      const Mat3 I_W = X[i].R * m.inertia_about_com() * X[i].R.transpose();
      const Mat3& R = Y[static_cast<std::size_t>(k)].R;
      EXPECT_LT(relative(Mat3(R * n.inertia_about_com() * R.transpose()), I_W), 1e-15) << body.name;
    }
    // The same mechanism: one-axis joints keep their coordinates, so M(0) agrees entry by entry
    // where every joint has them.
    const bool one_axis =
        std::all_of(original.model.joints().begin(), original.model.joints().end(),
                    [](const model::Joint& j) { return j.nv() <= 1; });
    if (one_axis && back.model.nv() == original.model.nv()) {
      dynamics::Data a(original.model), b(back.model);
      EXPECT_LT(
          relative(dynamics::crba(back.model, b, q_back), dynamics::crba(original.model, a, q)),
          1e-15);
    }
  }
  EXPECT_GE(written_count, 8);
}

// A joint's stops travel as URDF's <limit> and MJCF's range (limited) and come back as stops — on
// MJCF's coordinate, which counts from where the model is drawn — plastic: neither format has a
// restitution, so a stop's is listed as not written. A bound the joint does not have is written a
// megametre away and read back as none.
TEST(ModelExport, StopsTravelAsLimitsAndRanges) {
  const ModelFile file = parse_model_file(R"(name: stops
bodies:
  - {name: arm, shape: box, mass: 1, size: [0.1, 0.1, 0.5]}
  - {name: slider, shape: sphere, mass: 0.5, radius: 0.05}
joints:
  - {name: swing, type: revolute, parent: world, child: arm, axis: [0, 1, 0], q0: 0.2,
     limits: {lower: -0.5, upper: 1.0, restitution: 0.6}}
  - {name: reach, type: prismatic, parent: arm, child: slider, axis: [0, 0, 1],
     limits: {lower: -0.1}}
)",
                                          "stops.yaml", ".");
  const auto expect_limits = [](const ModelFile& back, const char* joint, double lower,
                                double upper) {
    const auto& limits = back.model.joint(back.model.joint_index(joint)).limits;
    ASSERT_TRUE(limits.has_value()) << joint;
    EXPECT_EQ(limits->lower, lower) << joint;
    EXPECT_EQ(limits->upper, upper) << joint;
    EXPECT_EQ(limits->restitution, 0.0) << joint;
  };
  const double none = std::numeric_limits<double>::infinity();
  const auto says_restitution = [](const ExportedModel& written) {
    return std::any_of(
        written.not_written.begin(), written.not_written.end(), [](const std::string& s) {
          return s.find("the restitution 0.6 of joint 'swing''s stops") != std::string::npos;
        });
  };

  const ExportedModel urdf = write_urdf(file);
  EXPECT_NE(urdf.text.find("<joint name=\"swing\" type=\"revolute\">"), std::string::npos);
  EXPECT_TRUE(says_restitution(urdf)) << urdf.text;
  const ModelFile from_urdf = parse_urdf(urdf.text, "stops.urdf");
  expect_limits(from_urdf, "swing", -0.5, 1.0);
  expect_limits(from_urdf, "reach", -0.1, none);

  const ExportedModel mjcf = write_mjcf(file, file.model.initial_q());
  EXPECT_TRUE(says_restitution(mjcf)) << mjcf.text;
  const ModelFile from_mjcf = parse_mjcf(mjcf.text, "stops.xml");
  expect_limits(from_mjcf, "swing", -0.5 - 0.2, 1.0 - 0.2);  // drawn at 0.2: q' = q − 0.2
  expect_limits(from_mjcf, "reach", -0.1, none);
}

// The initial velocities travel as the key `initial`, which reading takes as the initial state:
// the spinning top (a ball joint) and the tumbling racket (a free joint, whose speeds MuJoCo
// orders [v; ω]) come back spinning as they left.
TEST(ModelExport, InitialVelocitiesComeBackThroughTheInitialKey) {
  for (const char* name : {"heavy_top", "free_body_tennis_racket"}) {
    const ModelFile file = read_model_file(test::source_dir() + "/examples/" + name + ".yaml");
    ASSERT_GT(file.model.initial_v().norm(), 1.0) << name;
    const ExportedModel written = write_mjcf(file, file.model.initial_q());
    const ModelFile back = parse_mjcf(written.text, "written.xml");
    ASSERT_EQ(back.keyframes.size(), 1u) << name;
    EXPECT_EQ(back.keyframes[0].name, "initial");
    // (q is not compared: a ball joint's drawn tilt becomes its body's frame in MJCF, and q the
    // identity; the speeds, in the body's axes, are the same.)
    EXPECT_LT((back.model.initial_v() - file.model.initial_v()).cwiseAbs().maxCoeff(), 1e-15)
        << name;
  }
}

// MuJoCo's shapes on a floor — a tilted box, a cylinder on its side, a capsule and a sphere, with
// their own friction — read as momenta's contacts (eight corners, two rims, two end spheres, a
// sphere), written back as MuJoCo's geoms, and read again: the same contacts.
TEST(ModelExport, ContactsTravelAsMuJoCosSpheresCylindersAndBoxes) {
  const ModelFile original = parse_mjcf(R"(<mujoco model="touching">
  <worldbody>
    <geom name="floor" type="plane" size="0 0 1" pos="0 0 -0.5" friction="0.6"/>
    <body name="crate" pos="0 0 1" quat="0.95 0.2 0.15 0.05">
      <freejoint/>
      <geom name="crate" type="box" size="0.3 0.2 0.1" pos="0.01 0.02 0.03" quat="0.9 0.1 0.3 0.2"
            mass="2"/>
    </body>
    <body name="drum" pos="1 0 1">
      <freejoint/>
      <geom name="drum" type="cylinder" size="0.2 0.15" quat="0.7 0.7 0 0" friction="0.8" mass="1"/>
    </body>
    <body name="rod" pos="2 0 1">
      <freejoint/>
      <geom name="rod" type="capsule" size="0.05 0.3" mass="1"/>
      <geom name="knob" type="sphere" size="0.1" pos="0 0 0.5" mass="1" condim="1"/>
    </body>
  </worldbody>
</mujoco>
)",
                                        "touching.xml");
  ASSERT_EQ(original.model.constraints().size(), 13u);
  const ExportedModel written = write_mjcf(original, original.model.initial_q());
  EXPECT_TRUE(written.not_written.empty()) << written.not_written.front();
  const ModelFile back = parse_mjcf(written.text, "touching_back.xml");
  EXPECT_EQ(expect_ground_contacts_come_back(original.model, written, back.model), 13);
  // A box and a cylinder, named after their geoms (the drawn parts have those names); a sphere
  // each for the capsule's ends and the knob, named after its contact.
  for (const char* geom :
       {R"(name="crate_contact" type="box")", R"(name="drum_contact" type="cylinder")",
        R"(name="rod_end1_floor" type="sphere")", R"(name="rod_end2_floor" type="sphere")",
        R"(name="knob_floor" type="sphere")"}) {
    EXPECT_NE(written.text.find(geom), std::string::npos) << geom << "\n" << written.text;
  }
}

// Eight points on a body, a box's corners but for the last one's height `last_z` (m; square at
// 0.05), with a coin whose rim alone touches the ground.
ModelFile eight_points_and_a_rim(double last_z) {
  std::string corners;
  for (int k = 0; k < 8; ++k) {
    corners += fmt::format(
        "  - {{name: c{}, type: contact, body: b, point: [{}, {}, {}], friction: 0.5}}\n", k,
        (k & 1) ? 0.2 : -0.2, (k & 2) ? 0.1 : -0.1,
        k == 7    ? last_z
        : (k & 4) ? 0.05
                  : -0.05);
  }
  return parse_model_file(
      "gravity: [0, 0, -9.81]\n"
      "bodies: [{name: b, shape: box, mass: 1, size: [0.4, 0.2, 0.1], position: [0, 0, 1]},\n"
      "         {name: coin, shape: cylinder, mass: 1, radius: 0.1, length: 0.01, "
      "position: [1, 0, 1]}]\n"
      "joints:\n"
      "  - {name: free, type: free, parent: world, child: b}\n"
      "  - {name: coin_free, type: free, parent: world, child: coin}\n"
      "constraints:\n" +
          corners + "  - {name: rim, type: contact, body: coin, shape: disk, radius: 0.1}\n",
      "points.yaml", ".");
}

// Contacts MuJoCo has no geom for are listed by name, saying why: eight points one of which is a
// millimetre off the box the other seven are corners of, and a disk's rim alone. Squared, the
// eight are a box's corners: written as it, they come back.
TEST(ModelExport, ContactsWithNoMuJoCoGeomAreListedAsNotWritten) {
  const ModelFile off = eight_points_and_a_rim(0.051);
  const ExportedModel written = write_mjcf(off, off.model.initial_q());
  ASSERT_EQ(written.not_written.size(), 9u);
  for (int k = 0; k < 8; ++k) {
    const std::string& lost = written.not_written[static_cast<std::size_t>(k)];
    EXPECT_TRUE(listed_as_not_written(written, fmt::format("c{}", k))) << k;
    EXPECT_NE(lost.find("a point that is not one of eight corners of a box"), std::string::npos)
        << lost;
  }
  EXPECT_TRUE(listed_as_not_written(written, "rim"));
  EXPECT_NE(written.not_written[8].find("a disk's rim with no coaxial partner"), std::string::npos)
      << written.not_written[8];
  EXPECT_EQ(expect_ground_contacts_come_back(off.model, written,
                                             parse_mjcf(written.text, "off.xml").model),
            0);

  const ModelFile square = eight_points_and_a_rim(0.05);
  const ExportedModel box = write_mjcf(square, square.model.initial_q());
  ASSERT_EQ(box.not_written.size(), 1u);
  EXPECT_TRUE(listed_as_not_written(box, "rim"));
  EXPECT_NE(box.text.find(R"(<geom name="c" type="box" size="0.2 0.1 0.05" pos="0 0 0")"),
            std::string::npos)
      << box.text;
  EXPECT_EQ(
      expect_ground_contacts_come_back(square.model, box, parse_mjcf(box.text, "square.xml").model),
      8);
}

TEST(ModelExport, WhatAFormatCannotKeepIsRefusedByName) {
  const ModelFile coin =
      read_model_file(test::source_dir() + "/examples/constraints/rolling_coin.yaml");
  try {
    write_mjcf(coin, coin.model.initial_q());
    ADD_FAILURE() << "the rolling coin was written";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("(rolling): MJCF has no equality that keeps it"),
              std::string::npos)
        << e.what();
  }
  const ModelFile top = read_model_file(test::source_dir() + "/examples/heavy_top.yaml");
  try {
    write_urdf(top);
    ADD_FAILURE() << "the top was written as URDF";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("URDF has no such joint; write MJCF"), std::string::npos)
        << e.what();
  }
  // A loop drawn open is refused: MuJoCo would close it where it is drawn.
  const ModelFile bar = read_model_file(test::source_dir() + "/examples/constraints/four_bar.yaml");
  try {
    write_mjcf(bar, VecX::Zero(bar.model.nq()));
    ADD_FAILURE() << "the open four-bar was written";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("loop 'closure' is open by"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace momenta::io::export_test
