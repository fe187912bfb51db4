#include "momenta/system/closed_loop_system.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/model/units.hpp"

namespace momenta::system {

using model::ControllerKind;

namespace {

// Two sample instants within round-off of each other (the run lands steps on samples exactly,
// but a projection sees the step's end before it is snapped onto the target).
bool same_instant(double a, double b) {
  return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b));
}

}  // namespace

ClosedLoopSystem::ClosedLoopSystem(MultibodySystem& plant) : plant_(plant) {
  const model::Model& m = plant.model();
  // The measured outputs, every controller's in order, each one column (resolve_controller).
  std::vector<model::OutputSpec> measured;
  for (const model::ResolvedController& c : m.controllers()) {
    measured.insert(measured.end(), c.spec.measured_outputs.begin(), c.spec.measured_outputs.end());
  }
  if (!measured.empty()) {
    outputs_ = std::make_unique<OutputSet>(m, measured);
    measuring_ = std::make_unique<MultibodySystem>(m);
    output_values_.assign(outputs_->size(), 0.0);
  }
  int output_offset = 0;
  for (const model::ResolvedController& c : m.controllers()) {
    Loop loop;
    loop.c = &c;
    loop.z = nz_;
    loop.outputs = output_offset;
    output_offset += static_cast<int>(c.spec.measured_outputs.size());
    const model::Controller& s = c.spec;
    const std::size_t drives = c.drives.size();
    const auto name = [&](std::string_view what) { return fmt::format("{}.{}", s.name, what); };
    // Outputs, reference and error first, then the states.
    for (std::size_t i = 0; i < drives; ++i) {
      columns_.push_back(name(m.signals()[static_cast<std::size_t>(c.drives[i])].name()));
      units_.push_back(model::signal_unit(m, c.drives[i]));
    }
    const bool follows_reference =
        s.kind == ControllerKind::pid || s.kind == ControllerKind::linear;
    const int y = follows_reference ? c.measured[0] : 0;
    const std::string error_unit =
        !follows_reference ? ""
        : y < m.nq()       ? model::q_unit(m, y)
        : y < m.nq() + m.nv()
            ? model::v_unit(m, y - m.nq())
            : outputs_
                  ->column_units()[static_cast<std::size_t>(loop.outputs + y - m.nq() - m.nv())];
    if (follows_reference) {
      columns_.push_back(name("reference"));
      columns_.push_back(name("error"));
      units_.push_back(error_unit);
      units_.push_back(error_unit);
    }
    const std::string u_unit = model::signal_unit(m, c.drives[0]);
    const auto state = [&](std::string_view what, const std::string& unit, bool continuous) {
      columns_.push_back(name(what));
      units_.push_back(unit);
      if (continuous) state_names_.push_back(name(what));
    };
    const bool continuous = !s.discrete();
    if (s.kind == ControllerKind::pid) {
      if (continuous) {
        if (s.pid.ki != 0.0) {
          loop.integral = loop.nz++;
          state("integral", u_unit, true);
        }
        if (s.pid.kd != 0.0 && s.pid.derivative_filter > 0.0) {
          loop.filter = loop.nz++;
          state("filter", error_unit, true);
        }
      } else {
        state("integral", u_unit, false);
        state("derivative", u_unit, false);
        state("last_error", error_unit, false);
      }
    } else if (s.kind == ControllerKind::linear) {
      const int n = static_cast<int>(s.block.A.rows());
      for (int i = 0; i < n; ++i) state(fmt::format("z{}", i + 1), "", continuous);
      if (continuous) loop.nz = n;
    }
    loop.now.held.assign(drives, 0.0);
    loop.now.z = VecX::Zero(s.block.A.rows());
    loop.before = loop.now;
    loop.delay_line.assign(static_cast<std::size_t>(s.sensor.delay) * c.measured.size(), 0.0);
    loop.readings = VecX::Zero(static_cast<Eigen::Index>(c.measured.size()));
    nz_ += loop.nz;
    loops_.push_back(std::move(loop));
  }
  // Without ball or free joints (nq = nv) every coordinate is a vector space's (model.hpp):
  // steps add, rates are velocities, and the plant's part need not be split off.
  vector_space_ = m.nq() == m.nv();
  q_ = VecX::Zero(m.nq());
  v_ = VecX::Zero(m.nv());
  z_ = VecX::Zero(nz_);
  dq_ = VecX::Zero(m.nv());
  out_q_ = VecX::Zero(m.nq());
  vdot_ = VecX::Zero(m.nv());
  zdot_ = VecX::Zero(nz_);
  std::size_t most_drives = 0;
  for (const Loop& loop : loops_) most_drives = std::max(most_drives, loop.c->drives.size());
  u_.assign(most_drives, 0.0);
}

