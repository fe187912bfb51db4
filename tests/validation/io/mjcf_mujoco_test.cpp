// MJCF side by side with MuJoCo itself (2.2, Debian's libmujoco-dev): MuJoCo loads the same file
// and gives, at random states, the mass matrix M(q), the bias forces C(q, v) v + g(q), the passive
// and actuator forces (joint springs, dampers, motors at random controls) and the forward
// dynamics; momenta's reading of the file must give the same to 1e-12 relative. MuJoCo's contacts
// and constraint solver are off (momenta models neither contacts nor soft equality constraints).
//
// Coordinates: each joint's are the same on both sides (a free joint's [p; quaternion w x y z],
// a ball's quaternion), and so is their order — the file's, depth first (CoordinatesAreMuJoCos
// holds every joint to MuJoCo's qpos and dof addresses, in MJCF and URDF files) — but a free
// joint's velocity is MuJoCo's [v; ω], momenta's [ω; v] (rotation first). So v_momenta = P v_mj
// for a permutation P matched by joint name, and M_mj = Pᵀ M P, every generalized force
// τ_momenta = P τ_mj.

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/contact_geometry.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/force_elements.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta/io/mjcf_file.hpp"
#include "momenta/io/model_export.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/io/urdf_file.hpp"
#include "momenta_test/scratch_dir.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta {
namespace {

// A file loaded by MuJoCo, its contacts and constraint solver off unless `with_contacts`.
struct MuJoCoModel {
  explicit MuJoCoModel(const std::string& path, bool with_contacts = false) {
    char error[1000] = "";
    m = mj_loadXML(path.c_str(), nullptr, error, sizeof(error));
    if (m != nullptr) {
      if (!with_contacts) m->opt.disableflags |= mjDSBL_CONTACT | mjDSBL_CONSTRAINT;
      d = mj_makeData(m);
    }
    message = error;
  }
  ~MuJoCoModel() {
    if (d != nullptr) mj_deleteData(d);
    if (m != nullptr) mj_deleteModel(m);
  }
  mjModel* m = nullptr;
  mjData* d = nullptr;
  std::string message;
};

// v_momenta = P v_mj, joints matched by name: a free joint's six velocities turn from MuJoCo's
// [v; ω] to [ω; v].
MatX velocity_permutation(const model::Model& model, const mjModel* m) {
  MatX P = MatX::Zero(model.nv(), model.nv());
  for (const model::Joint& joint : model.joints()) {
    if (joint.nv() == 0) continue;
    const int id = mj_name2id(m, mjOBJ_JOINT, joint.name.c_str());
    EXPECT_GE(id, 0) << joint.name;
    if (id < 0) continue;
    const int k = joint.v_index, k_mj = m->jnt_dofadr[id];
    if (joint.type == model::JointType::free) {
      P.block(k, k_mj + 3, 3, 3).setIdentity();  // ω_momenta = the last three of MuJoCo's
      P.block(k + 3, k_mj, 3, 3).setIdentity();  // v_momenta = the first three
    } else {
      P.block(k, k_mj, joint.nv(), joint.nv()).setIdentity();
    }
  }
  return P;
}

// qpos_mj from momenta's q: each joint's coordinates at MuJoCo's address (the same layout), a
// hinge's or slide's counted from its ref (MuJoCo's qpos0 there).
VecX mujoco_configuration(const model::Model& model, const mjModel* m, const VecX& q) {
  VecX qpos(m->nq);
  for (const model::Joint& joint : model.joints()) {
    if (joint.nq() == 0) continue;
    const int id = mj_name2id(m, mjOBJ_JOINT, joint.name.c_str());
    const int at = m->jnt_qposadr[id];
    qpos.segment(at, joint.nq()) = q.segment(joint.q_index, joint.nq());
    if (m->jnt_type[id] == mjJNT_HINGE || m->jnt_type[id] == mjJNT_SLIDE) qpos[at] += m->qpos0[at];
  }
  return qpos;
}

// A random state: angles in ±π, slides in ±0.1 m, quaternions uniform, positions in ±1 m.
VecX random_configuration(const model::Model& model, std::mt19937& random) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::normal_distribution<double> normal;
  VecX q(model.nq());
  for (const model::Joint& joint : model.joints()) {
    double* qj = q.data() + joint.q_index;
    const auto quaternion = [&](double* out) {
      Eigen::Vector4d w(normal(random), normal(random), normal(random), normal(random));
      w.normalize();
      for (int i = 0; i < 4; ++i) out[i] = w[i];
    };
    switch (joint.type) {
      case model::JointType::revolute:
        qj[0] = 3.14 * unit(random);
        break;
      case model::JointType::prismatic:
        qj[0] = 0.1 * unit(random);
        break;
      case model::JointType::spherical:
        quaternion(qj);
        break;
      case model::JointType::free:
        for (int i = 0; i < 3; ++i) qj[i] = unit(random);
        quaternion(qj + 3);
        break;
      default:
        break;
    }
  }
  return q;
}

