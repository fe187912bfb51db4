// Simulation: the table it writes (columns, rows, --every), the conservation audit against the
// integrator's order and against invariants known in closed form, prescribed motion recorded
// exactly, a non-finite state stopping the run, and a step loop that does not allocate.

#include "momenta/simulate/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/model/model_builder.hpp"
#include "momenta_test/allocation_counter.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::simulate {

using model::OutputQuantity;
using model::OutputSpec;
namespace {

using model::Joint;
using model::JointType;
using model::ModelBuilder;

// A point mass m = 1 kg on a 1 m massless rod hinged about y at the origin, released from θ0.
model::Model pendulum(double theta0, double damping = 0.0) {
  ModelBuilder b;
  b.add_body("bob", inertia::MassProperties(1.0, Vec3(0, 0, -1), Mat3::Zero()));
  Joint j;
  j.name = "pivot";
  j.type = JointType::revolute;
  j.parent = "world";
  j.child = "bob";
  j.axis = Vec3::UnitY();
  j.q0 = VecX::Constant(1, theta0);
  j.damping = damping;
  b.add_joint(j);
  return b.build();
}

// A free body, I = diag(1, 2, 3) kg·m², spun near its intermediate axis, no gravity.
model::Model racket() {
  ModelBuilder b;
  b.set_gravity(Vec3::Zero());
  b.add_body("racket",
             inertia::MassProperties(1.0, Vec3::Zero(), Vec3(1.0, 2.0, 3.0).asDiagonal()));
  Joint j;
  j.name = "free";
  j.type = JointType::free;
  j.parent = "world";
  j.child = "racket";
  j.v0 = VecX(6);
  j.v0 << 0.01, 2.0, 0.01, 0.0, 0.0, 0.0;
  b.add_joint(j);
  return b.build();
}

// A 3 kg carriage lifted along z by the prescribed z(t) = 0.1 sin(4π t).
model::Model lift() {
  ModelBuilder b;
  b.add_signal(model::Signal("lift", model::SineSignal{0.1, 2.0, 0.0, 0.0, 0.0}));
  b.add_body("carriage", inertia::MassProperties(3.0, Vec3::Zero(), Mat3::Identity() * 0.01));
  Joint j;
  j.name = "slide";
  j.type = JointType::prismatic;
  j.parent = "world";
  j.child = "carriage";
  j.axis = Vec3::UnitZ();
  j.prescribed_signals = {"lift"};
  b.add_joint(j);
  return b.build();
}

SimulationOptions options(double duration, double step, std::string integrator = "rk4",
                          long every = 1) {
  SimulationOptions o;
  o.duration = duration;
  o.step = step;
  o.integrator = std::move(integrator);
  o.every = every;
  return o;
}

const AuditEntry& audit_entry(const SimulationSummary& s, const std::string& name) {
  for (const AuditEntry& e : s.audit)
    if (e.name == name) return e;
  throw InvalidArgument("no audit entry " + name);
}

TEST(Simulation, ColumnsOfAFreeBodyWithReactionsAndAnOutput) {
  const model::Model m = racket();
  OutputSpec w;
  w.name = "w";
  w.quantity = OutputQuantity::body_angular_velocity;
  w.target = "racket";
  SimulationOptions o = options(1.0, 1e-3);
  o.reactions = true;
  const Simulation sim(m, {w}, o);
  const std::vector<std::string> expected = {"time",
                                             "free.x",
                                             "free.y",
                                             "free.z",
                                             "free.qw",
                                             "free.qx",
                                             "free.qy",
                                             "free.qz",
                                             "free.wx",
                                             "free.wy",
                                             "free.wz",
                                             "free.vx",
                                             "free.vy",
                                             "free.vz",
                                             "energy_kinetic",
                                             "energy_potential",
                                             "energy_total",
                                             "H_x",
                                             "H_y",
                                             "H_z",
                                             "w.x",
                                             "w.y",
                                             "w.z",
                                             "free.reaction.Fx",
                                             "free.reaction.Fy",
                                             "free.reaction.Fz",
                                             "free.reaction.Mx",
                                             "free.reaction.My",
                                             "free.reaction.Mz",
                                             "audit.energy_drift",
                                             "audit.H_norm_drift",
                                             "audit.H_drift",
                                             "audit.quaternion_norm_error"};
  EXPECT_EQ(sim.column_names(), expected);
}

// The audit columns appear only for what the model should conserve.
TEST(Simulation, AuditColumnsFollowWhatTheModelConserves) {
  const std::vector<std::string> conservative = {"time",
                                                 "pivot.angle",
                                                 "pivot.angle_rate",
                                                 "energy_kinetic",
                                                 "energy_potential",
                                                 "energy_total",
                                                 "H_x",
                                                 "H_y",
                                                 "H_z",
                                                 "audit.energy_drift"};
  const model::Model undamped = pendulum(1.0), damped_model = pendulum(1.0, 0.1);
  EXPECT_EQ(Simulation(undamped, {}, options(1.0, 1e-2)).column_names(), conservative);
  const std::vector<std::string> damped(conservative.begin(), conservative.end() - 1);
  EXPECT_EQ(Simulation(damped_model, {}, options(1.0, 1e-2)).column_names(), damped);
}

// RK4's energy error is C h⁴ (1 + a h + …) over a fixed interval: halving h divides it by
// 16 (1 + a h / 2 + …). On this large-amplitude pendulum (θ0 = 2 rad) the O(h) correction is
// still visible at h = 0.01 s, so the test checks the asymptotic approach itself: both ratios
// within [16, 20] (orders 3 and 5 give 8 and 32), the second closer to 16, by about half.
TEST(Simulation, EnergyDriftOfRk4FallsWithTheFourthPowerOfTheStep) {
  const model::Model m = pendulum(2.0);
  double drift[3];
  for (int i = 0; i < 3; ++i) {
    Simulation sim(m, {}, options(3.0, 0.01 / (1 << i)));
    TableSink sink;
    const SimulationSummary s = sim.run(sink);
    ASSERT_TRUE(s.energy_audited);
    drift[i] = audit_entry(s, "energy").max_drift;
  }
  const double r1 = drift[0] / drift[1], r2 = drift[1] / drift[2];
  EXPECT_GT(r1, 16.0) << r1;
  EXPECT_LT(r1, 20.0) << r1;
  EXPECT_GT(r2, 16.0) << r2;
  EXPECT_LT(r2 - 16.0, 0.65 * (r1 - 16.0)) << r1 << " " << r2;
}

// Symplectic Euler keeps the energy error bounded at O(h): halving h halves it (ratio 2, within
// [1.6, 2.4] for the O(h²) correction at ω h ≤ 0.06).
TEST(Simulation, EnergyErrorOfSymplecticEulerIsFirstOrder) {
  const model::Model m = pendulum(2.0);
  double drift[2];
  for (int i = 0; i < 2; ++i) {
    Simulation sim(m, {}, options(3.0, i == 0 ? 0.02 : 0.01, "symplectic_euler"));
    TableSink sink;
    drift[i] = audit_entry(sim.run(sink), "energy").max_drift;
  }
  EXPECT_GT(drift[0] / drift[1], 1.6) << drift[0] << " " << drift[1];
  EXPECT_LT(drift[0] / drift[1], 2.4) << drift[0] << " " << drift[1];
}

// Rows at step 0, every n-th step and the last; times are k h exactly (integrate::run).
TEST(Simulation, EveryKeepsEveryNthStepAndTheLast) {
  const model::Model m = pendulum(1.0);  // outlives the simulation
  Simulation sim(m, {}, options(1.0, 0.1, "rk4", 3));
  TableSink sink;
  const SimulationSummary s = sim.run(sink);
  EXPECT_EQ(s.statistics.steps, 10);
  EXPECT_EQ(s.rows, 5);
  ASSERT_EQ(sink.rows.size(), 5u);
  const std::vector<double> times = {0.0, 3 * 0.1, 6 * 0.1, 9 * 0.1, 1.0};
  for (std::size_t i = 0; i < times.size(); ++i) EXPECT_EQ(sink.rows[i][0], times[i]) << i;
  EXPECT_EQ(s.t_end, 1.0);
}

// The audit sees every step: its maximum does not depend on which rows are kept, and is at least
// the largest drift among the kept rows.
TEST(Simulation, AuditMaximumIsOverEveryStepNotOnlyRecordedRows) {
  const model::Model m = pendulum(2.5);
  TableSink all, some;
  const SimulationSummary s1 = Simulation(m, {}, options(2.0, 0.01)).run(all);
  const SimulationSummary s7 = Simulation(m, {}, options(2.0, 0.01, "rk4", 7)).run(some);
  EXPECT_EQ(audit_entry(s1, "energy").max_drift, audit_entry(s7, "energy").max_drift);
  EXPECT_EQ(audit_entry(s1, "energy").final_drift, audit_entry(s7, "energy").final_drift);
  const int c = some.column("audit.energy_drift");
  double largest_kept = 0.0;
  for (const auto& row : some.rows) largest_kept = std::max(largest_kept, std::abs(row[c]));
  EXPECT_GE(audit_entry(s7, "energy").max_drift, largest_kept);
  EXPECT_LT(some.rows.size(), all.rows.size());
}

// Row 0 of a free body: T = ½ ωᵀ I ω = 4.0002 J and H = I ω = (0.01, 4, 0.03) (body frame = world
// at t = 0); H about the centre of mass is then conserved, and the quaternion keeps unit norm.
TEST(Simulation, FreeBodyConservesAngularMomentumAndUnitQuaternion) {
  const model::Model m = racket();
  Simulation sim(m, {}, options(2.0, 1e-3));
  TableSink sink;
  const SimulationSummary s = sim.run(sink);
  const auto& row0 = sink.rows.front();
  EXPECT_NEAR(row0[sink.column("energy_kinetic")], 4.0002, 1e-15 * 4);
  EXPECT_NEAR(row0[sink.column("H_x")], 0.01, 1e-16);
  EXPECT_NEAR(row0[sink.column("H_y")], 4.0, 1e-15);
  EXPECT_NEAR(row0[sink.column("H_z")], 0.03, 1e-16);
  ASSERT_TRUE(s.momentum_audited && s.energy_audited && s.quaternions_audited);
  // RK4 at ω h = 2e-3 over 2000 steps: local error ~ (ω h)⁵ per step, far below 1e-9.
  EXPECT_LT(audit_entry(s, "energy").max_drift, 1e-9);
  EXPECT_LT(audit_entry(s, "|H|").max_drift, 1e-9);
  EXPECT_LT(audit_entry(s, "H").max_drift, 1e-9);
  // The exponential map keeps |q| = 1 to round-off: a few ulps per step at most, 2000 steps.
  EXPECT_LT(audit_entry(s, "quaternion norm").max_drift, 1e-13);
}

// The structure-preserving splitting method holds H to round-off (rigid_body_integrator.hpp).
TEST(Simulation, RigidBodyIntegratorIsChosenByName) {
  const model::Model m = racket();
  Simulation sim(m, {}, options(2.0, 1e-2, "splitting"));
  TableSink sink;
  const SimulationSummary s = sim.run(sink);
  EXPECT_EQ(s.integrator, "splitting");
  // 200 steps, each rotating H exactly: a few ulps of |H| = 4 per step.
  EXPECT_LT(audit_entry(s, "H").max_drift, 1e-13);
}

TEST(Simulation, UnknownIntegratorListsBothFamilies) {
  try {
    const model::Model m = racket();
    Simulation(m, {}, options(1.0, 1e-3, "splittin"));
    ADD_FAILURE() << "no exception";
  } catch (const InvalidArgument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("did you mean 'splitting'"), std::string::npos) << what;
    EXPECT_NE(what.find("rk4"), std::string::npos) << what;
    EXPECT_NE(what.find("dopri5"), std::string::npos) << what;
  }
}

