#include "momenta/model/signal.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta::model {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
// (Spelled out for clang 14, which has no aggregate deduction.)
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

void require(bool ok, const std::string& name, const std::string& what) {
  if (!ok) throw InvalidArgument(fmt::format("signal '{}': {}", name, what));
}

// Checks one shape's parameters.
struct Validator {
  const std::string& name;
  void operator()(const ConstantSignal& s) const {
    require(std::isfinite(s.value), name, "value is not finite");
  }
  void operator()(const StepSignal& s) const {
    require(std::isfinite(s.start) && std::isfinite(s.initial) && std::isfinite(s.final), name,
            "step start, initial and final must be finite");
    require(s.rise_time >= 0 && std::isfinite(s.rise_time), name,
            fmt::format("rise_time {} must be zero or positive", s.rise_time));
  }
  void operator()(const RampSignal& s) const {
    require(std::isfinite(s.start) && std::isfinite(s.slope) && std::isfinite(s.offset), name,
            "ramp start, slope and offset must be finite");
    require(s.stop > s.start, name,
            fmt::format("ramp stop {} must be after start {}", s.stop, s.start));
  }
  void operator()(const PulseSignal& s) const {
    require(s.width > 0 && std::isfinite(s.width), name,
            fmt::format("pulse width {} s must be positive", s.width));
    require(s.period == 0 || s.period > s.width, name,
            fmt::format("pulse period {} s must be 0 (one pulse) or longer than its width {} s",
                        s.period, s.width));
    require(std::isfinite(s.start) && std::isfinite(s.amplitude) && std::isfinite(s.offset), name,
            "pulse start, amplitude and offset must be finite");
  }
  void operator()(const SineSignal& s) const {
    require(std::isfinite(s.amplitude) && std::isfinite(s.frequency) && std::isfinite(s.phase) &&
                std::isfinite(s.offset) && std::isfinite(s.start),
            name, "sine parameters must be finite");
    require(s.frequency >= 0, name, fmt::format("sine frequency {} Hz is negative", s.frequency));
  }
  void operator()(const ChirpSignal& s) const {
    require(s.duration > 0 && std::isfinite(s.duration), name,
            fmt::format("chirp duration {} s must be positive", s.duration));
    require(s.f0 >= 0 && s.f1 >= 0 && std::isfinite(s.f0) && std::isfinite(s.f1), name,
            fmt::format("chirp frequencies {} Hz and {} Hz must be non-negative", s.f0, s.f1));
  }
  void operator()(const TableSignal& s) const {
    require(s.times.size() == s.values.size(), name,
            fmt::format("table has {} times but {} values", s.times.size(), s.values.size()));
    require(!s.times.empty(), name, "table is empty");
    for (std::size_t i = 0; i < s.times.size(); ++i) {
      require(std::isfinite(s.times[i]) && std::isfinite(s.values[i]), name,
              fmt::format("table row {} is not finite", i + 1));
      // The message reads times[i − 1], so it is only formatted for i > 0.
      if (i > 0) {
        require(s.times[i] > s.times[i - 1], name,
                fmt::format("table times must increase strictly: row {} has t = {} after t = {}",
                            i + 1, s.times[i], s.times[i - 1]));
      }
    }
  }
};

// Whether t lies in the piece before the breakpoint a: strictly for the right limit (at a itself
// the piece starting there applies), inclusively for the left limit (the piece ending there).
bool before(double t, double a, Limit limit) { return limit == Limit::right ? t < a : t <= a; }

// The smallest of the candidates that is strictly after t; +infinity if none is.
double first_after(double t, std::initializer_list<double> candidates) {
  double next = std::numeric_limits<double>::infinity();
  for (double c : candidates) {
    if (c > t) next = std::min(next, c);
  }
  return next;
}

SignalSample sample_step(const StepSignal& s, double t, Limit limit) {
  const double jump = s.final - s.initial;
  if (before(t, s.start, limit)) return {s.initial, 0, 0};
  if (s.rise_time == 0 || !before(t, s.start + s.rise_time, limit)) return {s.final, 0, 0};
  // Quintic smoothstep h(x) = 10x³ − 15x⁴ + 6x⁵ on x = (t − start) / rise_time.
  const double T = s.rise_time;
  const double x = (t - s.start) / T;
  const double h = x * x * x * (10 + x * (-15 + 6 * x));
  const double dh = 30 * x * x * (1 - x) * (1 - x);
  const double ddh = 60 * x * (1 - x) * (1 - 2 * x);
  return {s.initial + jump * h, jump * dh / T, jump * ddh / (T * T)};
}