double relative(const MatX& ours, const MatX& theirs) {
  EXPECT_TRUE(ours.allFinite() && theirs.allFinite());
  return (ours - theirs).cwiseAbs().maxCoeff() / std::max(1.0, theirs.cwiseAbs().maxCoeff());
}

struct Worst {
  double mass_matrix = 0, bias = 0, element_forces = 0;
  double residual = 0;   // momenta's v̇ in MuJoCo's equations of motion: their backward error
  double forward = 0;    // |v̇ − v̇_mj| / |v̇_mj|
  double condition = 0;  // the largest κ(M) met
};

Worst compare_file(const std::string& path, int samples) {
  const std::string name = std::filesystem::path(path).stem().string();
  const io::ModelFile file = io::read_mjcf_file(path);
  const model::Model& model = file.model;
  MuJoCoModel mj(path);
  EXPECT_NE(mj.m, nullptr) << mj.message;
  if (mj.m == nullptr) return {};
  EXPECT_EQ(mj.m->nq, model.nq());
  EXPECT_EQ(mj.m->nv, model.nv());
  EXPECT_EQ(mj.m->nu, static_cast<int>(model.signals().size()));
  const int nv = model.nv();
  const MatX P = velocity_permutation(model, mj.m);
  dynamics::Data data(model);
  std::mt19937 random(2024);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Worst worst;
  for (int s = 0; s < samples; ++s) {
    // The same state, applied forces and controls on both sides.
    const VecX q = random_configuration(model, random);
    VecX v_mj(nv), tau_mj(nv);
    for (int i = 0; i < nv; ++i) {
      v_mj[i] = 2.0 * unit(random);
      tau_mj[i] = 5.0 * unit(random);
    }
    // Controls by actuator: momenta's signals are named after them, in the file's order.
    std::vector<double> u(static_cast<std::size_t>(mj.m->nu));
    for (double& ui : u) ui = 10.0 * unit(random);
    for (int i = 0; i < mj.m->nu; ++i) {
      EXPECT_EQ(model.signals()[static_cast<std::size_t>(i)].name(),
                mj_id2name(mj.m, mjOBJ_ACTUATOR, i));
    }
    const VecX qpos = mujoco_configuration(model, mj.m, q);
    for (int i = 0; i < model.nq(); ++i) mj.d->qpos[i] = qpos[i];
    for (int i = 0; i < nv; ++i) {
      mj.d->qvel[i] = v_mj[i];
      mj.d->qfrc_applied[i] = tau_mj[i];
    }
    for (int i = 0; i < mj.m->nu; ++i) mj.d->ctrl[i] = u[static_cast<std::size_t>(i)];
    mj_forward(mj.m, mj.d);
    MatX M_mj(nv, nv);
    mj_fullM(mj.m, M_mj.data(), mj.d->qM);
    const VecX bias_mj = Eigen::Map<const VecX>(mj.d->qfrc_bias, nv);
    const VecX elements_mj = Eigen::Map<const VecX>(mj.d->qfrc_passive, nv) +
                             Eigen::Map<const VecX>(mj.d->qfrc_actuator, nv);
    const VecX qacc_mj = Eigen::Map<const VecX>(mj.d->qacc, nv);

    const VecX v = P * v_mj;
    const MatX M = dynamics::crba(model, data, q);
    worst.mass_matrix = std::max(worst.mass_matrix, relative(P.transpose() * M * P, M_mj));
    const VecX bias = dynamics::rnea(model, data, q, v, VecX::Zero(nv));
    worst.bias = std::max(worst.bias, relative(bias, P * bias_mj));
    // The springs, dampers and motors: joint forces plus the bodies' wrenches as joint forces.
    dynamics::forward_kinematics(model, data, q, v);
    VecX tau_elements;
    std::vector<Vec6> f_ext(static_cast<std::size_t>(model.num_bodies()));
    dynamics::force_element_forces(model, data, u, q, v, tau_elements, f_ext);
    const VecX wrenches_as_tau = bias - dynamics::rnea(model, data, q, v, VecX::Zero(nv), f_ext);
    worst.element_forces =
        std::max(worst.element_forces, relative(tau_elements + wrenches_as_tau, P * elements_mj));
    const VecX vdot = dynamics::aba(model, data, q, v, P * tau_mj + tau_elements, f_ext);
    worst.forward = std::max(worst.forward, relative(vdot, P * qacc_mj));
    // The normwise backward error (Rigal and Gaches 1967): the residual of M_mj x = f_mj at
    // momenta's x = v̇, over |M_mj| |x| + |f_mj| (max norms).
    const VecX forces_mj = tau_mj + elements_mj - bias_mj;
    const VecX x = P.transpose() * vdot;
    const double size = M_mj.cwiseAbs().rowwise().sum().maxCoeff() * x.cwiseAbs().maxCoeff() +
                        forces_mj.cwiseAbs().maxCoeff();
    worst.residual = std::max(worst.residual, (M_mj * x - forces_mj).cwiseAbs().maxCoeff() / size);
    const Eigen::SelfAdjointEigenSolver<MatX> eigen(M_mj);
    worst.condition =
        std::max(worst.condition, eigen.eigenvalues().maxCoeff() / eigen.eigenvalues().minCoeff());
  }
  std::printf(
      "%s against MuJoCo %s, %d states: M %.2e, bias %.2e, springs/dampers/motors %.2e, "
      "equations of motion %.2e, accelerations %.2e (relative; κ(M) up to %.2e)\n",
      name.c_str(), mj_versionString(), samples, worst.mass_matrix, worst.bias,
      worst.element_forces, worst.residual, worst.forward, worst.condition);
  return worst;
}

