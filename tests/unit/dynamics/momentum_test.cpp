// Centre of mass and momentum of a pendulum and of a double pendulum, in closed form.
#include "momenta/dynamics/momentum.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "momenta_test/hand_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics {
namespace {

// Linear momentum m v_cm; angular momentum about the centre of mass I_c θ̇ ŷ, about the pivot
// (I_c + m l²) θ̇ ŷ.
TEST(Momentum, Pendulum) {
  const double m = 2.0, l = 0.7, I_c = 0.05;
  const Model model = test::pendulum(m, l, I_c);
  Data data(model);
  const double theta = 0.8, w = -1.9;
  const Momentum h = momentum(model, data, VecX::Constant(1, theta), VecX::Constant(1, w));
  const Vec3 u(-std::sin(theta), 0, -std::cos(theta)), du(-std::cos(theta), 0, std::sin(theta));
  EXPECT_EQ(h.mass, m);
  EXPECT_MATRIX_NEAR(h.p_WoScm_W, l * u, 1e-15);
  EXPECT_MATRIX_NEAR(h.v_WScm_W, l * w * du, 1e-15);
  EXPECT_MATRIX_NEAR(h.linear, m * l * w * du, 1e-15);
  EXPECT_MATRIX_NEAR(h.angular_about_com, Vec3(0, I_c * w, 0), 1e-15);
  EXPECT_MATRIX_NEAR(h.angular_about(Vec3::Zero()), Vec3(0, (I_c + m * l * l) * w, 0), 1e-15);
}

TEST(Momentum, CenterOfMassOfTwoBodies) {
  const double m1 = 1.0, m2 = 3.0, l1 = 0.5, l2 = 0.4;
  const Model model = test::double_pendulum(m1, m2, l1, l2);
  Data data(model);
  const VecX q = (VecX(2) << 0.3, 0.5).finished();
  const auto u = [](double f) { return Vec3(-std::sin(f), 0, -std::cos(f)); };
  const Vec3 expected = (m1 * l1 * u(0.3) + m2 * (l1 * u(0.3) + l2 * u(0.8))) / (m1 + m2);
  EXPECT_MATRIX_NEAR(center_of_mass(model, data, q), expected, 1e-15);
}

}  // namespace
}  // namespace momenta::dynamics
