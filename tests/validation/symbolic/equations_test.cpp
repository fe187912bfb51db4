// Symbolic equations of motion (symbolic/equations.hpp) against the numeric engine: M against
// CRBA and M v̇ + b = 0 with v̇ from forward dynamics (ABA, hybrid where joints are prescribed,
// the force elements included) at random states of every bundled example it writes and of random
// trees of every joint type; the lumped classics against their textbook forms; the generated C++
// (compiled into this test) and Python against the same numbers.

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <ginac/ginac.h>
#include <gtest/gtest.h>

#include "momenta/analysis/linearize.hpp"
#include "momenta/analysis/transfer_function.hpp"
#include "momenta/common/error.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/reactions.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/model/euler_coordinates.hpp"
#include "momenta/symbolic/equations.hpp"
#include "momenta/symbolic/linear_equations.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta_test/multibody_models.hpp"
#include "momenta_test/scratch_dir.hpp"
#include "momenta_test/tolerance.hpp"

// Generated at build time by `momenta equations --cpp` (tests/CMakeLists.txt).
#include "double_pendulum_eom.hpp"
#include "four_bar_eom.hpp"
#include "quarter_car_eom.hpp"

namespace momenta {
namespace {

using test::random_configuration;
using test::random_vector;

// The instant (q, v, v̇, u) a model is at: a random state, prescribed coordinates from their
// signals at t, v̇ from the numeric forward dynamics, u the signals that scale loads.
struct NumericInstant {
  VecX q, v, vdot, u;
  MatX M_free;     // CRBA's mass matrix on the free speeds
  VecX reactions;  // per joint: force on the child and moment about J', in the child's axes
  // With constraints: the solver's rows (φ, G, k) and multipliers λ at the state.
  VecX phi, k, lambda;
  MatX G;
};

NumericInstant numeric_instant(const model::Model& model, const symbolic::Equations& e,
                               std::mt19937& rng, double t) {
  system::MultibodySystem system(model);
  NumericInstant s;
  // Quaternions anywhere; the other coordinates within 0.05 of the initial ones (a spring along
  // a fixed line is written as ±(x_b − x_a) with the sign at the initial configuration: valid
  // while it does not pass through zero length, which ±1 m of travel in a quarter car would).
  VecX q = random_configuration(model, rng), v = random_vector(model.nv(), rng, 2.0);
  const VecX q0 = model.initial_q(), dq = random_vector(model.nq(), rng, 0.05);
  for (const model::Joint& j : model.joints()) {
    if (j.nq() != j.nv()) continue;
    for (int k = 0; k < j.nq(); ++k) q[j.q_index + k] = q0[j.q_index + k] + dq[j.q_index + k];
  }
  system.evaluate(t, q, v);
  s.q = system.evaluated_q();
  s.v = system.evaluated_v();
  s.vdot = system.data().vdot;
  if (const system::ConstraintSolver* solver = system.constraints()) {
    s.phi = solver->rows().position;
    s.G = solver->rows().G;
    s.k = solver->rows().bias;
    s.lambda = solver->multipliers();
  }
  // The joints' reactions of that motion (RNEA's backward pass with the elements' wrenches, the
  // constraint forces among them).
  const VecX vdot = s.vdot;
  dynamics::joint_reactions(model, system.data(), s.q, s.v, vdot, system.external_wrenches());
  s.reactions.resize(6 * model.num_joints());
  for (int j = 0; j < model.num_joints(); ++j) {
    const dynamics::JointReaction r =
        dynamics::joint_reaction(model, system.data(), j, model::ReactionFrame::child);
    s.reactions.segment<3>(6 * j) = r.force;
    s.reactions.segment<3>(6 * j + 3) = r.moment;
  }
  s.u.resize(static_cast<Eigen::Index>(e.input_names().size()));
  for (std::size_t k = 0; k < e.input_names().size(); ++k) {
    s.u[static_cast<Eigen::Index>(k)] =
        model.signals()[*model.find_signal(e.input_names()[k])].value(t);
  }
  dynamics::Data data(model);
  const MatX& M = dynamics::crba(model, data, s.q);
  const auto& free = e.free_speeds();
  const auto n = static_cast<Eigen::Index>(free.size());
  s.M_free.resize(n, n);
  for (Eigen::Index r = 0; r < n; ++r)
    for (Eigen::Index c = 0; c < n; ++c)
      s.M_free(r, c) = M(free[static_cast<std::size_t>(r)], free[static_cast<std::size_t>(c)]);
  return s;
}

VecX free_part(const VecX& x, const std::vector<int>& free) {
  VecX y(static_cast<Eigen::Index>(free.size()));
  for (std::size_t k = 0; k < free.size(); ++k) y[static_cast<Eigen::Index>(k)] = x[free[k]];
  return y;
}

// The constraint rows in symbols against the solver's at the same state: φ to 1e-12 m (or rad,
// or of the largest), G to 1e-12 of its largest entry, k to 1e-12 of the largest |k| and
// |G|·|v|² (its terms are velocity products).
void expect_rows_match(const symbolic::Equations& e, const NumericInstant& s) {
  VecX phi, k;
  MatX G;
  e.evaluate_constraints(s.q, s.v, s.u, phi, G, k);
  ASSERT_EQ(phi.size(), s.phi.size());
  ASSERT_EQ(G.rows(), s.G.rows());
  ASSERT_EQ(G.cols(), s.G.cols());
  EXPECT_MATRIX_NEAR(phi, s.phi, 1e-12 * std::max(1.0, s.phi.cwiseAbs().maxCoeff()));
  const double G_scale = s.G.cwiseAbs().maxCoeff();
  EXPECT_MATRIX_NEAR(G, s.G, 1e-12 * G_scale);
  const double v2 = s.v.squaredNorm();
  EXPECT_MATRIX_NEAR(k, s.k, 1e-12 * std::max(s.k.cwiseAbs().maxCoeff(), G_scale * v2));
}

// M to 1e-12 of its largest entry; the residual M v̇ + b to 1e-12 of the largest of |M v̇| and
// |b| (the terms that cancel): both sides are sums of O(10) products evaluated in double, where
// a wrong term shows at O(1). `e` is derived with its Newton–Euler form, checked with the
// numeric joint reactions.
void expect_matches_numerics(const model::Model& model, const symbolic::Equations& e, unsigned seed,
                             int states) {
  if (e.free_speeds().empty()) return;  // all motion prescribed: no equation to check
  std::mt19937 rng(seed);
  for (int k = 0; k < states; ++k) {
    const double t = 0.37 * k;
    const NumericInstant s = numeric_instant(model, e, rng, t);
    MatX M;
    VecX bias;
    e.evaluate(s.q, s.v, s.vdot, s.u, M, bias);
    const double M_scale = s.M_free.cwiseAbs().maxCoeff();
    EXPECT_MATRIX_NEAR(M, s.M_free, 1e-12 * M_scale) << "state " << k;
    const VecX Mv = M * free_part(s.vdot, e.free_speeds());
    VecX constraint_force = VecX::Zero(bias.size());
    VecX reactions = s.reactions;
    if (e.constraint_rows() > 0) {
      expect_rows_match(e, s);
      MatX G_free(s.G.rows(), bias.size());
      for (Eigen::Index c = 0; c < bias.size(); ++c)
        G_free.col(c) = s.G.col(e.free_speeds()[static_cast<std::size_t>(c)]);
      constraint_force = G_free.transpose() * s.lambda;
      reactions.conservativeResize(s.reactions.size() + s.lambda.size());
      reactions.tail(s.lambda.size()) = s.lambda;
    }
    const double scale = std::max({Mv.cwiseAbs().maxCoeff(), bias.cwiseAbs().maxCoeff(),
                                   constraint_force.cwiseAbs().maxCoeff(), 1e-300});
    EXPECT_MATRIX_NEAR(Mv + bias - constraint_force, VecX::Zero(bias.size()), 1e-12 * scale)
        << "state " << k;
    // The Newton–Euler form holds with the numeric reactions (and multipliers): each row is a sum
    // of products of the loads, accelerations and geometry (of the size of `scale` and the
    // reactions).
    const VecX residuals = e.newton_euler_residuals(s.q, s.v, s.vdot, s.u, reactions);
    const double ne_scale = std::max(scale, reactions.cwiseAbs().maxCoeff());
    EXPECT_GE(e.newton_euler_rows(), 3);
    EXPECT_MATRIX_NEAR(residuals, VecX::Zero(residuals.size()), 1e-12 * ne_scale) << "state " << k;
  }
}

std::string example(const std::string& name) {
  return std::string(MOMENTA_SOURCE_DIR) + "/examples/" + name + ".yaml";
}

TEST(SymbolicEquations, BundledExamplesEqualCrbaAndForwardDynamics) {
  for (const char* name :
       {"cruise_control", "quarter_car", "satellite_attitude", "pendulum", "compound_pendulum",
        "double_pendulum", "free_body_tennis_racket", "heavy_top", "sleeping_top", "gyroscope",
        "rotating_shaft_bent_rod", "rotor_on_bearings", "unbalanced_rotor",
        "kinematics/turntable_bead", "flexible_satellite"}) {
    SCOPED_TRACE(name);
    const io::ModelFile file = io::read_model_file(example(name));
    symbolic::EquationOptions options;
    options.newton_euler = true;
    const symbolic::Equations e = symbolic::derive_equations(file.model, options);
    expect_matches_numerics(file.model, e, 7, 3);
  }
}

// Constrained models: φ, G and k against the constraint solver's rows, M v̇ + b = G_freeᵀ λ with
// the solver's v̇ and λ, the Newton–Euler form with the joints' reactions and the multipliers —
// at random states (the equations hold off the constraint manifold too: λ and v̇ are those
// that keep the state's constraint accelerations zero).
TEST(SymbolicEquations, ConstrainedExamplesEqualTheConstraintSolver) {
  for (const char* name :
       {"constraints/four_bar", "constraints/slider_crank", "constraints/parallelogram_swing",
        "constraints/rod_on_rotating_shaft", "constraints/rolling_disk_on_axle",
        "constraints/rolling_coin", "constraints/chaplygin_sleigh", "constraints/geared_pair"}) {
    SCOPED_TRACE(name);
    const io::ModelFile file = io::read_model_file(example(name));
    symbolic::EquationOptions options;
    options.newton_euler = true;
    const symbolic::Equations e = symbolic::derive_equations(file.model, options);
    EXPECT_EQ(e.constraint_rows(), file.model.num_constraint_rows());
    expect_matches_numerics(file.model, e, 19, 3);
  }
}

TEST(SymbolicEquations, RandomTreesOfEveryJointTypeEqualCrbaAndForwardDynamics) {
  using model::JointType;
  const std::vector<std::vector<JointType>> families = {
      {JointType::revolute, JointType::prismatic, JointType::universal, JointType::fixed},
      {JointType::cylindrical, JointType::planar, JointType::revolute},
      {JointType::spherical, JointType::revolute, JointType::prismatic},
      {JointType::free, JointType::universal, JointType::spherical}};
  unsigned seed = 11;
  for (const auto& types : families) {
    SCOPED_TRACE(seed);
    const model::Model model = test::random_tree(4, seed++, types);
    symbolic::EquationOptions options;
    options.newton_euler = true;
    const symbolic::Equations e = symbolic::derive_equations(model, options);
    expect_matches_numerics(model, e, seed, 3);
  }
}

// Prescribed ball and free joints: their quaternion, ω and ω̇ (and position) are known functions
// of time, taken from the state; the bodies they carry get their equations. A pendulum hung from
// a body tumbling on a ball joint by three sines of its rotation vector, and a universal-joint
// arm on a body moved by a prescribed free joint.
TEST(SymbolicEquations, PrescribedBallAndFreeJointsMoveTheBodiesTheyCarry) {
  const std::string signals =
      "inputs:\n"
      "  - {name: ax, type: sine, amplitude: 0.7, frequency: 0.2, phase: 0.1, offset: 0.2}\n"
      "  - {name: ay, type: sine, amplitude: -0.5, frequency: 0.35, offset: 0.1}\n"
      "  - {name: az, type: sine, amplitude: 1.2, frequency: 0.15, phase: 0.5, offset: -0.3}\n";
  const std::string bodies =
      "bodies:\n"
      "  - {name: frame, mass: 2, inertia: [0.3, 0.5, 0.7], com: [0.1, 0, 0.05]}\n"
      "  - {name: arm, mass: 0.8, inertia: [0.02, 0.03, 0.01], com: [0, 0, -0.3]}\n";
  const std::string ball = "name: tumbling pendulum\n" + signals + bodies +
                           "joints:\n"
                           "  - {name: gimbal, type: ball, parent: world, child: frame, "
                           "prescribed: [ax, ay, az]}\n"
                           "  - {name: hinge, type: revolute, parent: frame, child: arm, "
                           "axis: [0, 1, 0], in_parent: {position: [0.2, 0.1, 0]}}\n";
  const std::string free = "name: carried arm\n" + signals + bodies +
                           "joints:\n"
                           "  - {name: carrier, type: free, parent: world, child: frame, "
                           "prescribed: [ax, ay, az, az, ax, ay]}\n"
                           "  - {name: joint, type: universal, parent: frame, child: arm, "
                           "axis: [1, 0, 0], axis2: [0, 1, 0]}\n";
  const std::vector<std::pair<std::string, std::size_t>> models = {{ball, 1}, {free, 2}};
  for (const auto& [text, free_speeds] : models) {
    const io::ModelFile file = io::parse_model_file(text, "prescribed.yaml", ".");
    SCOPED_TRACE(file.name);
    symbolic::EquationOptions options;
    options.newton_euler = true;
    const symbolic::Equations e = symbolic::derive_equations(file.model, options);
    EXPECT_EQ(e.free_speeds().size(), free_speeds);
    expect_matches_numerics(file.model, e, 29, 3);
  }
}

// The Newton–Euler rows in principal axes: a skewed plate on a shaft (products of inertia in its
// own axes) and random bodies get their rows in e1, e2, e3 (named in the group), Euler's
// equations with the principal moments, and still balance with the numeric reactions; the
// shaft, whose axes are principal, keeps them. With the inertia's entries as symbols the
// rotated Ī is exact too.
TEST(SymbolicEquations, NewtonEulerRowsInPrincipalAxes) {
  const auto groups_in_principal_axes = [](const symbolic::Equations& e) {
    int count = 0;
    for (int r = 0; r < e.newton_euler_rows(); ++r)
      count += e.newton_euler_group(r).find("(principal axes e1 = ") != std::string::npos;
    return count;
  };
  const std::string plate =
      "name: skewed plate\n"
      "bodies:\n"
      "  - {name: shaft, mass: 1, inertia: [0.01, 0.01, 0.002]}\n"
      "  - {name: plate, mass: 3, com: [0.02, 0, 0.1],\n"
      "     inertia: [[0.3, -0.05, 0.01], [-0.05, 0.4, 0.02], [0.01, 0.02, 0.6]]}\n"
      "joints:\n"
      "  - {name: bearing, type: revolute, parent: world, child: shaft, axis: [0, 0, 1]}\n"
      "  - {name: weld, type: fixed, parent: shaft, child: plate}\n";
  const io::ModelFile file = io::parse_model_file(plate, "plate.yaml", ".");
  symbolic::EquationOptions options;
  options.newton_euler = true;
  options.principal_axes = true;
  const symbolic::Equations e = symbolic::derive_equations(file.model, options);
  EXPECT_EQ(groups_in_principal_axes(e), 6);  // the plate's six rows
  expect_matches_numerics(file.model, e, 31, 3);
  options.all_symbols = true;
  const symbolic::Equations with_symbols = symbolic::derive_equations(file.model, options);
  EXPECT_EQ(groups_in_principal_axes(with_symbols), 6);
  expect_matches_numerics(file.model, with_symbols, 37, 2);
  options.all_symbols = false;
  const model::Model tree =
      test::random_tree(3, 41, {model::JointType::revolute, model::JointType::spherical});
  const symbolic::Equations random = symbolic::derive_equations(tree, options);
  EXPECT_GE(groups_in_principal_axes(random), 6);
  expect_matches_numerics(tree, random, 43, 3);
}

// Parameters as symbols evaluate to the same numbers as the numbers themselves.
TEST(SymbolicEquations, SymbolsEvaluateAtTheModelsValues) {
  const io::ModelFile file = io::read_model_file(example("double_pendulum"));
  symbolic::EquationOptions options;
  options.all_symbols = true;
  options.newton_euler = true;
  const symbolic::Equations e = symbolic::derive_equations(file.model, options);
  EXPECT_GE(e.parameters().size(), 5u);
  expect_matches_numerics(file.model, e, 3, 2);
}

// Fixed tendons: −nᵢ (k (L − rest) + c L̇) on each joint, over two hinges and a slide (the
// coefficient of the slide in rad/m), with numbers and with every parameter a symbol.
TEST(SymbolicEquations, FixedTendonsEqualTheNumericEngine) {
  const io::ModelFile file = io::read_model_file(std::string(MOMENTA_SOURCE_DIR) +
                                                 "/tests/data/models/tendon_pendulum.yaml");
  for (const bool symbols : {false, true}) {
    SCOPED_TRACE(symbols);
    symbolic::EquationOptions options;
    options.all_symbols = symbols;
    options.newton_euler = true;
    const symbolic::Equations e = symbolic::derive_equations(file.model, options);
    expect_matches_numerics(file.model, e, 29, 4);
    if (!symbols) continue;
    std::vector<std::string> names;
    for (const auto& p : e.parameters()) names.push_back(p.name);
    for (const char* name : {"k_cord", "c_cord", "rest_cord", "offset_cord", "n_cord_slide",
                             "n_cord_shoulder", "n_cord_elbow"}) {
      EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
    }
  }
}

// A textbook form and the printed equation are the same expression: both parsed by GiNaC and
// subtracted, lhs − rhs of each, the difference expands to 0.
void expect_same_equation(const std::string& printed, const std::string& expected) {
  GiNaC::parser reader;
  const auto sides = [&](const std::string& equation) {
    const auto eq = equation.find(" = ");
    return reader(equation.substr(0, eq)) - reader(equation.substr(eq + 3));
  };
  EXPECT_TRUE(GiNaC::expand(sides(printed) - sides(expected)).is_zero())
      << "printed: " << printed << "\nexpected: " << expected;
}

symbolic::Equations symbols_of_with(const std::string& name,
                                    const symbolic::EquationOptions& options) {
  return symbolic::derive_equations(io::read_model_file(example(name)).model, options);
}

symbolic::Equations symbols_of(const std::string& name) {
  symbolic::EquationOptions options;
  options.all_symbols = true;
  return symbolic::derive_equations(io::read_model_file(example(name)).model, options);
}

TEST(SymbolicEquations, LumpedClassicsReadAsTheTextbookWritesThem) {
  // Cruise control (FPE ch. 2): m v̇ + b v = u, the engine's force u(t) on the right.
  const symbolic::Equations cruise = symbols_of("cruise_control");
  ASSERT_EQ(cruise.free_speeds().size(), 1u);
  expect_same_equation(cruise.equation(0, symbolic::Format::text),
                       "m_car*road_ddot + c_road*road_dot = u");
  // Satellite attitude: I θ̈ = T, the thrusters' couple T = F_c d being the signal.
  expect_same_equation(symbols_of("satellite_attitude").equation(0, symbolic::Format::text),
                       "I_satellite_zz*attitude_ddot = thrust");
  // Pendulum: m L² θ̈ + m g L sin θ = 0, L the bob's (positive) distance below the pivot.
  expect_same_equation(symbols_of("pendulum").equation(0, symbolic::Format::text),
                       "m_bob*L_bob^2*pivot_ddot + m_bob*g*L_bob*sin(pivot) = 0");
  // Compound pendulum (Beer & Johnston §16.2, a rod on a fixed pivot): I_O θ̈ + m g d sin θ = 0
  // with I_O = Ī + m d² (parallel axes) and d = L_rod the distance from pivot to G below it.
  expect_same_equation(symbols_of("compound_pendulum").equation(0, symbolic::Format::text),
                       "(I_rod_yy + m_rod*L_rod^2)*pivot_ddot + m_rod*g*L_rod*sin(pivot) = 0");
  // Flexible satellite (FPE ch. 2): I1 θ̈1 + b (θ̇1 − θ̇2) + k (θ1 − θ2) = Tc and
  // I2 θ̈2 + b (θ̇2 − θ̇1) + k (θ2 − θ1) = 0, the boom a torsional spring between the bodies.
  const symbolic::Equations flexible = symbols_of("flexible_satellite");
  expect_same_equation(flexible.equation(0, symbolic::Format::text),
                       "I_hub_zz*theta1_ddot + c_boom*(theta1_dot - theta2_dot) + "
                       "k_boom*(theta1 - theta2) = tc");
  expect_same_equation(flexible.equation(1, symbolic::Format::text),
                       "I_appendage_zz*theta2_ddot + c_boom*(theta2_dot - theta1_dot) + "
                       "k_boom*(theta2 - theta1) = 0");
  // Quarter car (FPE ch. 2), in numbers: the wheel and the body.
  const symbolic::Equations car =
      symbolic::derive_equations(io::read_model_file(example("quarter_car")).model);
  expect_same_equation(car.equation(0, symbolic::Format::text),
                       "20*wheel_travel_ddot + 9800*(wheel_travel_dot - body_travel_dot) + "
                       "130000*(wheel_travel - body_travel) + 1000000*(wheel_travel - road) = 0");
  expect_same_equation(car.equation(1, symbolic::Format::text),
                       "375*body_travel_ddot + 9800*(body_travel_dot - wheel_travel_dot) + "
                       "130000*(body_travel - wheel_travel) = 0");
}

// A shape's inertia in its dimensions when those are symbols: the compound pendulum (Beer &
// Johnston §16.2, a uniform rod of length L on a pivot d from its centre G) reads
// (m L²/12 + m d²) θ̈ + m g d sin θ = 0 — Ī = m L²/12, not a number; its length alone asked for
// gives 2 kg × L²/12. Asked for as a symbol itself, I_rod_yy stays one.
// The same expression up to the printed decimals: lhs − rhs of the two, expanded, evaluated with
// every symbol at 1.1, 1.2, … (angles too), is round-off of the sum of its terms' sizes (1/12
// prints as 0.08333333333333333, 17 digits: 1e-16 relative).
void expect_same_equation_to_round_off(const std::string& printed, const std::string& expected) {
  GiNaC::parser reader;
  const auto sides = [&](const std::string& equation) {
    const auto eq = equation.find(" = ");
    return reader(equation.substr(0, eq)) - reader(equation.substr(eq + 3));
  };
  const GiNaC::ex difference = GiNaC::expand(sides(printed) - sides(expected));
  GiNaC::exmap values;
  double next = 1.1;
  for (const auto& [name, symbol] : reader.get_syms()) {
    values[symbol] = next;
    next += 0.1;
  }
  const auto value = [&](const GiNaC::ex& e) {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(values))).to_double();
  };
  double size = 0.0;
  if (GiNaC::is_a<GiNaC::add>(difference)) {
    for (std::size_t k = 0; k < difference.nops(); ++k) size += std::abs(value(difference.op(k)));
  }
  const GiNaC::ex printed_lhs = GiNaC::expand(sides(printed));
  for (std::size_t k = 0; k < printed_lhs.nops(); ++k) size += std::abs(value(printed_lhs.op(k)));
  EXPECT_LE(std::abs(value(difference)), 1e-15 * size)
      << "printed: " << printed << "\nexpected: " << expected;
}