Worst compare(const std::string& name, int samples) {
  return compare_file(test::source_dir() + "/tests/data/models/mjcf/" + name + ".xml", samples);
}

// 1e-12: the issue's bound for what both sides compute directly — M, the bias and element forces,
// and momenta's accelerations put into MuJoCo's equations of motion (the backward error). The
// accelerations themselves differ by up to κ(M) times that: the humanoid's 35 g thumb and 0.14 kg
// toes beside its 70 kg trunk make κ(M) up to 2e8, and the two sides factor M differently
// (momenta's ABA, MuJoCo's sparse LᵀDL), so they are held to κ(M) · 1e-14 (measured: 1.2e-10
// at κ 2.3e8; the arm 1.5e-13 at κ 1.5e4).
constexpr double kAgreement = 1e-12;

void expect_agreement(const Worst& w, double agreement = kAgreement) {
  EXPECT_LT(w.mass_matrix, agreement);
  EXPECT_LT(w.bias, agreement);
  EXPECT_LT(w.element_forces, agreement);
  EXPECT_LT(w.residual, agreement);
  EXPECT_LT(w.forward, w.condition * agreement / 100.0);
}

TEST(MjcfMuJoCo, SevenAxisArmWithMotorsSpringsAndDampers) { expect_agreement(compare("arm7", 50)); }

TEST(MjcfMuJoCo, HumanoidOnAFloatingBase) { expect_agreement(compare("humanoid", 50)); }

// Armature — a motor's reflected rotor inertia, set on almost every actuated joint of MuJoCo
// models — on M's diagonal, in the bias (none: it is inertia alone) and in the forward dynamics:
// the arm with armature on every joint through its default class and one joint's own, and the
// humanoid with armature on every hinge.
TEST(MjcfMuJoCo, ArmatureIsMuJoCos) {
  const std::filesystem::path dir = test::make_scratch_dir("mjcf_mujoco_armature");
  const auto with_armature = [&](const std::string& name, const std::string& from,
                                 const std::string& to) {
    std::ifstream in(test::source_dir() + "/tests/data/models/mjcf/" + name + ".xml");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (std::size_t at = text.find(from); at != std::string::npos;
         at = text.find(from, at + to.size())) {
      text.replace(at, from.size(), to);
    }
    const std::filesystem::path path = dir / (name + "_armature.xml");
    std::ofstream(path) << text;
    return path.string();
  };
  const std::string arm = with_armature("arm7", "<joint ", "<joint armature=\"0.07\" ");
  const io::ModelFile read = io::read_mjcf_file(arm);
  for (const model::Joint& joint : read.model.joints()) {
    if (joint.nv() > 0) {
      EXPECT_EQ(joint.armature, 0.07) << joint.name;
    }
  }
  expect_agreement(compare_file(arm, 50));
  const std::string humanoid =
      with_armature("humanoid", "<joint name=", "<joint armature=\"0.02\" name=");
  expect_agreement(compare_file(humanoid, 50));
}