// --- The laws ------------------------------------------------------------------------------------

void ClosedLoopSystem::measure_outputs(double t, const VecX& q, const VecX& v) {
  if (outputs_) outputs_->evaluate(*measuring_, t, q, v, output_values_);
}

double ClosedLoopSystem::measure(const Loop& loop, int i, const VecX& q, const VecX& v) const {
  const int index = loop.c->measured[static_cast<std::size_t>(i)];
  const int nq = plant_.model().nq(), nv = plant_.model().nv();
  const double y = index < nq ? q[index]
                   : index < nq + nv
                       ? v[index - nq]
                       : output_values_[static_cast<std::size_t>(loop.outputs + index - nq - nv)];
  const double step = loop.c->spec.sensor.quantization;
  return step > 0.0 ? step * std::round(y / step) : y;
}

model::SignalSample ClosedLoopSystem::reference(const Loop& loop, double t,
                                                model::Limit limit) const {
  if (loop.c->reference < 0) return {loop.c->spec.setpoint, 0.0, 0.0};
  return plant_.model().signals()[static_cast<std::size_t>(loop.c->reference)].sample(t, limit);
}

double ClosedLoopSystem::saturate(const Loop& loop, double u) const {
  return std::clamp(u, loop.c->spec.actuator.min, loop.c->spec.actuator.max);
}

void ClosedLoopSystem::continuous_law(Loop& loop, double t, model::Limit limit, const VecX& q,
                                      const VecX& v, const VecX& z, std::span<double> u,
                                      std::span<double> zdot) const {
  const model::Controller& s = loop.c->spec;
  switch (s.kind) {
    case ControllerKind::pid: {
      const model::SignalSample r = reference(loop, t, limit);
      const double e = r.value - measure(loop, 0, q, v);
      double raw = s.pid.kp * e;
      if (loop.integral >= 0) raw += z[loop.z + loop.integral];
      if (loop.filter >= 0) {
        // D(s) = kd s / (Tf s + 1) on e: the filter state follows e, the term is kd (e − x)/Tf.
        const double x = z[loop.z + loop.filter];
        raw += s.pid.kd * (e - x) / s.pid.derivative_filter;
        zdot[static_cast<std::size_t>(loop.filter)] = (e - x) / s.pid.derivative_filter;
      } else if (s.pid.kd != 0.0) {
        raw += s.pid.kd * (r.rate - v[loop.c->measured_rate]);
      }
      u[0] = saturate(loop, raw);
      if (loop.integral >= 0) {
        // Conditional integration: hold the integral while the actuator saturates and the
        // error drives it further in.
        const double push = s.pid.ki * e;
        const bool winding =
            (raw > s.actuator.max && push > 0.0) || (raw < s.actuator.min && push < 0.0);
        zdot[static_cast<std::size_t>(loop.integral)] = winding ? 0.0 : push;
      }
      return;
    }
    case ControllerKind::linear: {
      const double e = reference(loop, t, limit).value - measure(loop, 0, q, v);
      const model::LinearBlock& b = s.block;
      const auto n = b.A.rows();
      const auto zc = z.segment(loop.z, n);
      for (Eigen::Index i = 0; i < b.C.rows(); ++i) {
        u[static_cast<std::size_t>(i)] = saturate(loop, b.C.row(i).dot(zc) + b.D(i, 0) * e);
      }
      for (Eigen::Index i = 0; i < n; ++i) {
        zdot[static_cast<std::size_t>(i)] = b.A.row(i).dot(zc) + b.B(i, 0) * e;
      }
      return;
    }
    case ControllerKind::state_feedback: {
      const auto n = static_cast<Eigen::Index>(loop.c->measured.size());
      for (Eigen::Index i = 0; i < s.gain.rows(); ++i) {
        double raw = s.feedforward.size() > 0 ? s.feedforward[i] : 0.0;
        for (Eigen::Index j = 0; j < n; ++j) {
          const double x_ref = s.state_reference.size() > 0 ? s.state_reference[j] : 0.0;
          raw -= s.gain(i, j) * (measure(loop, static_cast<int>(j), q, v) - x_ref);
        }
        u[static_cast<std::size_t>(i)] = saturate(loop, raw);
      }
      return;
    }
    case ControllerKind::external:
      external_law(loop, t, q, v, u);
      return;
  }
}