TEST(SymbolicEquations, AShapesInertiaKeepsItsDimensionsAsSymbols) {
  symbolic::EquationOptions options;
  options.newton_euler = true;
  options.symbols = {"m", "g", "L", "d"};
  options.names = {{"m_rod", "m"}, {"length_rod", "L"}, {"L_rod", "d"}};
  const model::Model rod = io::read_model_file(example("compound_pendulum")).model;
  const symbolic::Equations e = symbolic::derive_equations(rod, options);
  expect_same_equation_to_round_off(e.equation(0, symbolic::Format::text),
                                    "(m*L^2/12 + m*d^2)*pivot_ddot + m*g*d*sin(pivot) = 0");
  expect_matches_numerics(rod, e, 5, 2);
  options.symbols = {"length_rod"};
  options.names = {};
  expect_same_equation_to_round_off(
      symbolic::derive_equations(rod, options).equation(0, symbolic::Format::text),
      "(length_rod^2/6 + 1/2)*pivot_ddot + 981/100*sin(pivot) = 0");
  options.symbols = {"length_rod", "I_rod_yy"};
  expect_same_equation(symbolic::derive_equations(rod, options).equation(0, symbolic::Format::text),
                       "(I_rod_yy + 1/2)*pivot_ddot + 981/100*sin(pivot) = 0");
}

