#pragma once
// Controllers: feedback laws in the model. A controller reads measured coordinates of the model
// (through a sensor), computes a control law, and drives input signals (through an actuator) in
// place of their signals of time — the closed loop of docs/control.md. This header describes a
// controller; system/closed_loop_system.hpp runs it beside the mechanism.
//
// Kinds, with e = r − y the error of a reference r and the measured y:
//   pid             u = kp e + ki ∫e dt + kd ė. The derivative is the measured coordinate's own
//                   rate where y is a position-level coordinate and there is no filter (exact, no
//                   differencing), else filtered, kd s / (Tf s + 1) with Tf = derivative_filter.
//                   Anti-windup by conditional integration: while the actuator saturates and the
//                   error pushes further into saturation, the integral holds.
//   state_feedback  u = −K (x − x_ref) + u_ff, x the measured coordinates (the state a
//                   linearization orders: positions, then rates), K of size drives × measured.
//   linear          a state-space block ż = A z + B e, u = C z + D e from the error (or a
//                   transfer function num/den, realized in controllable canonical form).
//   external        u = law(t, q, v), a function the program running the model supplies
//                   (Python's simulate(model, controller=fn)): it reads the mechanism's whole
//                   state, has no states of its own in the run and measures nothing by name. Not
//                   in model files; not linearized.
//
// Sample time. 0: continuous — the controller's states are integrated with the mechanism's by the
// run's integrator. T > 0: discrete — the law runs at t = kT exactly (the integrator ends a step
// on every sample) and its output is held between samples (zero-order hold). Discrete forms
// (Åström & Murray, Feedback Systems, the PID chapter's "Implementation": the derivative by a
// backward difference, the integral from past errors):
//   pid      u_k = kp e_k + I_k + D_k,  D_k = (Tf D_{k−1} + kd (e_k − e_{k−1})) / (Tf + T),
//            I_{k+1} = I_k + ki T e_k  (I_0 = 0, e_{−1} = e_0; Tf = 0: D_k = kd (e_k − e_{k−1})/T);
//            anti-windup as above, the integral held at a sample that saturates further.
//   linear   u_k = C z_k + D e_k, then z_{k+1} = A z_k + B e_k (A, B, C, D in z).
//   state_feedback  u_k = −K (x_k − x_ref) + u_ff.
//
// Sensor: the reading ỹ = quantization · round((y + noise) / quantization), noise white and
// Gaussian with standard deviation `noise` drawn at each sample (seeded: runs repeat), taken
// `delay` samples ago. Noise and delay need a sample time. Actuator: u clamped to [min, max];
// with a sample time, |u_k − u_{k−1}| ≤ rate_limit · T.

#include <functional>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "momenta/math/types.hpp"
#include "momenta/model/output_spec.hpp"

