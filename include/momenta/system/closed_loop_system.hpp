#pragma once
// A model with feedback controllers (model/controller.hpp) as the system the integrators advance:
// the mechanism (a MultibodySystem) and its controllers, in one state.
//
// State. The integrators advance second-order systems (q̇ = "v", v̇ = a), and a controller's
// continuous states z obey first-order equations ż = f(t, q, v, z). Each z is carried as a
// velocity coordinate whose "acceleration" is f — so every integrator, its error control and
// dense output treat it as they treat the mechanism — with the configuration coordinate beside
// it its time integral, which nothing reads:
//   q = [q_plant; ∫z dt],  v = [v_plant; z],  v̇ = [a(t, q, v, u); f(t, q, v, z)].
// Continuous states, in controller order: a pid's `integral` (the term ki ∫e dt, in the driven
// input's unit) where ki ≠ 0 and its derivative `filter` where kd ≠ 0 and Tf > 0; a linear block's
// z1 … zn.
//
// Measured outputs (Controller::measured_outputs: a body point's position, a spring's length)
// are evaluated on a second MultibodySystem of the model (its inputs zero: they are quantities of
// the state alone) once per evaluation, before the laws read them.
//
// Discrete controllers (sample time T) run at t = kT exactly: next_discontinuity() makes the
// integrator end a step on each sample, and project() — called after every step — takes the
// sample: reads the sensors, advances the law, holds the output until the next sample. Their
// states (the held output, a pid's integral and derivative terms and last error, a block's z, the
// delay line) are kept here, with the values before the latest sample, so that a state
// interpolated inside the last step (an event's) sees the output that acted there.

#include <memory>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "momenta/integrate/integrator.hpp"
#include "momenta/model/controller.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta/system/output_set.hpp"

namespace momenta::system {

class ClosedLoopSystem final : public integrate::SecondOrderSystem {
 public:
  /// The closed loop of `plant`'s model and its controllers; keeps a reference to `plant`.
  explicit ClosedLoopSystem(MultibodySystem& plant);

  MultibodySystem& plant() { return plant_; }
  const model::Model& model() const { return plant_.model(); }
  /// Number of continuous controller states (z).
  int num_controller_states() const { return nz_; }

  int nq() const override { return plant_.nq() + nz_; }
  int nv() const override { return plant_.nv() + nz_; }

  /// The state the run starts from at t0: the plant's (q, v) followed by the controllers'
  /// continuous states (integrals zero, a derivative filter at the error, so it starts without a
  /// kick; a block's z zero). Resets every discrete controller and takes its sample at t0.
  integrate::State start(double t0, const VecX& q, const VecX& v);

  void acceleration(double t, const VecX& q, const VecX& v, VecX& vdot) override;
  void integrate(const VecX& q, const VecX& dq, VecX& q_out) const override;
  void difference(const VecX& q0, const VecX& q1, VecX& dq) const override;
  void local_coordinate_rate(const VecX& delta, const VecX& v, VecX& delta_rate) const override;
  void configuration_scale(const VecX& q, VecX& scale) const override;
  /// The plant's next input discontinuity or the next sample of a discrete controller.
  double next_discontinuity(double t) const override;
  void begin_step(double t0, double t1) override;
  /// The plant's projection, then the sample of every discrete controller due at t. True when
  /// either changed anything.
  bool project(double t, VecX& q, VecX& v) override;
  std::string coordinate_name(int i, bool velocity) const override;

  /// What record() writes, per controller in model order: its outputs `<controller>.<input>`
  /// (after the actuator; all an external one writes); for pid and linear `<controller>.reference`
  /// and `<controller>.error` (as the sensor reads it); its states, `<controller>.integral`,
  /// `.filter` (continuous pid),
  /// `.derivative`, `.last_error` (discrete pid), `.z1` … (block).
  const std::vector<std::string>& column_names() const { return columns_; }
  /// Each column's unit: the driven input's where known, else "".
  const std::vector<std::string>& column_units() const { return units_; }
  /// The columns at the run's state (t, q, v) (sizes nq(), nv()); also sets the plant's driven
  /// inputs to the outputs there, so that its evaluations that follow see them. No allocation.
  void record(double t, const VecX& q, const VecX& v, std::span<double> out);

