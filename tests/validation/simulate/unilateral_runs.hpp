#pragma once
// What the tests of joint stops and contacts (simulate/unilaterals.hpp) share: a model from a
// model file's text, a run that records every row with the reactions, and a rod on a pin.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/io/model_file.hpp"
#include "momenta/simulate/simulation.hpp"

namespace momenta::simulate::unilateral_test {

inline constexpr double kG = 9.81;

inline model::Model load(const std::string& text) {
  return io::parse_model_file(text, "unilaterals.yaml", ".").model;
}

/// What loading the model file's text says is wrong with it, or "no error".
inline std::string load_error(const std::string& text) {
  try {
    load(text);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "no error";
}

struct UnilateralRun {
  SimulationSummary summary;
  TableSink table;
};

/// A run of `duration` s at `step` (the adaptive integrators at `tolerances`, rtol 1e-12 and
/// atol 1e-14 unless told), every row kept, with the reactions' columns where `reactions`.
inline UnilateralRun run_unilaterals(const model::Model& model, const std::string& integrator,
                                     double step, double duration, bool reactions = false,
                                     integrate::Tolerances tolerances = {1e-12, 1e-14}) {
  SimulationOptions options;
  options.duration = duration;
  options.step = step;
  options.integrator = integrator;
  options.tolerances = tolerances;
  options.reactions = reactions;
  Simulation simulation(model, {}, options);
  UnilateralRun run;
  run.summary = simulation.run(run.table);
  return run;
}

/// A uniform rod, m = 1 kg, l = 1 m, hanging from a pin about y (I_O = m l²/3); `joint_extra`
/// ends the pin's entry, `more` follows the joints.
inline std::string hanging_rod(const std::string& joint_extra, const std::string& more = "") {
  return "gravity: [0, 0, -9.81]\n"
         "bodies: [{name: rod, shape: slender_rod, mass: 1.0, length: 1.0, position: [0, 0, "
         "-0.5]}]\n"
         "joints:\n"
         "  - {name: pin, type: revolute, parent: world, child: rod, axis: [0, 1, 0], " +
         joint_extra + "}\n" + more;
}

/// The events of a mechanism held from the start and let go once, at `release` (s, to 1e-13).
inline void expect_held_then_let_go(const std::vector<StopEvent>& events, double release) {
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].kind, StopEventKind::rest);
  EXPECT_EQ(events[0].time, 0.0);
  EXPECT_EQ(events[1].kind, StopEventKind::release);
  EXPECT_NEAR(events[1].time, release, 1e-13);
}

}  // namespace momenta::simulate::unilateral_test