// Every standard shape of a model file, turned (ZYX 20°, 30°, 40°) and set off its body's origin
// on a ball joint, with its mass and every dimension a symbol: the equations evaluate to CRBA's
// mass matrix and the forward dynamics of the numeric engine, whose inertia the primitives give
// (checked against the textbooks' tables: tests/validation/inertia).
TEST(SymbolicEquations, EveryShapesInertiaInItsDimensionsEqualsTheNumericOne) {
  const auto dir = test::make_scratch_dir("equations_shapes");
  const std::vector<std::pair<std::string, std::string>> shapes = {
      {"slender_rod", "length: 0.8"},
      {"thin_ring", "radius: 0.3"},
      {"thin_disk", "radius: 0.3"},
      {"annulus", "inner_radius: 0.1, outer_radius: 0.3"},
      {"cylinder", "radius: 0.1, length: 0.6"},
      {"hollow_cylinder", "inner_radius: 0.05, outer_radius: 0.1, length: 0.6"},
      {"cylindrical_shell", "radius: 0.1, length: 0.6"},
      {"sphere", "radius: 0.2"},
      {"hollow_sphere", "inner_radius: 0.1, outer_radius: 0.2"},
      {"spherical_shell", "radius: 0.2"},
      {"box", "size: [0.2, 0.3, 0.5]"},
      {"thin_plate", "width: 0.4, height: 0.2"},
      {"cone", "radius: 0.1, height: 0.3"},
      {"ellipsoid", "semi_axes: [0.1, 0.2, 0.3]"},
  };
  for (const auto& [kind, sizes] : shapes) {
    SCOPED_TRACE(kind);
    const std::filesystem::path path = dir / (kind + ".yaml");
    std::ofstream(path) << "name: " << kind
                        << "\ngravity: [0, 0, -9.81]\nbodies:\n  - {name: body, shape: " << kind
                        << ", mass: 2.0, " << sizes
                        << ", position: [0.1, 0.05, -0.3], euler: {sequence: ZYX, angles_deg: "
                           "[20, 30, 40]}}\njoints:\n  - {name: ball, type: spherical, parent: "
                           "world, child: body}\n";
    const model::Model model = io::read_model_file(path).model;
    ASSERT_TRUE(model.body(1).shape.has_value());
    symbolic::EquationOptions options;
    options.newton_euler = true;
    options.symbols = {"m_body"};
    for (const auto& [key, value] : model.body(1).shape->sizes) {
      std::string name = key + "_body";
      std::replace(name.begin(), name.end(), '.', '_');
      options.symbols.push_back(name);
    }
    const symbolic::Equations e = symbolic::derive_equations(model, options);
    // Every dimension is in the equations (a symbol that cancelled would leave it a number).
    EXPECT_EQ(e.parameters().size(), options.symbols.size());
    expect_matches_numerics(model, e, 11, 2);
  }
}