 private:
  // One controller at run time.
  struct Discrete {
    std::vector<double> held;  // the output held since the last sample
    double integral = 0.0, derivative = 0.0, last_error = 0.0;
    VecX z;
  };
  struct Loop {
    const model::ResolvedController* c = nullptr;
    int z = 0;          // offset of its continuous states in the controller part of v
    int integral = -1;  // continuous pid: offsets (relative to z) of its states, or −1
    int filter = -1;
    int nz = 0;
    // Discrete: the next sample's index, the latest sample's time, the states now and before it.
    long next_sample = 0;
    double last_sample = 0.0;
    Discrete now, before;
    std::vector<double> delay_line;  // the last `delay` readings of each measured quantity
    std::mt19937_64 noise_source;
    VecX readings;    // scratch: one reading per measured quantity
    int outputs = 0;  // offset of its measured outputs in outputs_'s columns
  };

  // The measured quantity i of `loop` at the plant state (q, v): exact, then quantized.
  double measure(const Loop& loop, int i, const VecX& q, const VecX& v) const;
  // The reference at t (the setpoint, or its signal's value and rate).
  model::SignalSample reference(const Loop& loop, double t, model::Limit limit) const;
  // A continuous controller's outputs (into u) and its states' rates (into zdot), at (t, q, v, z).
  void continuous_law(Loop& loop, double t, model::Limit limit, const VecX& q, const VecX& v,
                      const VecX& z, std::span<double> u, std::span<double> zdot) const;
  // Sets the plant's driven inputs at (t, q, v) and z_ (the plant's parts of the state), and the
  // continuous controllers' state rates into zdot_.
  void drive_plant(double t, const VecX& q, const VecX& v);
  // One controller's outputs at (t, q, v, z_) into u_ (a continuous one's state rates into
  // zdot_), set on the plant's driven inputs.
  void drive(Loop& loop, double t, model::Limit limit, const VecX& q, const VecX& v);
  // An external controller's law at (t, q, v) into u, saturated; NumericalError for an output
  // that is not finite.
  void external_law(const Loop& loop, double t, const VecX& q, const VecX& v,
                    std::span<double> u) const;
  // A discrete controller's sample at t_k: readings, law, actuator, held output.
  void take_sample(Loop& loop, double t_k, const VecX& q, const VecX& v);
  // Saturation.
  double saturate(const Loop& loop, double u) const;
  // The discrete states in force at t (before the latest sample when t precedes it).
  const Discrete& discrete_at(const Loop& loop, double t) const;
  // Evaluates the measured outputs at the plant state (t, q, v) into output_values_ (nothing
  // without measured outputs).
  void measure_outputs(double t, const VecX& q, const VecX& v);
  // Copies the plant's parts of an augmented (q, v) into q_, v_ and the controllers' into z_.
  void split(const VecX& q, const VecX& v) const;

  MultibodySystem& plant_;
  std::vector<Loop> loops_;
  // Measured outputs: every controller's, in controller order, and the system they are read on
  // (both null without any).
  std::unique_ptr<MultibodySystem> measuring_;
  std::unique_ptr<OutputSet> outputs_;
  std::vector<double> output_values_;
  int nz_ = 0;
  bool vector_space_ = false;  // the plant has no quaternions: q ⊕ dq = q + dq throughout
  double step_end_ = 0.0;
  std::vector<std::string> columns_, units_, state_names_;
  // Scratch (mutable: the const overrides split their arguments too).
  mutable VecX q_, v_, z_, dq_, out_q_, vdot_, zdot_;
  std::vector<double> u_;
};

}  // namespace momenta::system