TEST(Simulation, BadOptionsAreRejected) {
  const model::Model m = pendulum(1.0);
  EXPECT_THROW(Simulation(m, {}, options(0.0, 1e-3)), InvalidArgument);
  EXPECT_THROW(Simulation(m, {}, options(1.0, -1e-3)), InvalidArgument);
  EXPECT_THROW(Simulation(m, {}, options(1.0, 1e-3, "rk4", 0)), InvalidArgument);
  OutputSpec clash;
  clash.name = "time";
  clash.quantity = OutputQuantity::joint_position;
  clash.target = "pivot";
  EXPECT_THROW(Simulation(m, {clash}, options(1.0, 1e-3)), InvalidArgument);
}

// Recorded prescribed coordinates are the signal's values exactly, whatever the integrator did;
// the reaction is m (z̈ + g).
TEST(Simulation, PrescribedCoordinatesAreRecordedExactly) {
  const model::Model m = lift();
  SimulationOptions o = options(1.0, 0.01, "rk4", 10);
  o.reactions = true;
  Simulation sim(m, {}, o);
  TableSink sink;
  sim.run(sink);
  const model::Signal& signal = m.signals()[0];
  for (const auto& row : sink.rows) {
    const double t = row[0];
    const model::SignalSample u = signal.sample(t);
    EXPECT_EQ(row[sink.column("slide.position")], u.value) << t;
    EXPECT_EQ(row[sink.column("slide.position_rate")], u.rate) << t;
    // m g ≈ 30 N: a few ulps of it.
    EXPECT_NEAR(row[sink.column("slide.reaction.Fz")], 3.0 * (u.acceleration + 9.81), 1e-12 * 30)
        << t;
  }
}