// The equations of `name` with every parameter a symbol and the textbook's names for them.
symbolic::Equations textbook_symbols_of(const std::string& name,
                                        std::map<std::string, std::string> names) {
  symbolic::EquationOptions options;
  options.all_symbols = true;
  options.names = std::move(names);
  return symbolic::derive_equations(io::read_model_file(example(name)).model, options);
}

// The double pendulum in Lagrange's form as textbooks write it (θ2 relative to the upper rod;
// e.g. Greenwood, Principles of Dynamics, §6-2 with m1 at the elbow): l1 is both the upper rod's
// length and m1's distance, one symbol because the file's two values agree.
TEST(SymbolicEquations, DoublePendulumReadsAsLagrangesEquations) {
  const symbolic::Equations e = textbook_symbols_of("double_pendulum", {{"m_mass1", "m1"},
                                                                        {"m_mass2", "m2"},
                                                                        {"L_mass1", "l1"},
                                                                        {"L_lower", "l1"},
                                                                        {"L_mass2", "l2"},
                                                                        {"upper", "theta1"},
                                                                        {"lower", "theta2"}});
  // sin(θ1 + θ2) written out: GiNaC does not expand trigonometric sums.
  const std::string sin12 = "(sin(theta1)*cos(theta2) + cos(theta1)*sin(theta2))";
  expect_same_equation(e.equation(0, symbolic::Format::text),
                       "(m1 + m2)*l1^2*theta1_ddot + m2*l2^2*(theta1_ddot + theta2_ddot)"
                       " + m2*l1*l2*cos(theta2)*(2*theta1_ddot + theta2_ddot)"
                       " - m2*l1*l2*sin(theta2)*(2*theta1_dot*theta2_dot + theta2_dot^2)"
                       " + (m1 + m2)*g*l1*sin(theta1) + m2*g*l2*" +
                           sin12 + " = 0");
  expect_same_equation(e.equation(1, symbolic::Format::text),
                       "m2*l2^2*(theta1_ddot + theta2_ddot) + m2*l1*l2*cos(theta2)*theta1_ddot"
                       " + m2*l1*l2*sin(theta2)*theta1_dot^2 + m2*g*l2*" +
                           sin12 + " = 0");
  EXPECT_EQ(e.parameters().size(), 5u);  // m1, m2, l1, l2, g
}