// Fixed tendons: each is momenta's FixedTendon, its length MuJoCo's ten_length (an offset from
// the joints' refs), its spring relaxed where MuJoCo's is (the springref rule, or springlength)
// and its spring and damper in the passive forces (compare_file's element forces) — on the leg
// whose tendons mix a slide with hinges, whose joints count from refs in degrees.
TEST(MjcfMuJoCo, FixedTendonsAreMuJoCos) {
  const std::string path = test::source_dir() + "/tests/data/models/mjcf/tendon_leg.xml";
  expect_agreement(compare("tendon_leg", 50));
  const io::ModelFile file = io::read_mjcf_file(path);
  const model::Model& model = file.model;
  MuJoCoModel mj(path);
  ASSERT_NE(mj.m, nullptr) << mj.message;
  ASSERT_EQ(mj.m->ntendon, 3);
  // Each tendon's length is an output column.
  ASSERT_EQ(file.outputs.size(), 3u);
  std::mt19937 random(7);
  for (int s = 0; s < 20; ++s) {
    const VecX q = random_configuration(model, random);
    const VecX qpos = mujoco_configuration(model, mj.m, q);
    for (int i = 0; i < model.nq(); ++i) mj.d->qpos[i] = qpos[i];
    mj_forward(mj.m, mj.d);
    for (int t = 0; t < mj.m->ntendon; ++t) {
      const std::string name = mj_id2name(mj.m, mjOBJ_TENDON, t);
      EXPECT_EQ(file.outputs[static_cast<std::size_t>(t)].name, name + "_length");
      const auto element =
          std::find_if(model.force_elements().begin(), model.force_elements().end(),
                       [&](const auto& e) { return model::force_element_name(e) == name; });
      ASSERT_NE(element, model.force_elements().end()) << name;
      const auto& tendon = std::get<model::FixedTendon>(*element);
      // A few products of O(1) numbers: round-off ~1e-16.
      EXPECT_NEAR(dynamics::tendon_length(model, tendon, q), mj.d->ten_length[t], 1e-14) << name;
      if (tendon.stiffness > 0.0) {
        EXPECT_NEAR(tendon.rest_length, mj.m->tendon_lengthspring[t], 1e-15) << name;
      }
    }
  }
  // momenta's own tendons written as MJCF: MuJoCo's passive forces are momenta's (the offset
  // MJCF cannot hold is said).
  const io::ModelFile yaml =
      io::read_model_file(test::source_dir() + "/tests/data/models/tendon_pendulum.yaml");
  const io::ExportedModel written = io::write_mjcf(yaml, yaml.model.initial_q());
  ASSERT_EQ(written.not_written.size(), 1u);
  EXPECT_NE(written.not_written[0].find("tendon 'cord''s offset 0.05"), std::string::npos);
  const std::filesystem::path dir = test::make_scratch_dir("mjcf_mujoco_tendons");
  std::ofstream(dir / "tendon_pendulum.xml") << written.text;
  expect_agreement(compare_file((dir / "tendon_pendulum.xml").string(), 50));
}

