#include "momenta/integrate/bdf.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>
#include <cvode/cvode_proj.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/integrate/run.hpp"

namespace momenta::integrate {

namespace {
// The chart's base moves once a local coordinate passes 2.5 (rad): inside |δ| < π, where the
// difference back from a projected configuration is the same branch (difference() returns the
// shortest turn), and dexp⁻¹ is smooth.
constexpr double kLargestLocalCoordinate = 2.5;

// CVODE's name of a return flag ("CV_CONV_FAILURE"), which it hands over in memory of its own.
std::string flag_name(int flag) {
  char* name = CVodeGetReturnFlagName(flag);
  std::string text = name != nullptr ? name : "unknown";
  std::free(name);
  return text;
}
}  // namespace

// CVODE's memory and everything its callbacks read and write, allocated by initialize().
struct Bdf::Solver {
  SUNContext context = nullptr;
  void* cvode = nullptr;
  N_Vector y = nullptr;
  SUNMatrix jacobian = nullptr;
  SUNLinearSolver linear_solver = nullptr;

  SecondOrderSystem* system = nullptr;
  Tolerances tolerances;
  int nv = 0;
  VecX q_base;                          // the chart's base point q_b
  VecX q, delta, v, delta_rate, vdot;   // the callbacks' workspace
  VecX delta_base, v_base;              // the Jacobian's base point
  VecX scale;                           // configuration_scale of the weights
  State returned;                       // the state step() last returned
  IntegratorStatistics before_restart;  // counters of CVODE's earlier runs (reset by ReInit)
  long* evaluations = nullptr;          // Bdf::statistics_.evaluations
  bool restart_pending = false;         // a chart change or an input discontinuity was reached
  std::exception_ptr error;             // what the system threw inside a callback
  std::optional<UndefinedAcceleration> undefined;  // the last trial point with no acceleration
  std::string message;                             // CVODE's last error message

  ~Solver() {
    if (cvode != nullptr) CVodeFree(&cvode);
    if (linear_solver != nullptr) SUNLinSolFree(linear_solver);
    if (jacobian != nullptr) SUNMatDestroy(jacobian);
    if (y != nullptr) N_VDestroy(y);
    if (context != nullptr) SUNContext_Free(&context);
  }

  Eigen::Map<VecX> delta_of(N_Vector x) const { return {N_VGetArrayPointer(x), nv}; }
  Eigen::Map<VecX> v_of(N_Vector x) const { return {N_VGetArrayPointer(x) + nv, nv}; }

  // y = (δ, v): the rates (dexp⁻¹_δ v, a(t, q_b ⊕ δ, v)). A non-finite acceleration is a
  // recoverable failure (CVODE retries smaller); an exception is kept and stops CVODE.
  static int rates(double t, N_Vector y, N_Vector y_rate, void* data) {
    auto& s = *static_cast<Solver*>(data);
    try {
      s.delta = s.delta_of(y);
      s.v = s.v_of(y);
      s.system->integrate(s.q_base, s.delta, s.q);
      s.system->local_coordinate_rate(s.delta, s.v, s.delta_rate);
      s.system->acceleration(t, s.q, s.v, s.vdot);
      ++*s.evaluations;
      if (!s.vdot.allFinite() || !s.delta_rate.allFinite()) return 1;
      s.delta_of(y_rate) = s.delta_rate;
      s.v_of(y_rate) = s.vdot;
      return 0;
    } catch (const UndefinedAcceleration& e) {
      // Past a point where it has no value: recoverable too, kept to say if CVODE gives up.
      s.undefined = e;
      return 1;
    } catch (...) {
      s.error = std::current_exception();
      return -1;
    }
  }

  // The error weights 1 / (atol + rtol·scale): dopri5's scales (file comment).
  static int weights(N_Vector y, N_Vector weight, void* data) {
    auto& s = *static_cast<Solver*>(data);
    s.delta = s.delta_of(y);
    s.system->integrate(s.q_base, s.delta, s.q);
    s.system->configuration_scale(s.q, s.scale);
    const double atol = s.tolerances.absolute;
    const double rtol = s.tolerances.relative;
    s.delta_of(weight) = (atol + rtol * s.scale.array()).inverse().matrix();
    s.v_of(weight) = (atol + rtol * s.v_of(y).array().abs()).inverse().matrix();
    return N_VMin(weight) > 0.0 && std::isfinite(N_VMaxNorm(weight)) ? 0 : -1;
  }