// Beer & Johnston 18.3: the rod pinned at A to the shaft turning at ω, in the shaft's frame,
// with Ī the rod's moment about G (the same about x and y), d = L/2 from A to G, φ the shaft's
// angle, and the wire from C (at height c on the shaft; the pin A at height h) to B (at b along
// the rod from A):
//   (Ī + m d²) β̈ − (Ī + m d²) φ̇² sin β cos β − m g d sin β = λ ∂|CB|/∂β   (Gᵀλ),
// |CB|² = (c − h)² + b² − 2 (c − h) b cos β (the law of cosines), λ the wire's push.
TEST(SymbolicEquations, BeerAndJohnston18_3ReadsAsTheTextbookWritesIt) {
  const symbolic::Equations e =
      textbook_symbols_of("constraints/rod_on_rotating_shaft", {{"I_rod_xx", "I"},
                                                                {"I_rod_yy", "I"},
                                                                {"L_rod", "d"},
                                                                {"m_rod", "m"},
                                                                {"pin_A", "beta"},
                                                                {"shaft_angle", "phi"},
                                                                {"L_pin_A", "h"},
                                                                {"p_wire_BC_a_z", "c"},
                                                                {"p_wire_BC_b_z", "b"}});
  const std::string CB = "sqrt((c - h)^2 + b^2 - 2*(c - h)*b*cos(beta))";
  expect_same_equation(e.equation(0, symbolic::Format::text),
                       "(I + m*d^2)*beta_ddot - (I + m*d^2)*phi_dot^2*sin(beta)*cos(beta)"
                       " - m*g*d*sin(beta) = lambda_wire_BC_length*(c - h)*b*sin(beta)/" +
                           CB);
  expect_same_equation(e.constraint_equation(0, symbolic::Format::text), CB + " - L_wire_BC = 0");
}

// Names a person gives: shared only where the values agree; a name the model does not have is
// refused with a suggestion; θ for the angles in text and LaTeX, the symbols' names unchanged.
TEST(SymbolicEquations, GivenNamesAndGreekAngles) {
  const model::Model pendulum = io::read_model_file(example("double_pendulum")).model;
  symbolic::EquationOptions options;
  options.all_symbols = true;
  options.names = {{"m_mass1", "m"}, {"L_mass1", "m"}};  // 1 kg and 1 m: equal numbers, allowed
  EXPECT_NO_THROW(symbolic::derive_equations(pendulum, options));
  options.names = {{"m_mass1", "m"}, {"g", "m"}};  // 1 and 9.81
  EXPECT_THROW(symbolic::derive_equations(pendulum, options), InvalidArgument);
  options.names = {{"m_mas1", "m1"}};
  try {
    symbolic::derive_equations(pendulum, options);
    ADD_FAILURE() << "no error";
  } catch (const InvalidArgument& error) {
    EXPECT_NE(std::string(error.what()).find("did you mean 'm_mass1'"), std::string::npos)
        << error.what();
  }
  options.names = {};
  options.greek = true;
  options.newton_euler = true;
  const symbolic::Equations e = symbolic::derive_equations(pendulum, options);
  const std::string text = e.equation(1, symbolic::Format::text);
  EXPECT_EQ(text.rfind("L_mass2^2*m_mass2*θ\u0308\u2082 + θ\u0308\u2081*(", 0), 0u) << text;
  EXPECT_NE(text.find("sin(θ\u2082)*θ\u0307\u2081^2"), std::string::npos) << text;
  const std::string latex = e.equation(1, symbolic::Format::latex);
  EXPECT_EQ(latex.rfind("L_{\\mathrm{mass2}}^{2} m_{\\mathrm{mass2}} \\ddot{\\theta}_{2}", 0), 0u)
      << latex;
  EXPECT_EQ(e.acceleration_names()[0], "upper_ddot");  // names (code, JSON) unchanged
  expect_matches_numerics(pendulum, e, 7, 2);
}