// A sink that counts flushes, to see that a failed run keeps its rows.
class CountingSink final : public RowSink {
 public:
  void begin(std::span<const std::string>) override {}
  void row(std::span<const double>) override { ++rows; }
  void flush() override { ++flushes; }
  long rows = 0;
  int flushes = 0;
};

// A 1 kg slider on a k = 1e8 N/m spring (ω = 1e4 rad/s) stepped at h = 0.01 s: RK4 is unstable
// (ω h = 100 ≫ 2.8) and the state overflows within a few hundred steps.
TEST(Simulation, NonFiniteStateStopsWithTimeAndKeepsTheRows) {
  ModelBuilder b;
  b.set_gravity(Vec3::Zero());
  b.add_body("slider", inertia::MassProperties(1.0, Vec3::Zero(), Mat3::Identity() * 0.01));
  Joint j;
  j.name = "rail";
  j.type = JointType::prismatic;
  j.parent = "world";
  j.child = "slider";
  j.axis = Vec3::UnitX();
  j.q0 = VecX::Constant(1, 0.01);
  b.add_joint(j);
  model::LinearSpringDamper spring;
  spring.name = "spring";
  spring.a = {"world", Vec3(-1.0, 0.0, 0.0)};
  spring.b = {"slider", Vec3::Zero()};
  spring.stiffness = 1e8;
  spring.free_length = 1.0;
  b.add_force_element(spring);
  const model::Model m = b.build();
  Simulation sim(m, {}, options(100.0, 0.01));
  CountingSink sink;
  try {
    sim.run(sink);
    ADD_FAILURE() << "no exception";
  } catch (const NumericalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("non-finite at t = "), std::string::npos) << what;
    EXPECT_NE(what.find("rail."), std::string::npos) << what;
    // The options to try stay options through the rewrap (the front ends spell them).
    const std::vector<std::string> named = e.options();
    EXPECT_NE(std::find(named.begin(), named.end(), "step"), named.end()) << what;
    EXPECT_NE(what.find(std::to_string(sink.rows) + " rows"), std::string::npos) << what;
  }
  EXPECT_GT(sink.rows, 1);
  EXPECT_EQ(sink.flushes, 1);
}