  // The Jacobian ∂(δ̇, v̇)/∂(δ, v) at y, column by column: the δ̇ rows of the v columns exactly
  // (dexp⁻¹_δ is linear in v), the rest by forward differences with the probe √ε·max(1, |x|) —
  // CVODE's own difference quotients scale the probe by the tolerance instead, and near rest
  // (|v| ≪ atol) that probe falls below the round-off of a spring's stretch ℓ − ℓ0, so the
  // columns become noise and Newton's method fails (measured: 105 failures in 0.1 s of
  // examples/stiff_spring_damper.yaml at rtol 1e-5).
  static int jacobian_columns(double t, N_Vector y, N_Vector y_rate, SUNMatrix matrix, void* data,
                              N_Vector, N_Vector, N_Vector) {
    auto& s = *static_cast<Solver*>(data);
    try {
      const int n = s.nv;
      const double probe = std::sqrt(std::numeric_limits<double>::epsilon());
      const auto column = [&](int j) {
        return Eigen::Map<VecX>(SUNDenseMatrix_Column(matrix, j), 2 * n);
      };
      s.delta_base = s.delta_of(y);
      s.v_base = s.v_of(y);
      s.system->integrate(s.q_base, s.delta_base, s.q);
      s.system->configuration_scale(s.q, s.scale);
      for (int j = 0; j < n; ++j) {
        // Along δ_j.
        const double eps_q = probe * std::max(1.0, s.scale[j]);
        s.delta = s.delta_base;
        s.delta[j] += eps_q;
        s.system->integrate(s.q_base, s.delta, s.q);
        s.system->local_coordinate_rate(s.delta, s.v_base, s.delta_rate);
        s.system->acceleration(t, s.q, s.v_base, s.vdot);
        column(j).head(n) = (s.delta_rate - s.delta_of(y_rate)) / eps_q;
        column(j).tail(n) = (s.vdot - s.v_of(y_rate)) / eps_q;
        // Along v_j.
        const double eps_v = probe * std::max(1.0, std::abs(s.v_base[j]));
        s.v = s.v_base;
        s.v[j] += eps_v;
        s.system->integrate(s.q_base, s.delta_base, s.q);
        s.system->acceleration(t, s.q, s.v, s.vdot);
        s.v.setZero();
        s.v[j] = 1.0;
        s.system->local_coordinate_rate(s.delta_base, s.v, s.delta_rate);
        column(n + j).head(n) = s.delta_rate;
        column(n + j).tail(n) = (s.vdot - s.v_of(y_rate)) / eps_v;
      }
      *s.evaluations += 2L * n;
      const Eigen::Map<VecX> entries(SUNDenseMatrix_Data(matrix), 4 * n * n);
      return entries.allFinite() ? 0 : 1;       // non-finite: CVODE retries with a smaller step
    } catch (const UndefinedAcceleration& e) {  // a probe past it: as in rates()
      s.undefined = e;
      return 1;
    } catch (...) {
      s.error = std::current_exception();
      return -1;
    }
  }

  // CVODE's projection after every step (CVodeSetProjFn, the CPODES method of Eich 1993): the
  // system's own projection onto its constraints (SecondOrderSystem::project), handed back as
  // the correction of (δ, v). Keeps the BDF history on the constraints, so the caller's
  // projection of the returned state is a change within the tolerance, not a restart.
  static int projection(double t, N_Vector y, N_Vector correction, double, N_Vector, void* data) {
    auto& s = *static_cast<Solver*>(data);
    try {
      s.delta = s.delta_of(y);
      s.system->integrate(s.q_base, s.delta, s.q);
      s.v = s.v_of(y);
      if (!s.system->project(t, s.q, s.v)) {
        N_VConst(0.0, correction);
        return 0;
      }
      s.system->difference(s.q_base, s.q, s.delta_rate);  // δ of the projected configuration
      s.delta_of(correction) = s.delta_rate - s.delta_of(y);
      s.v_of(correction) = s.v - s.v_of(y);
      return 0;
    } catch (...) {
      s.error = std::current_exception();
      return -1;
    }
  }

  static void keep_message(int, const char*, const char*, char* message, void* data) {
    static_cast<Solver*>(data)->message = message;
  }

  // Fails with CVODE's flag name and message where a call returned an error.
  void check(int flag, const char* call) const {
    if (flag >= 0) return;
    throw NumericalError(
        fmt::format("bdf: CVODE's {} failed ({}): {}", call, flag_name(flag), message));
  }