// A planar model's Newton–Euler form has three rows per body (Beer & Johnston §16.7: ΣF_x =
// m a_Gx, ΣF_y = m a_Gy, ΣM_G = Ī α), and with the n–t option a body on a fixed pivot reads as
// §16.8 writes it: the pendulum's T − m g cos θ = m L θ̇² and −m g sin θ = m L θ̈ (R_x = 0 for a
// string; its sign: t along the motion of a positive θ, against x here). Every row holds with
// the numeric reactions and accelerations (expect_matches_numerics).
TEST(SymbolicEquations, PlanarNewtonEulerHasThreeRowsPerBody) {
  symbolic::EquationOptions options;
  options.all_symbols = true;
  options.newton_euler = true;
  for (const char* name : {"pendulum", "compound_pendulum", "double_pendulum"}) {
    const model::Model model = io::read_model_file(example(name)).model;
    const symbolic::Equations e = symbolic::derive_equations(model, options);
    EXPECT_TRUE(e.newton_euler_planar()) << name;
    EXPECT_EQ(e.newton_euler_rows(), 4 * model.num_joints()) << name;  // 3 + the joint's
    expect_matches_numerics(model, e, 11, 2);
    options.normal_tangential = true;
    const symbolic::Equations nt = symbolic::derive_equations(model, options);
    EXPECT_EQ(nt.newton_euler_rows(), 4 * model.num_joints()) << name;
    expect_matches_numerics(model, nt, 12, 2);
    options.normal_tangential = false;
  }
  options.normal_tangential = true;
  const symbolic::Equations pendulum = symbols_of_with("pendulum", options);
  ASSERT_EQ(pendulum.newton_euler_rows(), 4);
  const auto equation = [&](int row) {
    const std::string text = pendulum.newton_euler_equation(row, symbolic::Format::text);
    return text.substr(text.find(":  ") + 3);
  };
  EXPECT_EQ(pendulum.newton_euler_equation(0, symbolic::Format::text).rfind("ΣF_n = ", 0), 0u);
  expect_same_equation(equation(0), "R_pivot_z - m_bob*g*cos(pivot) = m_bob*L_bob*pivot_dot^2");
  expect_same_equation(equation(1), "-R_pivot_x - m_bob*g*sin(pivot) = m_bob*L_bob*pivot_ddot");
  // A top is not planar: six rows for its body.
  options.normal_tangential = false;
  const symbolic::Equations top = symbols_of_with("heavy_top", options);
  EXPECT_FALSE(top.newton_euler_planar());
  EXPECT_GE(top.newton_euler_rows(), 6);
}