// A tendon equality that relates two joints is momenta's coupler: a tendon of two joints held at
// its length plus a0, and one tendon of one joint a polynomial of degree one in another. Where
// the coupler holds, MuJoCo's own equality rows (efc_pos) are zero; moved off it, they are not.
TEST(MjcfMuJoCo, TendonEqualitiesAreCouplersWhereMuJoCosHold) {
  const std::filesystem::path dir = test::make_scratch_dir("mjcf_mujoco_tendon_equality");
  const std::string path = (dir / "tendon_couplers.xml").string();
  std::ofstream(path) << R"(<mujoco>
  <compiler angle="degree"/>
  <worldbody>
    <body><joint name="a" axis="0 1 0" ref="12"/><geom size="0.1" mass="1"/>
      <body pos="0 0 -0.5"><joint name="b" axis="0 1 0" ref="-7"/><geom size="0.1" mass="1"/>
        <body pos="0 0 -0.5"><joint name="c" type="slide" axis="1 0 0" ref="0.02"/>
          <geom size="0.1" mass="1"/>
          <body pos="0 0 -0.5"><joint name="d" axis="1 0 0"/><geom size="0.1" mass="1"/>
          </body>
        </body>
      </body>
    </body>
  </worldbody>
  <tendon>
    <fixed name="pair"><joint joint="a" coef="0.8"/><joint joint="b" coef="-1.6"/></fixed>
    <fixed name="slide_only"><joint joint="c" coef="3"/></fixed>
    <fixed name="d_only"><joint joint="d" coef="-0.5"/></fixed>
  </tendon>
  <equality>
    <tendon name="held" tendon1="pair" polycoef="0.05 0 0 0 0"/>
    <tendon name="geared" tendon1="slide_only" tendon2="d_only" polycoef="0.01 2 0 0 0"/>
  </equality>
</mujoco>)";
  const io::ModelFile file = io::read_mjcf_file(path);
  const model::Model& model = file.model;
  ASSERT_EQ(model.constraints().size(), 2u);
  const auto& held = std::get<model::JointCoupler>(model.constraints()[0]);
  const auto& geared = std::get<model::JointCoupler>(model.constraints()[1]);
  MuJoCoModel mj(path);
  ASSERT_NE(mj.m, nullptr) << mj.message;
  mj.m->opt.disableflags &= ~mjDSBL_CONSTRAINT;
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const double off : {0.0, 0.01}) {
    // q_b and q_d free, q_a and q_c from the couplers (off them by `off`).
    VecX q(model.nq());
    const auto at = [&](const std::string& joint) -> double& {
      return q[model.joint(model.joint_index(joint)).q_index];
    };
    at(held.joint_b) = unit(random);
    at(geared.joint_b) = unit(random);
    at(held.joint_a) = held.ratio * at(held.joint_b) + held.offset + off;
    at(geared.joint_a) = geared.ratio * at(geared.joint_b) + geared.offset + off;
    const VecX qpos = mujoco_configuration(model, mj.m, q);
    for (int i = 0; i < model.nq(); ++i) mj.d->qpos[i] = qpos[i];
    mj_forward(mj.m, mj.d);
    int rows = 0;
    for (int r = 0; r < mj.d->nefc; ++r) {
      if (mj.d->efc_type[r] != mjCNSTR_EQUALITY) continue;
      ++rows;
      // O(1) lengths: round-off ~1e-16.
      if (off == 0.0) {
        EXPECT_NEAR(mj.d->efc_pos[r], 0.0, 1e-14) << "row " << r;
      } else {
        EXPECT_GT(std::abs(mj.d->efc_pos[r]), 1e-3) << "row " << r;
      }
    }
    EXPECT_EQ(rows, 2);
  }
}

// Mesh geoms (binary STL): a hexagonal prism turned by its geom, a cube scaled per axis, a wedge
// its file draws away from the origin, by density and by mass (exactmeshinertia="true": MuJoCo's
// legacy default weighs the prism 3.8 % light). MuJoCo keeps mesh vertices in single precision
// (mjModel.mesh_vert is float) and re-centres them there, so its masses and inertias differ from
// the solids the same float coordinates bound by up to a few 2^-24 ≈ 6e-8 per length (a mass goes
// as length³, an inertia as length⁵: up to 3e-7; measured M 2.7e-9, bias 7.7e-9): held to 1e-6.
TEST(MjcfMuJoCo, MeshGeomsWeighAsInMuJoCo) { expect_agreement(compare("mesh_arm", 50), 1e-6); }

