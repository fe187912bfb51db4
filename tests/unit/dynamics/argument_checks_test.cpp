// Every public dynamics algorithm refuses arguments of the wrong size, naming the algorithm, the
// argument and both sizes — before the fix a short q read out of bounds.
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/energy.hpp"
#include "momenta/dynamics/hybrid_dynamics.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/dynamics/momentum.hpp"
#include "momenta/dynamics/reactions.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta_test/hand_models.hpp"

namespace momenta::dynamics {
namespace {

void expect_refused(const std::function<void()>& call, const std::string& message) {
  try {
    call();
    ADD_FAILURE() << "accepted; expected: " << message;
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
  }
}

TEST(ArgumentChecks, EveryAlgorithmRefusesWrongSizes) {
  const Model model = test::double_pendulum(1.0, 1.0, 1.0, 1.0);  // nq = nv = 2, 3 bodies
  Data data(model);
  const VecX ok = VecX::Zero(2), short_q = VecX::Zero(1), long_v = VecX::Zero(3);
  const std::vector<Vec6> two_wrenches(2, Vec6::Zero());
  expect_refused([&] { aba(model, data, short_q, ok, ok); },
                 "aba: q has size 1; the model needs 2 (nq)");
  expect_refused([&] { aba(model, data, ok, long_v, ok); }, "aba: v has size 3");
  expect_refused([&] { aba(model, data, ok, ok, short_q); }, "aba: tau has size 1");
  expect_refused([&] { aba(model, data, ok, ok, ok, two_wrenches); },
                 "aba: f_ext has size 2; the model needs 3 (one wrench per body, or none)");
  expect_refused([&] { rnea(model, data, ok, ok, long_v); }, "rnea: vdot has size 3");
  expect_refused([&] { crba(model, data, long_v); }, "crba: q has size 3");
  expect_refused([&] { forward_kinematics(model, data, short_q); }, "forward_kinematics: q");
  expect_refused([&] { forward_kinematics(model, data, ok, ok, short_q); },
                 "forward_kinematics: vdot");
  expect_refused([&] { joint_reactions(model, data, ok, ok, short_q); },
                 "joint_reactions: vdot has size 1");
  expect_refused([&] { hybrid_dynamics(model, data, ok, ok, ok, short_q); },
                 "hybrid_dynamics: tau has size 1");
  expect_refused([&] { kinetic_energy(model, data, ok, short_q); }, "v has size 1");
  expect_refused([&] { momentum(model, data, short_q, ok); }, "q has size 1");
  // A Data built for another model of another size.
  const Model pendulum = test::pendulum(1.0, 1.0, 0.01);
  Data small(pendulum);
  expect_refused([&] { aba(model, small, ok, ok, ok); }, "aba: data (built for another model?)");
  // Right sizes pass.
  EXPECT_NO_THROW(aba(model, data, ok, ok, ok));
  EXPECT_NO_THROW(rnea(model, data, ok, ok, ok, std::vector<Vec6>(3, Vec6::Zero())));
}

}  // namespace
}  // namespace momenta::dynamics