void ClosedLoopSystem::external_law(const Loop& loop, double t, const VecX& q, const VecX& v,
                                    std::span<double> u) const {
  (*loop.c->spec.law)(t, q, v, u);
  for (std::size_t i = 0; i < u.size(); ++i) {
    if (!std::isfinite(u[i])) {
      const int s = loop.c->drives[i];
      throw NumericalError(
          fmt::format("controller '{}' gave {} = {} at t = {} s (a law's output must be finite)",
                      loop.c->spec.name,
                      plant_.model().signals()[static_cast<std::size_t>(s)].name(), u[i], t));
    }
    u[i] = saturate(loop, u[i]);
  }
}

void ClosedLoopSystem::take_sample(Loop& loop, double t_k, const VecX& q, const VecX& v) {
  const model::Controller& s = loop.c->spec;
  const bool first = loop.next_sample == 0;
  loop.before = loop.now;
  Discrete& d = loop.now;
  // Readings: quantized, with noise, through the delay line (filled with the first reading).
  const auto n = static_cast<std::size_t>(loop.readings.size());
  const auto delay = static_cast<std::size_t>(s.sensor.delay);
  for (std::size_t i = 0; i < n; ++i) {
    double y = measure(loop, static_cast<int>(i), q, v);
    if (s.sensor.noise > 0.0) {
      y += s.sensor.noise * std::normal_distribution<double>(0.0, 1.0)(loop.noise_source);
    }
    if (delay > 0) {
      double* line = loop.delay_line.data() + i * delay;
      if (first) std::fill(line, line + delay, y);
      const double oldest = line[0];
      std::copy(line + 1, line + delay, line);
      line[delay - 1] = y;
      y = oldest;
    }
    loop.readings[static_cast<Eigen::Index>(i)] = y;
  }
  // The law (Åström & Murray, Feedback Systems, the PID chapter's "Implementation": backward
  // differences for the derivative, the integral from past errors).
  const double T = s.sample_time;
  const double r = reference(loop, t_k, model::Limit::right).value;
  const std::size_t m = loop.c->drives.size();
  switch (s.kind) {
    case ControllerKind::pid: {
      const double e = r - loop.readings[0];
      if (first) d.last_error = e;
      const double Tf = s.pid.derivative_filter;
      d.derivative = (Tf * d.derivative + s.pid.kd * (e - d.last_error)) / (Tf + T);
      const double raw = s.pid.kp * e + d.integral + d.derivative;
      d.held[0] = saturate(loop, raw);
      const double push = s.pid.ki * T * e;
      const bool winding =
          (raw > s.actuator.max && push > 0.0) || (raw < s.actuator.min && push < 0.0);
      if (!winding) d.integral += push;
      d.last_error = e;
      break;
    }
    case ControllerKind::linear: {
      const double e = r - loop.readings[0];
      const model::LinearBlock& b = s.block;
      for (std::size_t i = 0; i < m; ++i) {
        const auto row = static_cast<Eigen::Index>(i);
        d.held[i] = saturate(loop, b.C.row(row).dot(d.z) + b.D(row, 0) * e);
      }
      // z⁺ = A z + B e (before.z is z as it was).
      d.z.noalias() = b.A * loop.before.z;
      d.z.noalias() += b.B.col(0) * e;
      break;
    }
    case ControllerKind::state_feedback: {
      for (std::size_t i = 0; i < m; ++i) {
        const auto row = static_cast<Eigen::Index>(i);
        double raw = s.feedforward.size() > 0 ? s.feedforward[row] : 0.0;
        for (Eigen::Index j = 0; j < loop.readings.size(); ++j) {
          const double x_ref = s.state_reference.size() > 0 ? s.state_reference[j] : 0.0;
          raw -= s.gain(row, j) * (loop.readings[j] - x_ref);
        }
        d.held[i] = saturate(loop, raw);
      }
      break;
    }
    case ControllerKind::external:
      external_law(loop, t_k, q, v, d.held);
      break;
  }
  // The rate limit, against the output held until now.
  if (!first && s.actuator.rate_limit < std::numeric_limits<double>::infinity()) {
    const double most = s.actuator.rate_limit * T;
    for (std::size_t i = 0; i < m; ++i) {
      d.held[i] = std::clamp(d.held[i], loop.before.held[i] - most, loop.before.held[i] + most);
    }
  }
  loop.last_sample = t_k;
  ++loop.next_sample;
}

const ClosedLoopSystem::Discrete& ClosedLoopSystem::discrete_at(const Loop& loop, double t) const {
  return t < loop.last_sample && !same_instant(t, loop.last_sample) ? loop.before : loop.now;
}