// The heavy top in the notes' Euler angles (ZXZ: precession φ, nutation θ, spin ψ), against
// Lagrange's equations of the symmetric top (Goldstein §5.7): with A and C its moments about the
// apex (transverse, axial) and V = m g l cos θ,
//   T = ½ A (θ̇² + φ̇² sin²θ) + ½ C (ψ̇ + φ̇ cos θ)²,
//   M = [[A sin²θ + C cos²θ, 0, C cos θ], [0, A, 0], [C cos θ, 0, C]],
//   b = θ̇ (∂M/∂θ) q̇ − ½ q̇ᵀ(∂M/∂θ)q̇ e_θ − m g l sin θ e_θ  (M q̈ + b = 0),
// at random states; and the file's initial state, (0, 20°, 0) with ω_B = [0, Ω sin θ, ω3], as
// φ̇ = Ω, θ̇ = 0, ψ̇ = ω3 − Ω cos θ.
TEST(SymbolicEquations, TheHeavyTopInEulerAnglesReadsAsLagrangeWritesIt) {
  const model::Model quaternion = io::read_model_file(example("heavy_top")).model;
  const model::Model top = model::with_euler_coordinates(quaternion, "ZXZ");
  ASSERT_EQ(top.nq(), 3);
  ASSERT_EQ(top.nv(), 3);
  EXPECT_EQ(top.q_name(0), "phi.angle");
  EXPECT_EQ(top.q_name(2), "psi.angle");
  const double theta0 = 20.0 * std::numbers::pi / 180.0, omega3 = 300.0;
  const double Omega = 1.2376467625713699 / std::sin(theta0);
  EXPECT_NEAR(top.initial_q()[0], 0.0, 1e-15);
  EXPECT_NEAR(top.initial_q()[1], theta0, 1e-15);
  EXPECT_NEAR(top.initial_q()[2], 0.0, 1e-15);
  EXPECT_NEAR(top.initial_v()[0], Omega, 1e-12);
  EXPECT_NEAR(top.initial_v()[1], 0.0, 1e-12);
  EXPECT_NEAR(top.initial_v()[2], omega3 - Omega * std::cos(theta0), 1e-12);
  EXPECT_NEAR(Omega, 3.618637, 1e-6);  // the file's slow precession

  const double m = 1.0, r = 0.05, h = 0.1, g = 9.81, l = 0.75 * h;
  const double A = 0.6 * m * h * h + 0.15 * m * r * r, C = 0.3 * m * r * r;
  const symbolic::Equations e = symbolic::derive_equations(top);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(-3.0, 3.0), rate(-20.0, 20.0);
  for (int trial = 0; trial < 20; ++trial) {
    const Vec3 q(angle(random), 0.2 + std::abs(angle(random)) * 0.9, angle(random));
    const Vec3 v(rate(random), rate(random), rate(random));
    const double s = std::sin(q[1]), c = std::cos(q[1]);
    Mat3 M_expected, dM;
    M_expected << A * s * s + C * c * c, 0, C * c, 0, A, 0, C * c, 0, C;
    dM << 2 * (A - C) * s * c, 0, -C * s, 0, 0, 0, -C * s, 0, 0;
    Vec3 b_expected = v[1] * dM * v;
    b_expected[1] += -0.5 * v.dot(dM * v) - m * g * l * s;
    MatX M;
    VecX b;
    e.evaluate(q, v, VecX::Zero(3), VecX(), M, b);
    EXPECT_MATRIX_NEAR(M, M_expected, 1e-15);
    EXPECT_MATRIX_NEAR(b, b_expected, 1e-12 * (1.0 + b_expected.norm()));
  }
  // A state at the sequence's gimbal lock (θ = 0, the top upright) has no Euler rates.
  std::ifstream file(example("heavy_top"));
  std::string upright((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const std::size_t tilt = upright.find("angles_deg: [0, 20, 0]");
  ASSERT_NE(tilt, std::string::npos);
  upright.replace(tilt, 22, "angles_deg: [0, 0, 0]");
  const model::Model standing = io::parse_model_file(upright, "upright.yaml", ".").model;
  EXPECT_THROW(model::with_euler_coordinates(standing, "ZXZ"), InvalidArgument);
}

// The numeric linearization of the same model about the same point, with its inputs and outputs.
analysis::LinearModel numeric_linearization(const io::ModelFile& file, const VecX& q, const VecX& v,
                                            std::vector<std::string> inputs,
                                            std::vector<std::string> outputs) {
  analysis::LinearizationOptions options;
  options.inputs = std::move(inputs);
  options.outputs = std::move(outputs);
  options.output_specs = file.outputs;
  return analysis::linearize(file.model, {0.0, q, v}, options);
}

TEST(SymbolicLinearization, CruiseControlTransferFunctionIsOneOverMsPlusB) {
  // FPE ch. 2: V(s)/U(s) = 1/(m s + b) per unit of force; the model's force is u along the road.
  const io::ModelFile file = io::read_model_file(example("cruise_control"));
  const symbolic::Equations e = symbols_of("cruise_control");
  const VecX q = file.model.initial_q(), v = file.model.initial_v();
  const symbolic::LinearEquations l = symbolic::linearize_equations(e, file.model, 0.0, q, v);
  ASSERT_EQ(l.input_names(), std::vector<std::string>{"u"});
  const std::string G = l.transfer_function(0, 0, true, symbolic::Format::text);
  GiNaC::parser reader;
  EXPECT_TRUE(GiNaC::normal(reader(G) - reader("1/(m_car*s + c_road)")).is_zero()) << G;
  ASSERT_TRUE(l.has_state_space());
  EXPECT_TRUE(
      GiNaC::normal(reader(l.entry(symbolic::LinearMatrix::A, 1, 1, symbolic::Format::text)) +
                    reader("c_road/m_car"))
          .is_zero());
}

// G(jω) of the symbolic linearization, parameters at their values, against the numeric
// linearization's (the one `momenta response` plots) at frequencies across the model's poles.
// The numeric one's velocity and input columns are exact (central differences of quadratics) and
// its configuration columns carry the Richardson-extrapolated differences' ~1e-10 relative error
// (analysis/linearize.hpp): 1e-8 of |G| covers both.
void expect_transfer_functions_agree(const std::string& name, const std::string& input,
                                     const std::string& output, int coordinate, bool rate,
                                     const VecX& q, const VecX& v) {
  const io::ModelFile file = io::read_model_file(example(name));
  symbolic::EquationOptions options;
  options.all_symbols = true;
  const symbolic::Equations e = symbolic::derive_equations(file.model, options);
  const symbolic::LinearEquations l = symbolic::linearize_equations(e, file.model, 0.0, q, v);
  const auto& inputs = l.input_names();
  const int i = static_cast<int>(std::find(inputs.begin(), inputs.end(), input) - inputs.begin());
  const analysis::LinearModel numeric = numeric_linearization(file, q, v, {input}, {output});
  for (const double w : {0.1, 1.0, 3.7, 10.0, 55.0, 300.0}) {
    const std::complex<double> s(0.0, w);
    const std::complex<double> symbolic_G = l.transfer_function_at(i, coordinate, rate, s);
    const std::complex<double> numeric_G = analysis::evaluate(numeric.system, 0, 0, s);
    EXPECT_LE(std::abs(symbolic_G - numeric_G), 1e-8 * std::abs(numeric_G))
        << name << " at ω = " << w << ": " << symbolic_G << " vs " << numeric_G;
  }
}

TEST(SymbolicLinearization, TransferFunctionsEqualTheNumericLinearizations) {
  const io::ModelFile cruise = io::read_model_file(example("cruise_control"));
  expect_transfer_functions_agree("cruise_control", "u", "speed", 0, true, cruise.model.initial_q(),
                                  cruise.model.initial_v());
  // The quarter car from the road (a prescribed input) to the body's travel (FPE Example 2.2).
  const io::ModelFile car = io::read_model_file(example("quarter_car"));
  expect_transfer_functions_agree("quarter_car", "road", "body_y", 1, false, car.model.initial_q(),
                                  car.model.initial_v());
  // The satellite (1/(I s²) per unit torque) and the flexible satellite's two-mode plant.
  const io::ModelFile sat = io::read_model_file(example("satellite_attitude"));
  expect_transfer_functions_agree("satellite_attitude", "thrust", "theta", 0, false,
                                  sat.model.initial_q(), sat.model.initial_v());
  const io::ModelFile flexible = io::read_model_file(example("flexible_satellite"));
  expect_transfer_functions_agree("flexible_satellite", "tc", "theta2", 1, false,
                                  flexible.model.initial_q(), flexible.model.initial_v());
}

TEST(SymbolicLinearization, PendulumAndDoublePendulumStateMatricesEqualTheNumericOnes) {
  // About the bottom (and, for the pendulum, about 40° where it is not at rest: v̇0 ≠ 0 enters K).
  for (const auto& [name, angle] :
       {std::pair{"pendulum", 0.0}, {"pendulum", 0.7}, {"double_pendulum", 0.0}}) {
    const io::ModelFile file = io::read_model_file(example(name));
    symbolic::EquationOptions options;
    options.all_symbols = true;
    const symbolic::Equations e = symbolic::derive_equations(file.model, options);
    VecX q = VecX::Constant(file.model.nq(), angle), v = VecX::Zero(file.model.nv());
    const symbolic::LinearEquations l = symbolic::linearize_equations(e, file.model, 0.0, q, v);
    ASSERT_TRUE(l.has_state_space());
    const analysis::LinearModel numeric = numeric_linearization(file, q, v, {}, {});
    const MatX& A = numeric.system.A();
    ASSERT_EQ(A.rows(), l.rows(symbolic::LinearMatrix::A));
    // Parameters at their values: each entry parsed, its symbols substituted, evaluated.
    GiNaC::parser reader;
    GiNaC::exmap values;
    for (const symbolic::Parameter& p : e.parameters())
      values[reader(p.name)] = GiNaC::numeric(p.value);
    for (int r = 0; r < A.rows(); ++r) {
      for (int c = 0; c < A.cols(); ++c) {
        const GiNaC::ex entry = GiNaC::evalf(
            reader(l.entry(symbolic::LinearMatrix::A, r, c, symbolic::Format::text)).subs(values));
        ASSERT_TRUE(GiNaC::is_a<GiNaC::numeric>(entry)) << entry;
        EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>(entry).to_double(), A(r, c),
                    1e-8 * A.cwiseAbs().maxCoeff())
            << name << " A(" << r << ", " << c << ")";
      }
    }
  }
}

TEST(SymbolicEquations, RefusesWhatItDoesNotWriteAndUnknownSymbols) {
  symbolic::EquationOptions options;
  options.symbols = {"m_bobb"};
  try {
    symbolic::derive_equations(io::read_model_file(example("pendulum")).model, options);
    ADD_FAILURE() << "no error";
  } catch (const InvalidArgument& error) {
    EXPECT_NE(std::string(error.what()).find("did you mean 'm_bob'"), std::string::npos)
        << error.what();
  }
  // A torsional spring across a ball joint: its angle is no sum of joint angles.
  const std::string ball =
      "name: ball\nbodies:\n  - {name: a, mass: 1, inertia: [1, 1, 1]}\n"
      "  - {name: b, mass: 1, inertia: [1, 1, 1]}\njoints:\n"
      "  - {name: ja, type: revolute, parent: world, child: a, axis: [0, 0, 1]}\n"
      "  - {name: jb, type: ball, parent: a, child: b}\n"
      "forces:\n  - {name: twist, type: torsional_spring, body_a: a, body_b: b, stiffness: 1}\n";
  try {
    symbolic::derive_equations(io::parse_model_file(ball, "ball.yaml", ".").model);
    ADD_FAILURE() << "no error";
  } catch (const InvalidArgument& error) {
    EXPECT_NE(std::string(error.what())
                  .find("'twist': a torsional spring across the spherical "
                        "joint 'jb'"),
              std::string::npos)
        << error.what();
  }
}

// The generated C++ (compiled in) computes the same M and b as the numeric engine.
template <class Mass, class Bias>
void expect_generated_code_matches(const std::string& name, int nfree, int nu, Mass mass_matrix,
                                   Bias bias) {
  const io::ModelFile file = io::read_model_file(example(name));
  const symbolic::Equations e = symbolic::derive_equations(file.model);
  std::mt19937 rng(5);
  for (int k = 0; k < 3; ++k) {
    const NumericInstant s = numeric_instant(file.model, e, rng, 0.2 * k);
    std::vector<double> M(static_cast<std::size_t>(nfree * nfree)),
        b(static_cast<std::size_t>(nfree));
    mass_matrix(s.q.data(), M.data());
    bias(s.q.data(), s.v.data(), s.vdot.data(), nu > 0 ? s.u.data() : nullptr, b.data());
    const MatX M_code =
        Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
            M.data(), nfree, nfree);
    EXPECT_MATRIX_NEAR(M_code, s.M_free, 1e-12 * s.M_free.cwiseAbs().maxCoeff());
    const VecX Mv = M_code * free_part(s.vdot, e.free_speeds());
    const VecX b_code = Eigen::Map<const VecX>(b.data(), nfree);
    const double scale = std::max(Mv.cwiseAbs().maxCoeff(), b_code.cwiseAbs().maxCoeff());
    EXPECT_MATRIX_NEAR(Mv + b_code, VecX::Zero(nfree), 1e-12 * scale);
  }
}

