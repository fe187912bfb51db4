#pragma once
// One-step integrators of a SecondOrderSystem, chosen by name.
//
//   rk4              classic fourth-order Runge–Kutta, fixed step (Munthe-Kaas form on rotations)
//   symplectic_euler semi-implicit Euler: v ← v + h a(q, v); q ← q ⊕ h v. First order, symplectic
//                    for separable conservative systems
//   dopri5           Dormand–Prince 5(4), adaptive step with error control and dense output
//
// Each integrator is sized once by initialize(); step() then never allocates.

#include <limits>
#include <memory>
#include <string_view>
#include <vector>

#include "momenta/integrate/second_order_system.hpp"

namespace momenta::integrate {

/// The state integrators advance.
struct State {
  double t = 0.0;
  VecX q;  ///< configuration, size nq
  VecX v;  ///< velocity, size nv
};

/// Counters every integrator keeps.
struct IntegratorStatistics {
  long steps = 0;           ///< accepted steps
  long rejected_steps = 0;  ///< steps retried with a smaller size (adaptive methods)
  long evaluations = 0;     ///< calls of SecondOrderSystem::acceleration
  /// Explicit adaptive methods (dopri5): accepted steps whose size stability set, not accuracy —
  /// Hairer's estimate h|λ| of the dominant eigenvalue along the step (Hairer & Wanner, Solving
  /// ODEs II, §IV.2) at or past the edge of the stability region (3.25 for dopri5).
  long stability_limited_steps = 0;
  /// The time from which 15 steps in a row were stability-limited (Hairer's test for "the
  /// problem seems to become stiff"); NaN when that never happened.
  double stiff_from = std::numeric_limits<double>::quiet_NaN();
  /// The largest |λ| (1/s) of those estimates.
  double stiff_eigenvalue = 0.0;
};

class Integrator {
 public:
  virtual ~Integrator() = default;

  /// The name it is chosen by ("rk4", ...).
  virtual std::string_view name() const = 0;
  /// Order of accuracy of the solution it returns.
  virtual int order() const = 0;
  /// True when step() chooses its own step size.
  virtual bool adaptive() const { return false; }

  /// Sizes the workspace for `system` and starts at `state` (allocates; call before stepping).
  virtual void initialize(SecondOrderSystem& system, const State& state) = 0;

  /// Advances `state` by one step and returns the size taken. Fixed-step methods take exactly
  /// `h`; adaptive ones take the step their error control accepts, never longer than `h` (so a
  /// caller can land on output times). Throws NumericalError when it cannot continue (step size
  /// underflow).
  virtual double step(SecondOrderSystem& system, State& state, double h) = 0;

  /// True when interpolate() gives the state inside the last step from the method's own dense
  /// output (dopri5's, of order four); the others leave it to StepInterpolant's cubic Hermite
  /// interpolation (integrate/step_interpolant.hpp).
  virtual bool has_dense_output() const { return false; }
  /// The state at t within the last step taken, from the dense output, before any projection
  /// (has_dense_output() only; the default throws std::logic_error).
  virtual void interpolate(const SecondOrderSystem& system, double t, State& out) const;

  /// The state was changed between steps (projected onto constraints): forget anything kept
  /// from the last step's end (dopri5's first-same-as-last derivative). The default keeps nothing.
  virtual void state_changed() {}

  const IntegratorStatistics& statistics() const { return statistics_; }

 protected:
  IntegratorStatistics statistics_;
};

/// The tightest tolerances an adaptive method accepts: a relative error below 100 ε cannot be
/// delivered in double precision (the error estimate is round-off there, and the step shrinks
/// until time stops advancing); an absolute error below 1e-200 overflows the error's square.
inline constexpr double kSmallestRelativeTolerance = 100 * 2.220446049250313e-16;
inline constexpr double kSmallestAbsoluteTolerance = 1e-200;

/// Tolerances of adaptive methods: per-component error scale atol + rtol·|x|.
struct Tolerances {
  double relative = 1e-8;
  double absolute = 1e-10;
};

/// Throws InvalidArgument when `tolerances` are not positive and finite, or ask for more than
/// double precision holds (kSmallestRelativeTolerance, kSmallestAbsoluteTolerance), naming the
/// integrator.
void check_tolerances(std::string_view integrator, const Tolerances& tolerances);

/// A new integrator of this folder by name (the general family of model/integrators.hpp, the one
/// list of names: rk4, symplectic_euler, dopri5, bdf, sdirk3); throws InvalidArgument for any other
/// name, or when a tolerance is not positive and finite. Front ends build integrators with
/// system::make_integrator, which asks the registry (with a did-you-mean for a misspelt name).
std::unique_ptr<Integrator> make_integrator(std::string_view name,
                                            const Tolerances& tolerances = {});

}  // namespace momenta::integrate