// --- The system ----------------------------------------------------------------------------------

void ClosedLoopSystem::split(const VecX& q, const VecX& v) const {
  q_ = q.head(q_.size());
  v_ = v.head(v_.size());
  if (nz_ > 0) z_ = v.tail(nz_);
}

integrate::State ClosedLoopSystem::start(double t0, const VecX& q, const VecX& v) {
  const model::Model& m = plant_.model();
  integrate::State state{t0, VecX::Zero(m.nq() + nz_), VecX::Zero(m.nv() + nz_)};
  state.q.head(m.nq()) = q;
  state.v.head(m.nv()) = v;
  measure_outputs(t0, q, v);
  for (Loop& loop : loops_) {
    const model::Controller& s = loop.c->spec;
    if (s.discrete()) {
      loop.now = Discrete{std::vector<double>(loop.c->drives.size(), 0.0), 0.0, 0.0, 0.0,
                          VecX::Zero(s.block.A.rows())};
      loop.before = loop.now;
      loop.noise_source.seed(s.sensor.seed);
      // The first sample at the first multiple of T from t0 on.
      loop.next_sample = 0;
      const double k0 = std::ceil(t0 / s.sample_time - 1e-9);
      if (k0 == 0.0) {
        take_sample(loop, t0, q, v);
      } else {
        loop.next_sample = static_cast<long>(k0);
      }
    } else if (loop.filter >= 0) {
      // The derivative filter starts at the error: no kick at the start.
      const double e = reference(loop, t0, model::Limit::right).value - measure(loop, 0, q, v);
      state.v[m.nv() + loop.z + loop.filter] = e;
    }
  }
  return state;
}

void ClosedLoopSystem::acceleration(double t, const VecX& q, const VecX& v, VecX& vdot) {
  // Without continuous controller states the state is the plant's own: no copies.
  if (nz_ == 0) {
    drive_plant(t, q, v);
    plant_.acceleration(t, q, v, vdot);
    return;
  }
  split(q, v);
  drive_plant(t, q_, v_);
  plant_.acceleration(t, q_, v_, vdot_);
  vdot.head(vdot_.size()) = vdot_;
  vdot.tail(nz_) = zdot_;
}

void ClosedLoopSystem::drive_plant(double t, const VecX& q, const VecX& v) {
  const model::Limit limit = t >= step_end_ ? model::Limit::left : model::Limit::right;
  measure_outputs(t, q, v);
  for (Loop& loop : loops_) drive(loop, t, limit, q, v);
}

void ClosedLoopSystem::drive(Loop& loop, double t, model::Limit limit, const VecX& q,
                             const VecX& v) {
  const std::size_t m = loop.c->drives.size();
  const std::span<double> u(u_.data(), m);
  if (loop.c->spec.discrete()) {
    const Discrete& d = discrete_at(loop, t);
    std::copy(d.held.begin(), d.held.end(), u.begin());
  } else {
    continuous_law(loop, t, limit, q, v, z_, u,
                   std::span<double>(zdot_.data() + loop.z, static_cast<std::size_t>(loop.nz)));
  }
  for (std::size_t i = 0; i < m; ++i) plant_.set_driven_value(loop.c->drives[i], u[i]);
}

void ClosedLoopSystem::integrate(const VecX& q, const VecX& dq, VecX& q_out) const {
  if (nz_ == 0) return plant_.integrate(q, dq, q_out);
  if (vector_space_) {
    q_out = q + dq;
    return;
  }
  const auto nq = q_.size(), nv = v_.size();
  q_ = q.head(nq);
  dq_ = dq.head(nv);
  plant_.integrate(q_, dq_, out_q_);
  q_out.head(nq) = out_q_;
  if (nz_ > 0) q_out.tail(nz_) = q.tail(nz_) + dq.tail(nz_);
}

void ClosedLoopSystem::difference(const VecX& q0, const VecX& q1, VecX& dq) const {
  if (nz_ == 0) return plant_.difference(q0, q1, dq);
  if (vector_space_) {
    dq = q1 - q0;
    return;
  }
  const auto nq = q_.size();
  q_ = q0.head(nq);
  out_q_ = q1.head(nq);
  plant_.difference(q_, out_q_, dq_);
  dq.head(dq_.size()) = dq_;
  if (nz_ > 0) dq.tail(nz_) = q1.tail(nz_) - q0.tail(nz_);
}

