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
  SignalSample sample(double t) const;

 private:
  std::string name_;
  Shape shape_;
};

}  // namespace momenta::model
