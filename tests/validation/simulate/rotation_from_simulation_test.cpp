// Closed-form rotation measured from simulated models (examples/*.yaml, read by
// io::read_model_file, advanced by the structure-preserving integrators on MultibodySystem):
// the tennis-racket flip interval and period against rigid_body::asymmetric_rotation (4K/λ), and
// the heavy top's steady precession rate against rigid_body::steady_precession (the slow root of
// Goldstein eq. 5.76).
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/dynamics/kinematics.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/rigid_body/analytic_references.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta/system/rigid_body_integrator.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::simulate {

using system::make_rigid_body_integrator;
using system::MultibodySystem;
namespace {

using integrate::State;

model::Model example(const std::string& file) {
  return io::read_model_file(test::source_dir() + "/examples/" + file).model;
}

// Attitude and angular velocity (in B) of body 1 by forward kinematics.
void body_rotation(const model::Model& model, dynamics::Data& data, const State& state, Mat3& R,
                   Vec3& w) {
  dynamics::forward_kinematics(model, data, state.q, state.v);
  R = data.X_WB[1].R;
  w = data.V_WB_B[1].head<3>();
}

// The times at which ω2 (the intermediate-axis component) changes sign over `duration` s of
// steps h, each by linear interpolation between the steps around it. ω2 = a sn(λt + u0) has
// zero curvature where it crosses zero (sn'' = −(1 + m) sn + 2m sn³), so the interpolation
// error is third order: below λ² h³/3 ≈ 4e-10 s per crossing at h = 1 ms.
std::vector<double> flip_times(const model::Model& model, std::string_view integrator_name,
                               double h, double duration) {
  MultibodySystem system(model);
  auto integrator = make_rigid_body_integrator(integrator_name);
  State state{0.0, model.initial_q(), model.initial_v()};
  integrator->initialize(system, state);
  dynamics::Data data(model);
  Mat3 R;
  Vec3 w;
  body_rotation(model, data, state, R, w);
  double previous = w[1];
  std::vector<double> times;
  const long steps = std::lround(duration / h);
  for (long k = 1; k <= steps; ++k) {
    integrator->step(system, state, h);
    body_rotation(model, data, state, R, w);
    if ((previous < 0) != (w[1] < 0)) {
      times.push_back((k - 1) * h + h * previous / (previous - w[1]));
    }
    previous = w[1];
  }
  return times;
}

TEST(RotationFromSimulation, TennisRacketFlipPeriod) {
  // examples/free_body_tennis_racket.yaml: I = diag(1, 2, 3) kg·m² (principal along B),
  // ω0 = (0.01, 2, 0.01) rad/s. The analytic flip interval 2K/λ and period 4K/λ
  // (analytic_references.hpp) against the mean interval between the ω2 reversals of 300 s of
  // simulation (26 flips), for each integrator at the file's step, h = 1 ms, and at 2 ms.
  // The measured interval carries the integrator's phase error, O(hᵖ): the test checks its size
  // and that it grows by 2ᵖ from h = 1 ms to 2 ms (±0.3, where it is above the 1e-12 floor of
  // the measurement). Measured at 1 ms: splitting 7.2e-8, lie_group 1.1e-6 (4.0× and 4.0× at
  // 2 ms); splitting4 and exact 1.3e-13, the floor (the interpolation error of the first and last
  // reversal, < λ²h³/3 ≈ 4e-10 s each, over 26 intervals of 11 s, and round-off). Bounds:
  // splitting 1e-7, lie_group 2e-6, splitting4 and exact 1e-12.
  const model::Model model = example("free_body_tennis_racket.yaml");
  const inertia::MassProperties& body = model.body(1).mass_properties;
  const inertia::PrincipalAxes axes = body.principal_axes();
  ASSERT_MATRIX_NEAR(axes.R_BP, Mat3::Identity(), 1e-15);  // the file's body is principal
  const rigid_body::AsymmetricRotation analytic =
      rigid_body::asymmetric_rotation(axes.moments, model.initial_v().head<3>());
  ASSERT_TRUE(analytic.about_major_axis);
  const double duration = 300.0;
  struct Case {
    std::string_view name;
    int order;
    double bound;
  };
  for (const Case& c : {Case{"splitting", 2, 1e-7}, Case{"splitting4", 4, 1e-12},
                        Case{"lie_group", 2, 2e-6}, Case{"exact", 0, 1e-12}}) {
    SCOPED_TRACE(std::string(c.name));
    double errors[2];
    for (int i = 0; i < 2; ++i) {
      const double h = 1e-3 * (i + 1);
      const std::vector<double> times = flip_times(model, c.name, h, duration);
      ASSERT_GE(times.size(), 20u);
      const double n = static_cast<double>(times.size() - 1);
      const double interval = (times.back() - times.front()) / n;
      // Every other reversal: one period of ω.
      const size_t periods = (times.size() - 1) / 2;
      const double period = (times[2 * periods] - times.front()) / periods;
      errors[i] = std::abs(interval - analytic.flip_interval) / analytic.flip_interval;
      RecordProperty(fmt::format("{}_h{}ms_flip_error", c.name, i + 1),
                     fmt::format("{:.3g}", errors[i]));
      if (i == 0) {
        EXPECT_LT(errors[i], c.bound);
        EXPECT_LT(std::abs(period - analytic.period) / analytic.period, c.bound);
      }
    }
    if (c.order > 0 && errors[0] > 1e-12) {
      EXPECT_NEAR(std::log2(errors[1] / errors[0]), c.order, 0.3);
    }
  }
}

TEST(RotationFromSimulation, HeavyTopSteadyPrecession) {
  // examples/heavy_top.yaml: a solid cone on its apex, tilted θ = 20°, spin ω3 = 300 rad/s,
  // started on the slow steady precession. The top read from the model (mass, the centre of mass
  // from the pivot, the principal moments about the pivot), the slow root from
  // analytic_references, against the rate at which the simulated symmetry axis turns about the
  // vertical over 5 s (about 3 turns), φ(T)/T, for each integrator at the file's step,
  // h = 0.1 ms; θ stays at 20°. The error is the integrator's phase error, O(hᵖ), growing by
  // 2ᵖ from h = 0.1 to 0.2 ms (±0.3; checked where it is above round-off). Measured at 0.1 ms:
  // rate 1.1e-7 (splitting), 3.3e-6 (lie_group), 7.4e-15 (splitting4; 1.2e-13 at 0.2 ms, 16×);
  // θ within 7.5e-8, 2.5e-6, 3.9e-15 rad. Bounds: 2e-7, 5e-6, 5e-14.
  const model::Model model = example("heavy_top.yaml");
  const model::Joint& joint = model.joint(0);
  ASSERT_EQ(joint.type, model::JointType::spherical);
  const inertia::MassProperties& body = model.body(1).mass_properties;
  const Vec3 p_BoO_B = joint.X_CJ.p;
  const inertia::PrincipalAxes about_pivot =
      inertia::MassProperties(body.mass(), body.center_of_mass(), body.inertia_about(p_BoO_B))
          .principal_axes();
  // Symmetric: two equal moments (transverse I1), the third (axial I3) along B's z.
  ASSERT_NEAR(about_pivot.moments[1], about_pivot.moments[2], 1e-15);
  rigid_body::SymmetricTop top;
  top.transverse_moment = about_pivot.moments[2];
  top.axial_moment = about_pivot.moments[0];
  top.mass = body.mass();
  top.com_distance = (body.center_of_mass() - p_BoO_B).norm();
  top.gravity = model.gravity().norm();
  // The initial nutation angle and spin from the model's state.
  dynamics::Data data(model);
  State start{0.0, model.initial_q(), model.initial_v()};
  Mat3 R;
  Vec3 w;
  body_rotation(model, data, start, R, w);
  const double theta = std::acos(R(2, 2));
  const double spin = w[2];
  const double slow = rigid_body::steady_precession(top, theta, spin).slow;
  ASSERT_NEAR(theta, 20.0 * std::numbers::pi / 180, 1e-15);
  const double duration = 5.0;
  struct Case {
    std::string_view name;
    int order;
    double bound;
  };
  for (const Case& c :
       {Case{"splitting", 2, 2e-7}, Case{"splitting4", 4, 5e-14}, Case{"lie_group", 2, 5e-6}}) {
    SCOPED_TRACE(std::string(c.name));
    double errors[2];
    for (int i = 0; i < 2; ++i) {
      const double h = 1e-4 * (i + 1);
      MultibodySystem system(model);
      auto integrator = make_rigid_body_integrator(c.name);
      State state = start;
      integrator->initialize(system, state);
      // φ of the symmetry axis a = R e_z = (sin φ sin θ, −cos φ sin θ, cos θ), unwrapped.
      double phi = 0, worst_theta = 0;
      const long steps = std::lround(duration / h);
      for (long k = 1; k <= steps; ++k) {
        integrator->step(system, state, h);
        body_rotation(model, data, state, R, w);
        const double phi_now = std::atan2(R(0, 2), -R(1, 2));
        phi += std::remainder(phi_now - phi, 2 * std::numbers::pi);
        worst_theta = std::max(worst_theta, std::abs(std::acos(R(2, 2)) - theta));
      }
      const double rate = phi / duration;
      errors[i] = std::abs(rate - slow) / slow;
      RecordProperty(fmt::format("{}_h{}e-4_rate_error", c.name, i + 1),
                     fmt::format("{:.3g} (theta {:.3g})", errors[i], worst_theta));
      if (i == 0) {
        EXPECT_LT(errors[i], c.bound);
        EXPECT_LT(worst_theta, c.bound);
      }
    }
    if (errors[0] > 1e-12) {
      EXPECT_NEAR(std::log2(errors[1] / errors[0]), c.order, 0.3);
    }
  }
}

}  // namespace
}  // namespace momenta::simulate