TEST(SymbolicEquations, GeneratedCppEqualsTheNumericEngine) {
  expect_generated_code_matches("double_pendulum", double_pendulum_eom::nfree,
                                double_pendulum_eom::nu, double_pendulum_eom::mass_matrix,
                                double_pendulum_eom::bias);
  expect_generated_code_matches("quarter_car", quarter_car_eom::nfree, quarter_car_eom::nu,
                                quarter_car_eom::mass_matrix, quarter_car_eom::bias);
}

// The four-bar's generated constraints(): φ, G (free columns) and k with the crank's prescribed
// acceleration in it, against the solver's rows; M v̇ + b = Gᵀλ and G v̇ + k = 0 with its v̇, λ.
TEST(SymbolicEquations, GeneratedCppOfTheFourBarCarriesItsConstraints) {
  namespace eom = four_bar_eom;
  const io::ModelFile file = io::read_model_file(example("constraints/four_bar"));
  const symbolic::Equations e = symbolic::derive_equations(file.model);
  ASSERT_EQ(eom::nrows, file.model.num_constraint_rows());
  std::mt19937 rng(23);
  for (int k = 0; k < 3; ++k) {
    const NumericInstant s = numeric_instant(file.model, e, rng, 0.3 + 0.2 * k);
    std::vector<double> M(eom::nfree * eom::nfree), b(eom::nfree), phi(eom::nrows),
        G(eom::nrows * eom::nfree), bias(eom::nrows);
    eom::mass_matrix(s.q.data(), M.data());
    eom::bias(s.q.data(), s.v.data(), s.vdot.data(), nullptr, b.data());
    eom::constraints(s.q.data(), s.v.data(), s.vdot.data(), nullptr, phi.data(), G.data(),
                     bias.data());
    using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    const MatX M_code = Eigen::Map<const RowMajor>(M.data(), eom::nfree, eom::nfree);
    const MatX G_code = Eigen::Map<const RowMajor>(G.data(), eom::nrows, eom::nfree);
    MatX G_free(eom::nrows, eom::nfree);
    for (int c = 0; c < eom::nfree; ++c)
      G_free.col(c) = s.G.col(e.free_speeds()[static_cast<std::size_t>(c)]);
    EXPECT_MATRIX_NEAR(Eigen::Map<const VecX>(phi.data(), eom::nrows), s.phi, 1e-12);
    EXPECT_MATRIX_NEAR(G_code, G_free, 1e-12 * G_free.cwiseAbs().maxCoeff());
    const VecX vdot_free = free_part(s.vdot, e.free_speeds());
    const VecX Mv = M_code * vdot_free, force = G_code.transpose() * s.lambda;
    const VecX b_code = Eigen::Map<const VecX>(b.data(), eom::nfree);
    const double scale = std::max(
        {Mv.cwiseAbs().maxCoeff(), b_code.cwiseAbs().maxCoeff(), force.cwiseAbs().maxCoeff()});
    EXPECT_MATRIX_NEAR(Mv + b_code - force, VecX::Zero(eom::nfree), 1e-12 * scale);
    // G v̇ + k = 0 on the rows the solver keeps (the three out of the plane are redundant).
    const VecX accel = G_code * vdot_free + Eigen::Map<const VecX>(bias.data(), eom::nrows);
    const VecX Gv = (G_code * vdot_free).cwiseAbs();
    for (int r = 0; r < eom::nrows; ++r) {
      if (s.lambda[r] == 0.0) continue;
      EXPECT_NEAR(accel[r], 0.0, 1e-11 * std::max(1.0, Gv[r])) << "row " << r;
    }
  }
}

// Constrained models read as a textbook writes them: the geared pair (a coupler q_p = n q_w),
// each wheel's equation with the mesh's effort λ, and the constraint itself.
TEST(SymbolicEquations, TheGearedPairReadsWithItsMeshEffort) {
  const symbolic::Equations e = symbols_of("constraints/geared_pair");
  ASSERT_EQ(e.free_speeds().size(), 2u);
  ASSERT_EQ(e.constraint_rows(), 1);
  EXPECT_EQ(e.multiplier_names(), std::vector<std::string>{"lambda_mesh_ratio"});
  expect_same_equation(e.equation(0, symbolic::Format::text),
                       "I_pinion_zz*pinion_axle_ddot = lambda_mesh_ratio");
  expect_same_equation(e.equation(1, symbolic::Format::text),
                       "I_wheel_zz*wheel_axle_ddot - F_drive = -n_mesh*lambda_mesh_ratio");
  expect_same_equation(e.constraint_equation(0, symbolic::Format::text),
                       "pinion_axle - n_mesh*wheel_axle = 0");
}

// The generated Python, run by python3, prints the same M and b as Equations::evaluate.
TEST(SymbolicEquations, GeneratedPythonEqualsTheLibrary) {
  const auto dir = test::make_scratch_dir("equations_python");
  const io::ModelFile file = io::read_model_file(example("double_pendulum"));
  const symbolic::Equations e = symbolic::derive_equations(file.model);
  std::ofstream(dir / "eom.py") << e.generate_code(symbolic::Format::python, "eom");
  std::ofstream(dir / "run.py") << "import eom\n"
                                   "q = [0.3, -1.1]; v = [0.7, 2.2]; a = [0.0, 0.0]\n"
                                   "for row in eom.mass_matrix(q): print(*[repr(x) for x in row])\n"
                                   "print(*[repr(x) for x in eom.bias(q, v, a, [])])\n";
  const std::string command = "cd '" + dir.string() + "' && python3 run.py > out.txt";
  ASSERT_EQ(std::system(command.c_str()), 0);
  std::ifstream in(dir / "out.txt");
  VecX q(2), v(2), a = VecX::Zero(2);
  q << 0.3, -1.1;
  v << 0.7, 2.2;
  MatX M;
  VecX b;
  e.evaluate(q, v, a, VecX(), M, b);
  double x;
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) {
      ASSERT_TRUE(in >> x);
      EXPECT_NEAR(x, M(r, c), 1e-13 * M.cwiseAbs().maxCoeff());
    }
  for (int r = 0; r < 2; ++r) {
    ASSERT_TRUE(in >> x);
    EXPECT_NEAR(x, b[r], 1e-13 * b.cwiseAbs().maxCoeff());
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace momenta