void ClosedLoopSystem::local_coordinate_rate(const VecX& delta, const VecX& v,
                                             VecX& delta_rate) const {
  if (nz_ == 0) return plant_.local_coordinate_rate(delta, v, delta_rate);
  if (vector_space_) {
    delta_rate = v;
    return;
  }
  const auto nv = v_.size();
  dq_ = delta.head(nv);
  v_ = v.head(nv);
  VecX& rate = vdot_;  // scratch of size nv (acceleration() rewrites it before reading)
  plant_.local_coordinate_rate(dq_, v_, rate);
  delta_rate.head(nv) = rate;
  if (nz_ > 0) delta_rate.tail(nz_) = v.tail(nz_);
}

void ClosedLoopSystem::configuration_scale(const VecX& q, VecX& scale) const {
  if (nz_ == 0) return plant_.configuration_scale(q, scale);
  if (vector_space_) {
    scale = q.cwiseAbs();
    return;
  }
  const auto nq = q_.size(), nv = v_.size();
  q_ = q.head(nq);
  VecX& plant_scale = dq_;
  plant_.configuration_scale(q_, plant_scale);
  scale.head(nv) = plant_scale;
  if (nz_ > 0) scale.tail(nz_) = q.tail(nz_).cwiseAbs();
}

double ClosedLoopSystem::next_discontinuity(double t) const {
  double next = plant_.next_discontinuity(t);
  for (const Loop& loop : loops_) {
    const double T = loop.c->spec.sample_time;
    if (T <= 0.0) continue;
    // The first multiple of T after t, beyond round-off (t may lie a rounding below kT).
    const double k = std::floor(t / T) + 1.0;
    double sample = k * T;
    if (same_instant(sample, t)) sample = (k + 1.0) * T;
    next = std::min(next, sample);
  }
  return next;
}

void ClosedLoopSystem::begin_step(double t0, double t1) {
  step_end_ = t1;
  plant_.begin_step(t0, t1);
}

bool ClosedLoopSystem::project(double t, VecX& q, VecX& v) {
  // The plant's projection, on the plant's part of the state.
  bool changed = false;
  if (nz_ == 0) {
    changed = plant_.project(t, q, v);
  } else {
    split(q, v);
    if (plant_.project(t, q_, v_)) {
      q.head(q_.size()) = q_;
      v.head(v_.size()) = v_;
      changed = true;
    }
  }
  // Every sample due at t.
  const VecX& q_plant = nz_ == 0 ? q : q_;
  const VecX& v_plant = nz_ == 0 ? v : v_;
  bool measured = false;
  for (Loop& loop : loops_) {
    const double T = loop.c->spec.sample_time;
    if (T <= 0.0) continue;
    const double t_k = static_cast<double>(loop.next_sample) * T;
    if (t < t_k && !same_instant(t, t_k)) continue;
    if (!measured) measure_outputs(t, q_plant, v_plant);
    measured = true;
    take_sample(loop, t_k, q_plant, v_plant);
    changed = true;
  }
  return changed;
}

std::string ClosedLoopSystem::coordinate_name(int i, bool velocity) const {
  const int n = velocity ? plant_.nv() : plant_.nq();
  if (i < n) return plant_.coordinate_name(i, velocity);
  const std::string& state = state_names_[static_cast<std::size_t>(i - n)];
  return velocity ? state : "∫" + state + " dt";
}

void ClosedLoopSystem::record(double t, const VecX& q, const VecX& v, std::span<double> out) {
  split(q, v);
  measure_outputs(t, q_, v_);
  std::size_t c = 0;
  for (Loop& loop : loops_) {
    const model::Controller& s = loop.c->spec;
    drive(loop, t, model::Limit::right, q_, v_);
    for (std::size_t i = 0; i < loop.c->drives.size(); ++i) out[c++] = u_[i];
    if (s.kind == ControllerKind::pid || s.kind == ControllerKind::linear) {
      const model::SignalSample r = reference(loop, t, model::Limit::right);
      const double y = measure(loop, 0, q_, v_);
      out[c++] = r.value;
      out[c++] = r.value - y;
    }
    if (s.discrete()) {
      const Discrete& d = discrete_at(loop, t);
      if (s.kind == ControllerKind::pid) {
        out[c++] = d.integral;
        out[c++] = d.derivative;
        out[c++] = d.last_error;
      } else if (s.kind == ControllerKind::linear) {
        for (Eigen::Index i = 0; i < d.z.size(); ++i) out[c++] = d.z[i];
      }
    } else {
      for (int i = 0; i < loop.nz; ++i) out[c++] = z_[loop.z + i];
    }
  }
}

}  // namespace momenta::system
