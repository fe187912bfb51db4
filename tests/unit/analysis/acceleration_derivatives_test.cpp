// ∂a/∂q and ∂a/∂v of AccelerationDerivatives against central differences (with one Richardson
// extrapolation, error O(h⁴)) of the model's own accelerations: springs and dampers between
// bodies, a prescribed road moving mid-step, gravity on a chain of links, joint damping.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "momenta/analysis/acceleration_derivatives.hpp"
#include "momenta/common/error.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta_test/allocation_counter.hpp"

namespace momenta::analysis {
namespace {

// (f(x + h) − f(x − h)) / 2h extrapolated with h/2: the derivative to ~1e-11 of its size here.
template <class F>
VecX richardson(F&& f, double h) {
  const auto central = [&](double s) { return VecX((f(s) - f(-s)) / (2.0 * s)); };
  return (4.0 * central(0.5 * h) - central(h)) / 3.0;
}

void expect_match(const std::string& file, double t, const VecX& dq_state, const VecX& v) {
  SCOPED_TRACE(file);
  const io::ModelFile model_file = io::read_model_file(file);
  const model::Model& model = model_file.model;
  system::MultibodySystem system(model);
  const int n = model.nv();
  const VecX q = model.initial_q() + dq_state;
  AccelerationDerivatives derivatives(model);
  MatX da_dq(n, n), da_dv(n, n);
  VecX a(n);
  system.acceleration(t, q, v, a);
  derivatives.compute(system, da_dq, da_dv);

  MatX reference_q = MatX::Zero(n, n), reference_v = MatX::Zero(n, n);
  for (const int j : derivatives.free()) {
    const auto moved = [&](bool velocity) {
      return [&, velocity](double s) {
        VecX qs = q, vs = v, out(n);
        (velocity ? vs : qs)[j] += s;
        system.acceleration(t, qs, vs, out);
        return out;
      };
    };
    reference_q.col(j) = richardson(moved(false), 1e-3);
    reference_v.col(j) = richardson(moved(true), 1e-3);
  }
  for (int i = 0; i < n; ++i) {
    bool free = false;
    for (const int f : derivatives.free()) free = free || f == i;
    if (free) continue;
    reference_q.row(i).setZero();  // a prescribed coordinate's motion is given
    reference_v.row(i).setZero();
  }
  const double scale_q = reference_q.cwiseAbs().maxCoeff();
  const double scale_v = reference_v.cwiseAbs().maxCoeff();
  ASSERT_GT(scale_q, 0.0);
  ASSERT_GT(scale_v, 0.0);
  EXPECT_LT((da_dq - reference_q).cwiseAbs().maxCoeff(), 1e-8 * scale_q);
  EXPECT_LT((da_dv - reference_v).cwiseAbs().maxCoeff(), 1e-8 * scale_v);
}

TEST(AccelerationDerivatives, QuarterCarWithTheRoadRisingMatchesDifferences) {
  VecX dq(3), v(3);
  dq << 0.0, 0.004, -0.002;
  v << 0.0, 0.3, -0.1;
  expect_match("examples/quarter_car.yaml", 0.105, dq, v);  // mid-rise of the kerb
}

TEST(AccelerationDerivatives, DoublePendulumMatchesDifferences) {
  VecX dq(2), v(2);
  dq << 0.3, -0.7;
  v << 1.1, -0.4;
  expect_match("examples/double_pendulum.yaml", 0.0, dq, v);
}

TEST(AccelerationDerivatives, DampedPendulumMatchesDifferences) {
  VecX dq(1), v(1);
  dq << 0.2;
  v << -0.8;
  expect_match("examples/identification/damped_pendulum.yaml", 0.0, dq, v);
}

TEST(AccelerationDerivatives, DoNotAllocate) {
  const io::ModelFile file = io::read_model_file("examples/quarter_car.yaml");
  system::MultibodySystem system(file.model);
  AccelerationDerivatives derivatives(file.model);
  MatX da_dq(3, 3), da_dv(3, 3);
  VecX q = file.model.initial_q(), v = VecX::Constant(3, 0.1), a(3);
  system.acceleration(0.105, q, v, a);
  derivatives.compute(system, da_dq, da_dv);
  if (!test::allocation_count_includes_malloc()) GTEST_SKIP() << "allocation counter unavailable";
  const long before = test::allocation_count();
  derivatives.compute(system, da_dq, da_dv);
  EXPECT_EQ(test::allocation_count() - before, 0);
}

TEST(AccelerationDerivatives, RefuseAModelWithConstraints) {
  const io::ModelFile file = io::read_model_file("examples/constraints/four_bar.yaml");
  EXPECT_THROW(AccelerationDerivatives{file.model}, InvalidArgument);
}

}  // namespace
}  // namespace momenta::analysis
