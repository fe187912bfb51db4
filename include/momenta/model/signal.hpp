#pragma once
// Input signals u(t): what drives applied forces and torques, and the motion of prescribed joints.
//
// A Signal is a small value type (no virtual calls, no allocation when evaluated) holding one of
// the standard shapes. Prescribed joints need q(t), q̇(t) and q̈(t), so every shape gives its first
// two derivatives; where a shape has a corner or a jump (a step, a ramp's start, a table's
// breakpoints) the derivatives are those of the piece t lies in — give a step a `rise_time` to make
// it smooth (a C² quintic blend) when its derivatives matter.

#include <limits>
#include <string>
#include <variant>
#include <vector>

namespace momenta::model {

/// u(t) = value.
struct ConstantSignal {
  double value = 0.0;
};

/// initial before start, final after start + rise_time; with rise_time > 0 the two are joined
/// by the quintic smoothstep 10s³ − 15s⁴ + 6s⁵ (zero first and second derivatives at both ends).
struct StepSignal {
  double start = 0.0;
  double initial = 0.0;
  double final = 1.0;
  double rise_time = 0.0;
};

/// offset + slope · (t − start) for t > start, offset before; with a finite `stop` the value holds
/// after stop.
struct RampSignal {
  double start = 0.0;
  double slope = 1.0;
  double offset = 0.0;
  double stop = std::numeric_limits<double>::infinity();
};

/// offset + amplitude while start <= t < start + width (repeating every `period` if period > 0).
struct PulseSignal {
  double start = 0.0;
  double width = 1.0;
  double amplitude = 1.0;
  double offset = 0.0;
  double period = 0.0;
};

/// offset + amplitude · sin(2π f (t − start) + phase) for t >= start, offset + amplitude ·
/// sin(phase) before. f in Hz, phase in rad.
struct SineSignal {
  double amplitude = 1.0;
  double frequency = 1.0;
  double phase = 0.0;
  double offset = 0.0;
  double start = 0.0;
};

/// Linear chirp: amplitude · sin(2π (f0 τ + (f1 − f0) τ² / (2 duration))) with τ = t − start, for
/// 0 <= τ <= duration, zero outside. Frequencies in Hz.
struct ChirpSignal {
  double amplitude = 1.0;
  double f0 = 0.1;
  double f1 = 10.0;
  double start = 0.0;
  double duration = 10.0;
};

/// Piecewise-linear through (times[i], values[i]), times strictly increasing; holds the end values
/// outside the table.
struct TableSignal {
  std::vector<double> times;
  std::vector<double> values;
};

/// Which side a signal is sampled from at a breakpoint (where it, or a derivative, jumps).
enum class Limit {
  right,  ///< The piece that starts at t: u(t⁺). What sample(t) returns by default.
  left,   ///< The piece that ends at t: u(t⁻). What an integration step ending at t integrated.
};

/// Value and first two time derivatives of a signal at one instant.
struct SignalSample {
  double value;
  double rate;
  double acceleration;
};

class Signal {
 public:
  using Shape = std::variant<ConstantSignal, StepSignal, RampSignal, PulseSignal, SineSignal,
                             ChirpSignal, TableSignal>;

  /// Checks the shape's parameters (durations positive, table increasing and finite, ...) and
  /// throws InvalidArgument naming `name` and the offending parameter otherwise.
  Signal(std::string name, Shape shape);

  const std::string& name() const { return name_; }
  const Shape& shape() const { return shape_; }

  double value(double t) const { return sample(t).value; }
  /// Value, rate and acceleration at t. Away from breakpoints both limits agree; at a breakpoint
  /// `limit` chooses the piece (right: the one starting at t; left: the one ending there).
  SignalSample sample(double t, Limit limit = Limit::right) const;

  /// The first breakpoint strictly after t: a time where the value or one of its first two
  /// derivatives jumps — a step's start (and the end of its rise), a ramp's start and stop, a
  /// pulse's edges, a sine's start, a chirp's start and end, a table's times. +infinity when
  /// there is none. Integrators end a step on each (integrate/run.hpp), so that no step straddles
  /// a jump and the methods keep their order.
  double next_breakpoint(double t) const;

 private:
  std::string name_;
  Shape shape_;
};

}  // namespace momenta::model
