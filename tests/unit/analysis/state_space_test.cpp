#include "momenta/analysis/state_space.hpp"

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::analysis {
namespace {

// Message of the InvalidArgument thrown by f, or "" if none.
template <typename F>
std::string message_of(F&& f) {
  try {
    f();
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "";
}

StateSpace two_state_system() {
  MatX A(2, 2), B(2, 2), C(1, 2), D(1, 2);
  A << 0, 1, -4, -0.4;
  B << 0, 0, 1, 2;
  C << 1, 0;
  D << 0, 0.5;
  return StateSpace(A, B, C, D, {"position", "velocity"}, {"force", "torque"}, {"height"});
}

TEST(StateSpace, SizesNamesAndDefaults) {
  const StateSpace s = two_state_system();
  EXPECT_EQ(s.state_count(), 2u);
  EXPECT_EQ(s.input_count(), 2u);
  EXPECT_EQ(s.output_count(), 1u);
  EXPECT_EQ(s.input_index("torque"), 1u);
  EXPECT_EQ(s.state_index("velocity"), 1u);
  EXPECT_FALSE(s.is_siso());

  // Empty D is the zero matrix; empty name lists get x1.., u1.., y1...
  const StateSpace d(MatX::Identity(3, 3), MatX::Ones(3, 2), MatX::Ones(4, 3), MatX());
  EXPECT_EQ(d.D().rows(), 4);
  EXPECT_EQ(d.D().cols(), 2);
  EXPECT_EQ(d.D().cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(d.state_names()[2], "x3");
  EXPECT_EQ(d.input_names()[1], "u2");
  EXPECT_EQ(d.output_names()[3], "y4");
}

TEST(StateSpace, SisoPicksThePair) {
  const StateSpace s = two_state_system().siso("torque", "height");
  EXPECT_TRUE(s.is_siso());
  EXPECT_EQ(s.input_names()[0], "torque");
  EXPECT_EQ(s.output_names()[0], "height");
  EXPECT_EQ(s.B()(1, 0), 2.0);
  EXPECT_EQ(s.D()(0, 0), 0.5);
  EXPECT_EQ(s.state_names()[0], "position");
}

TEST(StateSpace, UnitsTravelWithTheNamesTheyBelongTo) {
  const StateSpace plain = two_state_system();
  EXPECT_TRUE(plain.units().states.empty());  // built from matrices: none known
  const StateSpace s = plain.with_units({{"m", "m/s"}, {"N", "N·m"}, {"m"}});
  EXPECT_EQ(s.units().inputs[1], "N·m");
  const StateSpace pair = s.siso("torque", "height");
  EXPECT_EQ(pair.units().inputs, std::vector<std::string>{"N·m"});
  EXPECT_EQ(pair.units().outputs, std::vector<std::string>{"m"});
  EXPECT_EQ(pair.units().states, (std::vector<std::string>{"m", "m/s"}));
  EXPECT_EQ(plain.siso("force", "height").units().inputs.size(), 0u);
  EXPECT_EQ(message_of([&] {
              (void)plain.with_units({{"m"}, {}, {}});
            }),
            "StateSpace: 1 state units for 2 states");
}

TEST(StateSpace, DimensionErrorsNameTheMatrixAndSizes) {
  const MatX A = MatX::Identity(2, 2);
  EXPECT_NE(message_of([&] {
              StateSpace(MatX::Ones(2, 3), MatX::Ones(2, 1), MatX::Ones(1, 2), MatX());
            }).find("A is 2×3"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              StateSpace(A, MatX::Ones(3, 1), MatX::Ones(1, 2), MatX());
            }).find("B is 3×1"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              StateSpace(A, MatX::Ones(2, 1), MatX::Ones(1, 3), MatX());
            }).find("C is 1×3"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              StateSpace(A, MatX::Ones(2, 1), MatX::Ones(1, 2), MatX::Ones(2, 2));
            }).find("D is 2×2 but must be 1×1"),
            std::string::npos);
  MatX bad = A;
  bad(1, 0) = std::nan("");
  EXPECT_NE(message_of([&] {
              StateSpace(bad, MatX::Ones(2, 1), MatX::Ones(1, 2), MatX());
            }).find("A(1, 0) = nan"),
            std::string::npos);
}

TEST(StateSpace, NameErrors) {
  const MatX A = MatX::Identity(2, 2);
  EXPECT_NE(message_of([&] {
              StateSpace(A, MatX::Ones(2, 1), MatX::Ones(1, 2), MatX(), {"a"});
            }).find("1 state names given for 2 states"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              StateSpace(A, MatX::Ones(2, 1), MatX::Ones(1, 2), MatX(), {"a", "a"});
            }).find("'a' appears twice"),
            std::string::npos);
  const StateSpace s = two_state_system();
  const std::string unknown = message_of([&] { s.input_index("torqe"); });
  EXPECT_NE(unknown.find("did you mean 'torque'"), std::string::npos) << unknown;
  EXPECT_NE(message_of([&] { s.siso(2, 0); }).find("input index 2"), std::string::npos);
  EXPECT_NE(message_of([&] { s.siso(0, 1); }).find("output index 1"), std::string::npos);
}

TEST(StateSpace, SecondOrderCompanionForm) {
  // Two masses: M q̈ + C q̇ + K q = F u; check A x = [q̇; M⁻¹(F u − K q − C q̇)] at a point.
  MatX M(2, 2), C(2, 2), K(2, 2), F(2, 1), Cq(1, 2), Cv(1, 2);
  M << 2, 0.5, 0.5, 1;
  C << 0.3, -0.1, -0.1, 0.2;
  K << 40, -10, -10, 10;
  F << 1, 0;
  Cq << 0, 1;
  Cv << 1, 0;
  const StateSpace s = second_order_state_space(M, C, K, F, Cq, Cv, {"q_a", "q_b"});
  EXPECT_EQ(s.state_names()[3], "q_b_dot");
  VecX q(2), v(2);
  q << 0.1, -0.3;
  v << 1.5, 0.7;
  const double u = 2.0;
  VecX x(4);
  x << q, v;
  const VecX xdot = s.A() * x + s.B() * u;
  EXPECT_MATRIX_NEAR(xdot.head(2), v, 0.0);
  // Round-off of a 2×2 solve on O(10) numbers.
  EXPECT_MATRIX_NEAR(M * xdot.tail(2) + C * v + K * q, F * u, 1e-13);
  EXPECT_EQ((s.C() * x)(0), q[1] + v[0]);

  MatX indefinite = M;
  indefinite(1, 1) = -1;
  EXPECT_NE(message_of([&] {
              second_order_state_space(indefinite, C, K, F, Cq, Cv);
            }).find("not positive definite"),
            std::string::npos);
}

}  // namespace
}  // namespace momenta::analysis