// A state passed between the tools as a vector (a keyframe, a logged qpos, a controller's gains)
// means the same posture: every joint's coordinates start at MuJoCo's qpos address, its speeds at
// its dof address. Branched trees whose breadth-first order differs from the file's depth-first
// one: the humanoid (a floating base, bodies of several hinges), the arm, and files written here
// with branches declared out of level order, several hinges with `pos` offsets in one body, a
// `childclass` default, a free root; and a URDF, which MuJoCo reads too.
TEST(MjcfMuJoCo, CoordinatesAreMuJoCos) {
  const std::filesystem::path dir = test::make_scratch_dir("mjcf_mujoco_order");
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  };
  const std::string branched = write("branched.xml", R"(<mujoco model="branched">
  <default><default class="limb"><joint damping="0.1" axis="0 1 0"/></default></default>
  <worldbody>
    <body name="trunk" pos="0 0 1">
      <freejoint name="root"/>
      <geom type="box" size="0.1 0.2 0.3" mass="5"/>
      <body name="left" pos="0 0.3 0" childclass="limb">
        <joint name="left_x" axis="1 0 0" pos="0 0 0.05"/>
        <joint name="left_y" pos="0 0 0.05"/>
        <geom type="capsule" fromto="0 0 0 0 0 -0.4" size="0.05"/>
        <body name="left_lower" pos="0 0 -0.4">
          <joint name="left_knee"/>
          <geom type="capsule" fromto="0 0 0 0 0 -0.4" size="0.04"/>
        </body>
      </body>
      <body name="right" pos="0 -0.3 0" childclass="limb">
        <joint name="right_ball" type="ball"/>
        <geom type="capsule" fromto="0 0 0 0 0 -0.4" size="0.05"/>
        <body name="right_lower" pos="0 0 -0.4">
          <joint name="right_knee"/>
          <joint name="right_slide" type="slide" axis="0 0 1"/>
          <geom type="capsule" fromto="0 0 0 0 0 -0.4" size="0.04"/>
        </body>
      </body>
      <body name="head" pos="0 0 0.4">
        <joint name="neck" axis="0 0 1"/>
        <geom type="sphere" size="0.1" mass="1"/>
      </body>
    </body>
  </worldbody>
</mujoco>)");
  // The joints declared breadth first (both hips, then both knees); the links' tree decides.
  const std::string urdf = write("branched.urdf", R"(<robot name="branched">
  <link name="base"><inertial><mass value="5"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="left"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="right"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="left_lower"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="right_lower"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="left_hip" type="continuous"><parent link="base"/><child link="left"/><origin xyz="0 0.3 0"/><axis xyz="0 1 0"/></joint>
  <joint name="right_hip" type="continuous"><parent link="base"/><child link="right"/><origin xyz="0 -0.3 0"/><axis xyz="0 1 0"/></joint>
  <joint name="left_knee" type="continuous"><parent link="left"/><child link="left_lower"/><origin xyz="0 0 -0.4"/><axis xyz="0 1 0"/></joint>
  <joint name="right_knee" type="prismatic"><parent link="right"/><child link="right_lower"/><origin xyz="0 0 -0.4"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>)");
  const std::string models = test::source_dir() + "/tests/data/models/mjcf/";
  for (const std::string& path : {models + "humanoid.xml", models + "arm7.xml", branched, urdf}) {
    SCOPED_TRACE(path);
    const io::ModelFile file =
        path.ends_with(".urdf") ? io::read_urdf_file(path) : io::read_mjcf_file(path);
    const MuJoCoModel mj(path);
    ASSERT_NE(mj.m, nullptr) << mj.message;
    ASSERT_EQ(mj.m->nq, file.model.nq());
    ASSERT_EQ(mj.m->nv, file.model.nv());
    std::string order;
    for (const model::Joint& joint : file.model.joints()) {
      if (joint.nv() == 0) continue;
      order += joint.name + " ";
      const int id = mj_name2id(mj.m, mjOBJ_JOINT, joint.name.c_str());
      ASSERT_GE(id, 0) << joint.name;
      EXPECT_EQ(joint.q_index, mj.m->jnt_qposadr[id]) << joint.name;
      EXPECT_EQ(joint.v_index, mj.m->jnt_dofadr[id]) << joint.name;
    }
    std::printf("%s: %s\n", std::filesystem::path(path).filename().c_str(), order.c_str());
  }
}