// The step loop does not allocate: a run of 1000 steps allocates exactly as much as one of 100
// (all of it before the first step).
TEST(Simulation, StepLoopDoesNotAllocate) {
  for (const model::Model& m : {pendulum(1.0), racket(), lift()}) {
    OutputSpec tip;
    tip.name = "tip";
    tip.quantity = OutputQuantity::body_velocity;
    tip.target = m.body(1).name;
    tip.point = Vec3(0.1, 0.2, 0.3);
    OutputSpec pin;
    pin.name = "pin";
    pin.quantity = OutputQuantity::reaction_force;
    pin.target = m.joint(0).name;
    long allocations[2];
    for (int i = 0; i < 2; ++i) {
      SimulationOptions o = options(i == 0 ? 0.1 : 1.0, 1e-3);
      o.reactions = true;
      Simulation sim(m, {tip, pin}, o);
      CountingSink sink;
      const long before = test::allocation_count();
      sim.run(sink);
      allocations[i] = test::allocation_count() - before;
      EXPECT_EQ(sink.rows, i == 0 ? 101 : 1001);
    }
    EXPECT_EQ(allocations[0], allocations[1]) << m.joint(0).name;
  }
}

// run() may be called again and starts afresh: the system, the integrator and the event monitor
// the constructor built are reused, and nothing of the first run may leak into the second — the
// constraint solver's redundant rows and consistent state, an adaptive method's step size, the
// events' signs, the step end that decides which side of a breakpoint a signal is read from.
TEST(Simulation, RunningTwiceWritesTheSameTableAndSummary) {
  const io::ModelFile swing =
      io::read_model_file(test::source_dir() + "/examples/constraints/parallelogram_swing.yaml");
  // A pendulum on a carriage shaken by a square wave of force: its breakpoints (every 0.15 s) are
  // where the step end matters.
  ModelBuilder b;
  b.add_signal(model::Signal("shake", model::PulseSignal{0.0, 0.15, 20.0, -10.0, 0.3}));
  b.add_body("carriage", inertia::MassProperties(3.0, Vec3::Zero(), Mat3::Identity() * 0.01));
  b.add_body("bob", inertia::MassProperties(1.0, Vec3(0, 0, -0.5), Mat3::Identity() * 1e-3));
  Joint slide;
  slide.name = "slide";
  slide.type = JointType::prismatic;
  slide.parent = "world";
  slide.child = "carriage";
  slide.axis = Vec3::UnitX();
  b.add_joint(slide);
  Joint pivot;
  pivot.name = "pivot";
  pivot.type = JointType::revolute;
  pivot.parent = "carriage";
  pivot.child = "bob";
  pivot.axis = Vec3::UnitY();
  pivot.q0 = VecX::Constant(1, 0.3);
  b.add_joint(pivot);
  model::AppliedForce push;
  push.name = "push";
  push.at.body = "carriage";
  push.vector = Vec3::UnitX();
  push.signal = "shake";
  b.add_force_element(push);
  const model::Model shaken = b.build();

  struct Case {
    const model::Model* model;
    std::string integrator;
    std::string event;
  };
  for (const Case& c : {Case{&swing.model, "dopri5", "pivot1.angle < -1.6"},
                        Case{&swing.model, "rk4", "pivot1.angle < -1.6"},
                        Case{&shaken, "dopri5", "pivot.angle < 0"}}) {
    SimulationOptions o = options(1.0, 0.01, c.integrator);
    o.reactions = true;
    o.events = {model::parse_event_condition(c.event)};
    Simulation sim(*c.model, {}, o);
    TableSink first, second;
    const SimulationSummary a = sim.run(first);
    const SimulationSummary z = sim.run(second);
    SCOPED_TRACE(c.integrator + " on " + c.model->joint(0).name);
    ASSERT_GT(first.rows.size(), 10u);
    ASSERT_FALSE(a.events.empty());
    EXPECT_EQ(first.columns, second.columns);
    EXPECT_EQ(first.rows, second.rows);  // bit for bit
    EXPECT_EQ(a.statistics.steps, z.statistics.steps);
    EXPECT_EQ(a.statistics.rejected_steps, z.statistics.rejected_steps);
    EXPECT_EQ(a.statistics.evaluations, z.statistics.evaluations);
    EXPECT_EQ(a.events.size(), z.events.size());
    EXPECT_EQ(a.redundant_constraint_rows, z.redundant_constraint_rows);
    EXPECT_EQ(a.initial_state.q_changes.size(), z.initial_state.q_changes.size());
    EXPECT_EQ(a.t_end, z.t_end);
  }
}

TEST(Simulation, SummaryNamesStepsEvaluationsAndAudit) {
  const model::Model m = pendulum(1.0);
  Simulation sim(m, {}, options(1.0, 0.01));
  TableSink sink;
  const std::string text = format_summary(sim.run(sink));
  EXPECT_NE(text.find("rk4 (order 4)"), std::string::npos) << text;
  EXPECT_NE(text.find("100 accepted, 0 rejected; 400 evaluations"), std::string::npos) << text;
  EXPECT_NE(text.find("energy"), std::string::npos) << text;
  EXPECT_NE(text.find("H                not audited"), std::string::npos) << text;
}

}  // namespace
}  // namespace momenta::simulate
