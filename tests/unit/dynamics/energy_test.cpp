// Energies of a pendulum in closed form.
#include "momenta/dynamics/energy.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "momenta_test/hand_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics {
namespace {

// T = ½ (I_c + m l²) θ̇², V = −m g l cos θ (zero with the centre of mass at the pivot height).
TEST(Energy, Pendulum) {
  const double m = 2.0, l = 0.7, I_c = 0.05, g = 9.81;
  const Model model = test::pendulum(m, l, I_c, g);
  Data data(model);
  const VecX q = VecX::Constant(1, 0.8), v = VecX::Constant(1, -1.9);
  EXPECT_TRUE(test::relatively_near(kinetic_energy(model, data, q, v),
                                    0.5 * (I_c + m * l * l) * v[0] * v[0], 1e-15));
  EXPECT_TRUE(
      test::relatively_near(potential_energy(model, data, q), -m * g * l * std::cos(q[0]), 1e-15));
}

}  // namespace
}  // namespace momenta::dynamics