SignalSample sample_table(const TableSignal& s, double t, Limit limit) {
  if (before(t, s.times.front(), limit) || s.times.size() == 1) return {s.values.front(), 0, 0};
  if (!before(t, s.times.back(), limit)) return {s.values.back(), 0, 0};
  // The segment holding t: [times[i-1], times[i]) for the right limit, (times[i-1], times[i]]
  // for the left.
  const auto it = limit == Limit::right ? std::upper_bound(s.times.begin(), s.times.end(), t)
                                        : std::lower_bound(s.times.begin(), s.times.end(), t);
  const std::size_t i = static_cast<std::size_t>(it - s.times.begin());
  const double slope = (s.values[i] - s.values[i - 1]) / (s.times[i] - s.times[i - 1]);
  return {s.values[i - 1] + slope * (t - s.times[i - 1]), slope, 0};
}

}  // namespace

Signal::Signal(std::string name, Shape shape) : name_(std::move(name)), shape_(std::move(shape)) {
  std::visit(Validator{name_}, shape_);
}

SignalSample Signal::sample(double t, Limit limit) const {
  return std::visit(Overloaded{
                        [](const ConstantSignal& s) {
                          return SignalSample{s.value, 0, 0};
                        },
                        [&](const StepSignal& s) { return sample_step(s, t, limit); },
                        [&](const RampSignal& s) {
                          if (before(t, s.start, limit)) return SignalSample{s.offset, 0, 0};
                          if (!before(t, s.stop, limit)) {
                            return SignalSample{s.offset + s.slope * (s.stop - s.start), 0, 0};
                          }
                          return SignalSample{s.offset + s.slope * (t - s.start), s.slope, 0};
                        },
                        [&](const PulseSignal& s) {
                          double phase = t - s.start;
                          if (s.period > 0 && phase > 0) {
                            phase = std::fmod(phase, s.period);
                            // The left limit at a period boundary belongs to the previous period's
                            // end.
                            if (limit == Limit::left && phase == 0) phase = s.period;
                          }
                          const bool on = !before(phase, 0, limit) && before(phase, s.width, limit);
                          return SignalSample{s.offset + (on ? s.amplitude : 0.0), 0, 0};
                        },
                        [&](const SineSignal& s) {
                          if (before(t, s.start, limit)) {
                            return SignalSample{s.offset + s.amplitude * std::sin(s.phase), 0, 0};
                          }
                          const double w = kTwoPi * s.frequency;
                          const double angle = w * (t - s.start) + s.phase;
                          return SignalSample{s.offset + s.amplitude * std::sin(angle),
                                              s.amplitude * w * std::cos(angle),
                                              -s.amplitude * w * w * std::sin(angle)};
                        },
                        [&](const ChirpSignal& s) {
                          const double tau = t - s.start;
                          if (before(tau, 0, limit) || !before(tau, s.duration, limit)) {
                            return SignalSample{0, 0, 0};
                          }
                          // Phase φ(τ) = 2π (f0 τ + k τ²/2), k = (f1 − f0) / duration.
                          const double k = (s.f1 - s.f0) / s.duration;
                          const double phi = kTwoPi * (s.f0 * tau + 0.5 * k * tau * tau);
                          const double dphi = kTwoPi * (s.f0 + k * tau);
                          const double ddphi = kTwoPi * k;
                          const double A = s.amplitude;
                          return SignalSample{
                              A * std::sin(phi), A * dphi * std::cos(phi),
                              A * (ddphi * std::cos(phi) - dphi * dphi * std::sin(phi))};
                        },
                        [&](const TableSignal& s) { return sample_table(s, t, limit); },
                    },
                    shape_);
}

double Signal::next_breakpoint(double t) const {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  return std::visit(Overloaded{
                        [](const ConstantSignal&) { return kNone; },
                        [t](const StepSignal& s) {
                          return first_after(t, {s.start, s.start + s.rise_time});
                        },
                        [t](const RampSignal& s) {
                          return first_after(t, {s.start, s.stop});
                        },
                        [t](const PulseSignal& s) {
                          if (s.period == 0 || t < s.start)
                            return first_after(t, {s.start, s.start + s.width});
                          // The edges of the period holding t and the next period's rising edge.
                          const double k = std::floor((t - s.start) / s.period);
                          const double begin = s.start + k * s.period;
                          return first_after(t, {begin, begin + s.width, begin + s.period,
                                                 begin + s.period + s.width});
                        },
                        [t](const SineSignal& s) { return first_after(t, {s.start}); },
                        [t](const ChirpSignal& s) {
                          return first_after(t, {s.start, s.start + s.duration});
                        },
                        [t](const TableSignal& s) {
                          const auto it = std::upper_bound(s.times.begin(), s.times.end(), t);
                          return it == s.times.end() ? kNone : *it;
                        },
                    },
                    shape_);
}

}  // namespace momenta::model