  // CVODE's counters, which CVodeReInit resets.
  IntegratorStatistics counters() const {
    long steps = 0, error_test_failures = 0, newton_failures = 0;
    CVodeGetNumSteps(cvode, &steps);
    CVodeGetNumErrTestFails(cvode, &error_test_failures);
    CVodeGetNumNonlinSolvConvFails(cvode, &newton_failures);
    return {steps, error_test_failures + newton_failures, 0};
  }

  // The state y stands for, at time t.
  void read(N_Vector x, double t, State& state) {
    delta = delta_of(x);
    system->integrate(q_base, delta, state.q);
    state.v = v_of(x);
    state.t = t;
  }

  // A new chart at `state` (δ = 0) and a fresh BDF history there.
  void restart_at(const State& state) {
    const IntegratorStatistics now = counters();
    before_restart.steps += now.steps;
    before_restart.rejected_steps += now.rejected_steps;
    q_base = state.q;
    delta_of(y).setZero();
    v_of(y) = state.v;
    check(CVodeReInit(cvode, state.t, y), "CVodeReInit");
    returned = state;
    restart_pending = false;
  }

  // The weighted root-mean-square difference between `state` and the one last returned: ≤ 1
  // when the caller's change (a projection) is within the tolerances.
  double change_from_returned(const State& state) const {
    const double atol = tolerances.absolute;
    const double rtol = tolerances.relative;
    const auto squares = [&](const VecX& a, const VecX& b) {
      return ((a - b).array() / (atol + rtol * b.array().abs())).square().sum();
    };
    const double n = static_cast<double>(state.q.size() + state.v.size());
    return std::sqrt((squares(state.q, returned.q) + squares(state.v, returned.v)) / n);
  }
};

Bdf::Bdf(const Tolerances& tolerances) : tolerances_(tolerances) {
  check_tolerances(name(), tolerances);
}

Bdf::~Bdf() = default;

void Bdf::initialize(SecondOrderSystem& system, const State& state) {
  statistics_ = {};
  restarts_ = 0;
  solver_ = std::make_unique<Solver>();
  Solver& s = *solver_;
  s.system = &system;
  s.tolerances = tolerances_;
  s.nv = system.nv();
  s.evaluations = &statistics_.evaluations;
  for (VecX* x : {&s.delta, &s.v, &s.delta_rate, &s.vdot, &s.scale, &s.delta_base, &s.v_base}) {
    *x = VecX::Zero(s.nv);
  }
  s.q = VecX::Zero(system.nq());
  s.q_base = state.q;
  s.returned = state;
  if (s.nv == 0) return;  // nothing moves: step() only advances time

  if (SUNContext_Create(nullptr, &s.context) != 0) throw NumericalError("bdf: no SUNDIALS context");
  s.y = N_VNew_Serial(2 * s.nv, s.context);
  s.cvode = CVodeCreate(CV_BDF, s.context);
  s.jacobian = SUNDenseMatrix(2 * s.nv, 2 * s.nv, s.context);
  if (s.y == nullptr || s.cvode == nullptr || s.jacobian == nullptr) {
    throw NumericalError("bdf: SUNDIALS could not allocate the solver");
  }
  s.linear_solver = SUNLinSol_Dense(s.y, s.jacobian, s.context);
  s.check(CVodeSetErrHandlerFn(s.cvode, &Solver::keep_message, &s), "CVodeSetErrHandlerFn");
  s.delta_of(s.y).setZero();
  s.v_of(s.y) = state.v;
  s.check(CVodeInit(s.cvode, &Solver::rates, state.t, s.y), "CVodeInit");
  s.check(CVodeSetUserData(s.cvode, &s), "CVodeSetUserData");
  s.check(CVodeWFtolerances(s.cvode, &Solver::weights), "CVodeWFtolerances");
  s.check(CVodeSetLinearSolver(s.cvode, s.linear_solver, s.jacobian), "CVodeSetLinearSolver");
  s.check(CVodeSetJacFn(s.cvode, &Solver::jacobian_columns), "CVodeSetJacFn");
  s.check(CVodeSetProjFn(s.cvode, &Solver::projection), "CVodeSetProjFn");
  s.check(CVodeSetProjErrEst(s.cvode, SUNFALSE), "CVodeSetProjErrEst");
  // integrate::run bounds the whole run's steps; CVODE's own default (500 per call) would stop a
  // long output interval of a stiff model.
  s.check(CVodeSetMaxNumSteps(s.cvode, static_cast<long>(kMaxRunSteps)), "CVodeSetMaxNumSteps");
  s.check(CVodeSetMaxHnilWarns(s.cvode, -1), "CVodeSetMaxHnilWarns");
  // A jump in the acceleration that is no event is crossed by shrinking the steps that straddle
  // it; CVODE's default of 7 failed error tests of one step gave up on the MuJoCo arm's rocking.
  s.check(CVodeSetMaxErrTestFails(s.cvode, 20), "CVodeSetMaxErrTestFails");
}

double Bdf::step(SecondOrderSystem& system, State& state, double h_max) {
  if (!(h_max > 0.0)) {
    throw InvalidArgument(fmt::format("bdf: the step limit must be positive, got {}", h_max));
  }
  if (!solver_) throw InvalidArgument("bdf: step() before initialize()");
  Solver& s = *solver_;
  s.system = &system;
  const double t_start = state.t;
  const double t_out = state.t + h_max;
  if (s.nv == 0) {
    state.t = t_out;
    return h_max;
  }

  // A state other than the one returned (a projection beyond the tolerance, an edit), a chart
  // far from its base, or an input discontinuity just reached: start afresh from `state`.
  // (integrate::run may round the time it was handed to its grid: an ulp is no change.)
  const bool same_time =
      std::abs(state.t - s.returned.t) <= 1e-12 * std::max(1.0, std::abs(state.t));
  if (s.restart_pending || !same_time || s.change_from_returned(state) > 1.0) {
    s.restart_at(state);
    ++restarts_;
  }

  // No step straddles the next input discontinuity: CVODE stops on it.
  const double t_break = system.next_discontinuity(state.t);
  const bool stops_on_break = t_break <= t_out;
  s.check(
      CVodeSetStopTime(s.cvode, stops_on_break ? t_break : std::numeric_limits<double>::infinity()),
      "CVodeSetStopTime");
  system.begin_step(state.t, stops_on_break ? t_break : std::numeric_limits<double>::infinity());
  // Steps below the resolution of time fail instead of creeping on forever (towards a point where
  // the acceleration stops being finite, say).
  const double smallest_step =
      16.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(t_out));
  s.check(CVodeSetMinStep(s.cvode, smallest_step), "CVodeSetMinStep");
  // Where CVODE gives up on trial points with no acceleration (Painlevé's point of a sliding
  // contact, say) short of them, it integrates again from the start to halfway to the last point it
  // reached and hands that back: the caller looks there for an event before them (a slip that
  // stops), with the step's interpolant sound away from the point, and the next step goes on from
  // there. Where no step gets on from the start, the motion reaches the point: it throws.
  double t_target = stops_on_break ? t_break : t_out;
  double t_reached = state.t;
  int flag = CVode(s.cvode, t_target, s.y, &t_reached, CV_NORMAL);
  while (flag < 0 && s.undefined && !s.error && t_reached > t_start) {
    s.undefined.reset();
    t_target = t_start + 0.5 * (t_reached - t_start);
    s.restart_at(state);
    ++restarts_;
    s.check(CVodeSetStopTime(s.cvode, t_target), "CVodeSetStopTime");
    flag = CVode(s.cvode, t_target, s.y, &t_reached, CV_NORMAL);
  }
  if (s.error) std::rethrow_exception(std::exchange(s.error, nullptr));
  if (flag < 0 && s.undefined) {
    throw UndefinedAcceleration(
        fmt::format("{} (the motion reaches it: bdf's steps from t = {:.9g} s all met it, {})",
                    std::exchange(s.undefined, std::nullopt)->what(), t_reached, flag_name(flag)));
  }
  s.undefined.reset();
  if (flag < 0) {
    throw NumericalError(fmt::format(
        "bdf: CVODE stopped at t = {:.9g} s ({}): {}. The model may be singular there, or the "
        "tolerances (rtol = {}, atol = {}) too tight",
        t_reached, flag_name(flag), s.message, tolerances_.relative, tolerances_.absolute));
  }

  s.read(s.y, t_target, state);
  const IntegratorStatistics now = s.counters();
  statistics_.steps = s.before_restart.steps + now.steps;
  statistics_.rejected_steps = s.before_restart.rejected_steps + now.rejected_steps;
  s.returned = state;
  s.restart_pending =
      (stops_on_break && t_target == t_break) ||
      (system.nq() != s.nv && s.delta.cwiseAbs().maxCoeff() > kLargestLocalCoordinate);
  return state.t - t_start;
}

}  // namespace momenta::integrate