namespace momenta::model {

class Model;

enum class ControllerKind { pid, state_feedback, linear, external };

/// The kind's name in files and messages ("pid", "state_feedback", "linear", "external").
const char* controller_kind_name(ControllerKind kind);

/// How the controller reads what it measures.
struct Sensor {
  double quantization = 0.0;  ///< resolution of the reading (the quantity's unit); 0: exact
  double noise = 0.0;         ///< standard deviation of the added white noise; 0: none
  int delay = 0;              ///< samples between taking a reading and using it
  unsigned seed = 1;          ///< the noise's random seed
};

/// What stands between the control law and the input it drives.
struct Actuator {
  double min = -std::numeric_limits<double>::infinity();  ///< saturation, the input's unit
  double max = std::numeric_limits<double>::infinity();
  double rate_limit = std::numeric_limits<double>::infinity();  ///< unit/s, discrete only
  bool saturates() const {
    return min > -std::numeric_limits<double>::infinity() ||
           max < std::numeric_limits<double>::infinity();
  }
};

struct PidGains {
  double kp = 0.0;
  double ki = 0.0;                 ///< 1/s times kp's unit
  double kd = 0.0;                 ///< s times kp's unit
  double derivative_filter = 0.0;  ///< Tf, s: the derivative's low-pass time constant
};

/// A linear block from the error e (one) to the output(s) u: ż = A z + B e (continuous) or
/// z⁺ = A z + B e (discrete), u = C z + D e.
struct LinearBlock {
  MatX A, B, C, D;
};

/// An external controller's law: the outputs u (one per driven input, before the actuator) at t
/// from the mechanism's state q (size nq), v (size nv). May throw; the run then stops with it.
using ControlLaw = std::function<void(double t, const VecX& q, const VecX& v, std::span<double> u)>;

struct Controller {
  std::string name;
  ControllerKind kind = ControllerKind::pid;
  /// s: 0 continuous, > 0 discrete with a zero-order hold.
  double sample_time = 0.0;
  /// What it measures: names of the model's coordinates (Model::q_name, v_name: "cart.position",
  /// "tilt.angle_rate") or of the outputs in measured_outputs. pid and linear: one;
  /// state_feedback: the state x.
  std::vector<std::string> measured;
  /// The model outputs (a model file's `outputs:` entries) a measured name may be, by their
  /// names (resolved, only those measured remain, each once): each one value (a component chosen
  /// where the quantity has several) of a quantity of the state alone — a joint's position or
  /// velocity, a body point's position or velocity, an angular velocity, Euler angles or rates, a
  /// spring's length or tension. Accelerations, efforts, reactions, constraint forces and signals
  /// depend on the inputs the loop sets (an algebraic loop) and are refused.
  std::vector<OutputSpec> measured_outputs;
  /// The signals it drives (the model's inputs). pid and linear: one; state_feedback: K's rows.
  /// A signal that prescribes a joint's coordinate (a revolute, prismatic, cylindrical, universal
  /// or planar joint's) is commanded: the output is that coordinate's acceleration (rad/s² or
  /// m/s²), the coordinate starting at the joint's q0 and v0 and integrated from there — a servo
  /// that moves its joint as told whatever the load, the drive's effort what `effort` outputs
  /// and --reactions report.
  std::vector<std::string> drives;
  /// pid and linear: the reference r, a signal's name, or empty for the constant `setpoint`.
  std::string reference;
  double setpoint = 0.0;
  PidGains pid;
  /// state_feedback: K (drives × measured), x_ref (size measured, zero when empty) and u_ff (size
  /// drives, zero when empty).
  MatX gain;
  VecX state_reference;
  VecX feedforward;
  LinearBlock block;
  /// external: the law (shared: copies of a model share it).
  std::shared_ptr<const ControlLaw> law;
  Sensor sensor;
  Actuator actuator;

  bool discrete() const { return sample_time > 0.0; }
};

/// The block realizing the transfer function num(s)/den(s) (or in z, for a discrete one):
/// coefficients highest power first, den's leading one non-zero, deg num ≤ deg den (proper). The
/// controllable canonical form (Franklin, Powell & Emami-Naeini §7.4). Throws InvalidArgument
/// naming `what` for an improper or empty one.
LinearBlock transfer_function_block(const std::vector<double>& num, const std::vector<double>& den,
                                    std::string_view what);

/// A controller with its names resolved against a built model (ModelBuilder::build makes these).
struct ResolvedController {
  Controller spec;
  /// Each measured quantity: an index into [q; v; outputs] — i < nq is q[i], i < nq + nv is
  /// v[i − nq], else spec.measured_outputs[i − nq − nv].
  std::vector<int> measured;
  /// pid without a filter on a position coordinate: the v index of its rate, else −1.
  int measured_rate = -1;
  std::vector<int> drives;  ///< signal indices
  int reference = -1;       ///< signal index, −1 for the setpoint
};

/// Checks `controller` against `model` and resolves its names. Throws InvalidArgument naming the
/// controller and the fault: a coordinate or signal the model lacks (did you mean), a drive of a
/// prescribed joint's signal, a sample time not positive and finite, gains or blocks of the
/// wrong size or not finite, a derivative without filter on a rate, noise, delay or a rate limit
/// without a sample time, min > max; an external one without a law, or with measured names or a
/// sensor (it reads the whole state as it is).
ResolvedController resolve_controller(const Controller& controller, const Model& model);

/// `controller` offered `outputs` (a model file's `outputs:`) to measure by name: resolving it
/// keeps those it measures (ResolvedController::spec) and names the others in a did-you-mean.
Controller with_measured_outputs(Controller controller, const std::vector<OutputSpec>& outputs);

/// Throws InvalidArgument when `model` already has a controller of `controller`'s name, or one
/// driving a signal it drives.
void check_controller_fits(const ResolvedController& controller, const Model& model);

}  // namespace momenta::model