// A keyframe is the state MuJoCo's mj_resetDataKeyframe sets: momenta's q and v from the key's
// qpos and qvel put every body where MuJoCo puts it (xpos, xmat after mj_forward) and give the
// same kinetic energy — through a hinge's and a slide's `ref` (momenta's q = qpos − ref), a free
// joint's [v; ω] (momenta's [ω; v]) and a ball's quaternion. A key without qvel is at rest, one
// without qpos is qpos0 (the drawn configuration); an unnamed key is key<i>.
TEST(MjcfMuJoCo, KeyframesAreMuJoCosStates) {
  const std::filesystem::path dir = test::make_scratch_dir("mjcf_mujoco_keys");
  const std::string path = (dir / "keyed.xml").string();
  std::ofstream(path) << R"(<mujoco model="keyed">
  <worldbody>
    <body name="trunk" pos="0 0 1" euler="10 0 30">
      <freejoint name="root"/>
      <geom type="box" size="0.1 0.2 0.3" mass="5"/>
      <body name="left" pos="0 0.3 0">
        <joint name="left_x" axis="1 0 0" ref="20" pos="0 0 0.05"/>
        <joint name="left_y" axis="0 1 0" ref="-35"/>
        <geom type="capsule" fromto="0 0 0 0 0.1 -0.4" size="0.05"/>
        <body name="left_lower" pos="0 0 -0.4">
          <joint name="left_slide" type="slide" axis="0 0.6 0.8" ref="0.1"/>
          <geom type="capsule" fromto="0 0 0 0.1 0 -0.4" size="0.04"/>
        </body>
      </body>
      <body name="right" pos="0 -0.3 0">
        <joint name="right_ball" type="ball"/>
        <geom type="capsule" fromto="0 0 0 0.1 -0.1 -0.4" size="0.05"/>
      </body>
    </body>
  </worldbody>
  <keyframe>
    <key name="crouch" time="1.5" qpos="0.1 0.2 0.8 0.5 0.5 0.5 0.5 0.5 -0.4 0.25 0.8 0.6 0 0"
         qvel="0.1 0.2 0.3 1 -2 3 0.5 -0.5 0.2 1 -1 0.5"/>
    <key qvel="0 0 0 0 0 1 0 0 0 0 0 0"/>
  </keyframe>
</mujoco>)";
  const io::ModelFile file = io::read_mjcf_file(path);
  ASSERT_EQ(file.keyframes.size(), 2u);
  EXPECT_EQ(file.keyframes[0].name, "crouch");
  EXPECT_EQ(file.keyframes[0].time, 1.5);
  EXPECT_EQ(file.keyframes[1].name, "key1");
  const MuJoCoModel mj(path);
  ASSERT_NE(mj.m, nullptr) << mj.message;
  mj.m->opt.enableflags |= mjENBL_ENERGY;
  dynamics::Data data(file.model);
  for (int k = 0; k < 2; ++k) {
    const io::Keyframe& key = file.keyframes[static_cast<std::size_t>(k)];
    SCOPED_TRACE(key.name);
    mj_resetDataKeyframe(mj.m, mj.d, k);
    mj_forward(mj.m, mj.d);
    dynamics::forward_kinematics(file.model, data, key.q);
    for (const char* body : {"trunk", "left", "left_lower", "right"}) {
      const int id = mj_name2id(mj.m, mjOBJ_BODY, body);
      const Transform& X_WB = data.X_WB[static_cast<std::size_t>(file.model.body_index(body))];
      const Vec3 p_mj(mj.d->xpos[3 * id], mj.d->xpos[3 * id + 1], mj.d->xpos[3 * id + 2]);
      const Mat3 R_mj =
          Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(mj.d->xmat + 9 * id);
      EXPECT_LT((X_WB.p - p_mj).norm(), 1e-14) << body;
      EXPECT_LT((X_WB.R - R_mj).cwiseAbs().maxCoeff(), 1e-14) << body;
    }
    const double kinetic = 0.5 * key.v.dot(dynamics::crba(file.model, data, key.q) * key.v);
    EXPECT_GT(kinetic, 0.1);
    EXPECT_NEAR(kinetic, mj.d->energy[1], 1e-13 * kinetic);
  }
  // Asked for by name, a key is the model's initial state; one the file lacks is named.
  io::ModelFileOptions options;
  options.keyframe = "crouch";
  EXPECT_EQ(io::read_model_file(path, options).model.initial_q(), file.keyframes[0].q);
  options.keyframe = "crotch";
  try {
    io::read_model_file(path, options);
    ADD_FAILURE() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("keyframe 'crotch': " + path +
                                         " has no such key (did you mean 'crouch'?); its keys: "
                                         "crouch, key1"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace momenta

namespace momenta {
namespace {

// The contacts momenta reads from an MJCF file are the ones MuJoCo finds: a sphere, a capsule, a
// cylinder lying on their sides, each sunk 1e-9 m into a tilted floor, give MuJoCo 1 + 2 + 2
// contacts — each at a point where one of momenta's contacts of that geom touches, to the depth
// (MuJoCo's point is halfway into the overlap) —, with its friction and condim.
TEST(MjcfMuJoCo, GeomsOnAPlaneTouchWhereMuJoCosDo) {
  const double sunk = 1e-9;
  // Each body placed on the slope (turned 0.2 rad about x) at (x, y) of it, `height` above it.
  const Mat3 slope = Eigen::AngleAxisd(0.2, Vec3::UnitX()).toRotationMatrix();
  const auto at = [&](double x, double y, double height) {
    const Vec3 p = slope * Vec3(x, y, height);
    return fmt::format("{:.17g} {:.17g} {:.17g}", p.x(), p.y(), p.z());
  };
  const std::string text = fmt::format(
      R"(<mujoco>
<compiler angle="radian"/>
<option gravity="0 0 -9.81"/>
<worldbody>
<geom name="floor" type="plane" size="3 3 0.1" euler="0.2 0 0" friction="0.6"/>
<body name="ball" pos="{}" euler="0.2 0 0"><freejoint/><geom name="ball" type="sphere" size="0.1"/></body>
<body name="rod" pos="{}" euler="0.2 0 0"><freejoint/>
<geom name="rod" type="capsule" fromto="0 -0.2 0 0 0.2 0" size="0.1" friction="0.9"/></body>
<body name="drum" pos="{}" euler="0.2 0 0"><freejoint/>
<geom name="drum" type="cylinder" size="0.1 0.2" euler="1.5707963267948966 0 0" condim="1" priority="1"/></body>
</worldbody>
</mujoco>)",
      at(0, 0, 0.1 - sunk), at(1, 0, 0.1 - sunk), at(-1, 0, 0.1 - sunk));
  const std::filesystem::path dir = test::make_scratch_dir("mjcf_mujoco_contacts");
  const std::string path = (dir / "on_a_slope.xml").string();
  std::ofstream(path) << text;
  MuJoCoModel mj(path, true);
  ASSERT_NE(mj.m, nullptr) << mj.message;
  mj_forward(mj.m, mj.d);
  ASSERT_EQ(mj.d->ncon, 5);

  const io::ModelFile momenta_file = io::read_mjcf_file(path);
  const model::Model& model = momenta_file.model;
  dynamics::Data data(model);
  dynamics::forward_kinematics(model, data, model.initial_q());
  std::vector<dynamics::ContactGeometry> touching;
  std::vector<const model::Contact*> which;
  for (const model::Constraint& constraint : model.constraints()) {
    const auto& c = std::get<model::Contact>(constraint);
    const dynamics::ContactGeometry g = dynamics::contact_geometry(c, data);
    if (g.gap < 0.0) {
      EXPECT_NEAR(g.gap, -sunk, 1e-15) << c.name;
      touching.push_back(g);
      which.push_back(&c);
    } else {
      EXPECT_GT(g.gap, 1e-3) << c.name;
    }
  }
  ASSERT_EQ(touching.size(), 5u);
  for (int k = 0; k < mj.d->ncon; ++k) {
    const mjContact& con = mj.d->contact[k];
    const int geom = con.geom1 == 0 ? con.geom2 : con.geom1;
    const std::string name = mj_id2name(mj.m, mjOBJ_GEOM, geom);
    const Vec3 p_mj(con.pos[0], con.pos[1], con.pos[2]);
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < touching.size(); ++i) {
      if ((touching[i].point_W - p_mj).norm() < (touching[nearest].point_W - p_mj).norm())
        nearest = i;
    }
    SCOPED_TRACE(name);
    EXPECT_EQ(which[nearest]->name.rfind(name, 0), 0u) << which[nearest]->name;
    // MuJoCo's point is halfway into the overlap: sunk / 2 from momenta's surface point.
    EXPECT_LT((touching[nearest].point_W - p_mj).norm(), sunk);
    EXPECT_NEAR(con.dist, -sunk, 1e-15);
    const double mu = which[nearest]->static_friction;
    EXPECT_EQ(con.dim, mu > 0.0 ? 3 : 1);
    if (mu > 0.0) {
      EXPECT_EQ(con.friction[0], mu);
    }
  }
}

// momenta's own contacts written as MJCF: the skidding ball's sphere on its lane, loaded by MuJoCo
// with contacts on, touches the plane once with the friction written, and reads back as the
// contact it was.
TEST(MjcfMuJoCo, ContactsWrittenAreMuJoCosContacts) {
  const io::ModelFile yaml =
      io::read_model_file(test::source_dir() + "/examples/skidding_ball.yaml");
  const io::ExportedModel written = io::write_mjcf(yaml, yaml.model.initial_q());
  const std::filesystem::path dir = test::make_scratch_dir("mjcf_mujoco_contacts_written");
  const std::string path = (dir / "skidding_ball.xml").string();
  std::ofstream(path) << written.text;
  MuJoCoModel mj(path, true);
  ASSERT_NE(mj.m, nullptr) << mj.message;
  mj_forward(mj.m, mj.d);
  ASSERT_EQ(mj.d->ncon, 1);
  const auto& lane = std::get<model::Contact>(yaml.model.constraints()[0]);
  EXPECT_NEAR(mj.d->contact[0].dist, 0.0, 1e-15);
  EXPECT_EQ(mj.d->contact[0].dim, 3);
  EXPECT_EQ(mj.d->contact[0].friction[0], lane.static_friction);
  const io::ModelFile back = io::read_mjcf_file(path);
  ASSERT_EQ(back.model.constraints().size(), 1u);
  const auto& read = std::get<model::Contact>(back.model.constraints()[0]);
  EXPECT_EQ(read.name, "lane_ground0");
  EXPECT_EQ(read.radius, lane.radius);
  EXPECT_EQ(read.static_friction, lane.static_friction);
  EXPECT_EQ(read.kinetic_friction, lane.static_friction);  // MuJoCo's one coefficient
  EXPECT_EQ(read.plane_normal, lane.plane_normal);
  EXPECT_EQ(read.plane_point, lane.plane_point);
}

}  // namespace
}  // namespace momenta
