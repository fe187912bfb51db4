#include "momenta/identify/trajectory_sensitivities.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <utility>

#include <fmt/format.h>

#include "momenta/analysis/acceleration_derivatives.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/integrate/run.hpp"
#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/model/units.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta/system/output_set.hpp"

namespace momenta::identify {
namespace {

// Refuses what the sensitivity equations here do not cover, naming it.
void check_scope(const model::Model& model) {
  if (model.nq() != model.nv()) {
    for (const model::Joint& j : model.joints()) {
      if (j.nq() != j.nv()) {
        throw InvalidArgument(fmt::format(
            "joint '{}' turns in three dimensions (a ball or free joint): the sensitivity "
            "equations here cover models whose coordinates are vectors (revolute, prismatic, "
            "cylindrical, universal, planar joints)",
            j.name));
      }
    }
  }
  if (model.has_constraints()) {
    throw InvalidArgument(fmt::format(
        "constraint '{}': the sensitivity equations here cover models without constraints or "
        "contacts",
        std::visit([](const auto& c) { return c.name; }, model.constraints().front())));
  }
  if (model.has_joint_limits()) {
    for (const model::Joint& j : model.joints()) {
      if (j.limits) {
        throw InvalidArgument(fmt::format(
            "joint '{}' has stops: an impact makes the sensitivities jump, which the sensitivity "
            "equations here do not follow",
            j.name));
      }
    }
  }
  if (model.has_controllers()) {
    throw InvalidArgument(
        "the model has controllers: the sensitivity equations here cover the plant alone (give "
        "the measured input as a table instead)");
  }
}

// One model and what runs it: the nominal one and each p ± h. Held by pointer (the system
// keeps a reference to the model).
struct Member {
  model::Model model;
  system::MultibodySystem system;
  system::OutputSet outputs;
  Member(model::Model m, const std::vector<model::OutputSpec>& specs)
      : model(std::move(m)), system(model), outputs(model, specs) {}
};

// The state and its scaled sensitivities p_i ∂x/∂p_i as one second-order system: configuration
// (q, S_q,1, …), velocity (v, S_v,1, …).
class SensitivitySystem final : public integrate::SecondOrderSystem {
 public:
  // ∂r/∂p_i by central differences between plus and minus (steps h_i), or, where `forward` is
  // not empty, forward differences to forward[i] (steps forward_steps[i]; the nominal's r is 0).
  SensitivitySystem(Member& nominal, std::vector<std::unique_ptr<Member>>& plus,
                    std::vector<std::unique_ptr<Member>>& minus,
                    std::vector<std::unique_ptr<Member>>& forward, const VecX& steps,
                    const VecX& forward_steps, const VecX& scales)
      : nominal_(nominal),
        plus_(plus),
        minus_(minus),
        forward_(forward),
        steps_(steps),
        forward_steps_(forward_steps),
        central_(forward.empty()),
        scales_(scales),
        derivatives_(nominal.model),
        n_(nominal.model.nv()),
        np_(static_cast<int>(steps.size())) {
    q_.resize(n_);
    v_.resize(n_);
    a_.resize(n_);
    r_.resize(n_);
    da_dp_.resize(n_);
    da_dq_.resize(n_, n_);
    da_dv_.resize(n_, n_);
  }

  int nq() const override { return n_ * (1 + np_); }
  int nv() const override { return n_ * (1 + np_); }
  /// The state's own accuracy chooses the steps; the sensitivities follow them.
  int error_controlled() const override { return n_; }
  long evaluations() const { return evaluations_; }

  // ∂a/∂p_i: a shifted model's accelerations differ from the nominal a by −M_ff⁻¹ r_i to first
  // order, r_i the generalized force its dynamics leave unbalanced at a (an inverse dynamics, not
  // a forward one: MultibodySystem::residual), M_ff factored once for ∂a/∂x.
  void acceleration(double t, const VecX& q, const VecX& v, VecX& vdot) override {
    q_ = q.head(n_);
    v_ = v.head(n_);
    nominal_.system.acceleration(t, q_, v_, a_);
    derivatives_.compute(nominal_.system, da_dq_, da_dv_);
    vdot.head(n_) = a_;
    for (int i = 0; i < np_; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const Eigen::Index at = n_ * (1 + i);
      auto out = vdot.segment(at, n_);
      out.noalias() = da_dq_ * q.segment(at, n_);
      out.noalias() += da_dv_ * v.segment(at, n_);
      if (central_) {
        r_ = plus_[k]->system.residual(t, q_, v_, a_);
        r_ -= minus_[k]->system.residual(t, q_, v_, a_);
        r_ *= scales_[i] / (2.0 * steps_[i]);
      } else {
        r_ = forward_[k]->system.residual(t, q_, v_, a_);
        r_ *= scales_[i] / forward_steps_[i];
      }
      derivatives_.acceleration_change(r_, da_dp_);
      out += da_dp_;  // zero on prescribed coordinates, as da_dq_'s and da_dv_'s rows
    }
    evaluations_ += 1 + (central_ ? 2L : 1L) * np_;
  }

  void integrate(const VecX& q, const VecX& dq, VecX& q_out) const override { q_out = q + dq; }

  double next_discontinuity(double t) const override {
    double next = nominal_.system.next_discontinuity(t);
    for (const auto& m : plus_) next = std::min(next, m->system.next_discontinuity(t));
    for (const auto& m : minus_) next = std::min(next, m->system.next_discontinuity(t));
    for (const auto& m : forward_) next = std::min(next, m->system.next_discontinuity(t));
    return next;
  }

  void begin_step(double t0, double t1) override {
    nominal_.system.begin_step(t0, t1);
    for (const auto& m : plus_) m->system.begin_step(t0, t1);
    for (const auto& m : minus_) m->system.begin_step(t0, t1);
    for (const auto& m : forward_) m->system.begin_step(t0, t1);
  }

  std::string coordinate_name(int i, bool velocity) const override {
    const model::Model& model = nominal_.model;
    const int c = i % n_;
    const std::string& name = velocity ? model.v_name(c) : model.q_name(c);
    if (i < n_) return name;
    return fmt::format("the sensitivity of {} to parameter {}", name, i / n_);
  }

 private:
  Member& nominal_;
  std::vector<std::unique_ptr<Member>>& plus_;
  std::vector<std::unique_ptr<Member>>& minus_;
  std::vector<std::unique_ptr<Member>>& forward_;
  const VecX& steps_;
  const VecX& forward_steps_;
  bool central_;
  const VecX& scales_;
  analysis::AccelerationDerivatives derivatives_;
  int n_, np_;
  VecX q_, v_, a_, r_, da_dp_;
  MatX da_dq_, da_dv_;
  long evaluations_ = 0;
};

// Records the channels (and their sensitivities) at each sample time a run reaches.
class Sampler {
 public:
  Sampler(const ChannelSet& channels, Member& nominal, std::vector<std::unique_ptr<Member>>* plus,
          std::vector<std::unique_ptr<Member>>* minus, const VecX& steps, const VecX& scales,
          const VecX& times, double spacing, SampledOutputs& out)
      : channels_(channels),
        nominal_(nominal),
        plus_(plus),
        minus_(minus),
        steps_(steps),
        scales_(scales),
        times_(times),
        spacing_(spacing),
        out_(out),
        n_(nominal.model.nv()) {
    const auto nc = static_cast<Eigen::Index>(channels.names().size());
    const auto N = times.size();
    out.values.resize(N, nc);
    const auto np = static_cast<Eigen::Index>(steps.size());
    if (plus != nullptr) out.sensitivities.setZero(N * nc, np);
    column_values_.resize(static_cast<std::size_t>(nominal.outputs.size()));
    column_plus_ = column_minus_ = column_values_;
    for (Eigen::Index c = 0; c < nc; ++c)
      uses_outputs_ = uses_outputs_ || channels.source(int(c)) < 0;
    if (uses_outputs_ && plus != nullptr) output_jacobian_.resize(nominal.outputs.size(), 2 * n_);
  }

  void operator()(const integrate::State& state) {
    if (next_ >= times_.size()) return;
    const double t_sample = times_[0] + double(next_) * spacing_;
    if (std::abs(state.t - t_sample) > 1e-9 * spacing_) return;
    q_ = state.q.head(n_);
    v_ = state.v.head(n_);
    nominal_.system.apply_prescribed_motion(state.t, q_, v_);
    if (uses_outputs_) nominal_.outputs.evaluate(nominal_.system, state.t, q_, v_, column_values_);
    const auto nc = static_cast<Eigen::Index>(channels_.names().size());
    for (Eigen::Index c = 0; c < nc; ++c) {
      const int source = channels_.source(int(c));
      out_.values(next_, c) = source >= 0 ? (source < n_ ? q_[source] : v_[source - n_])
                                          : column_values_[static_cast<std::size_t>(-1 - source)];
    }
    if (plus_ != nullptr) record_sensitivities(state);
    ++next_;
  }

  bool complete() const { return next_ == times_.size(); }

 private:
  // ∂y/∂p_i = (∂y/∂x S̃_i) / s_i + ∂y/∂p_i at the state (outputs only).
  void record_sensitivities(const integrate::State& state) {
    const auto np = static_cast<Eigen::Index>(steps_.size());
    if (uses_outputs_) differentiate_outputs(state.t);
    const auto nc = static_cast<Eigen::Index>(channels_.names().size());
    for (Eigen::Index i = 0; i < np; ++i) {
      const Eigen::Index at = n_ * (1 + i);
      std::fill(column_plus_.begin(), column_plus_.end(), 0.0);
      std::fill(column_minus_.begin(), column_minus_.end(), 0.0);
      if (uses_outputs_) {
        auto& plus = *(*plus_)[static_cast<std::size_t>(i)];
        auto& minus = *(*minus_)[static_cast<std::size_t>(i)];
        plus.outputs.evaluate(plus.system, state.t, q_, v_, column_plus_);
        minus.outputs.evaluate(minus.system, state.t, q_, v_, column_minus_);
      }
      for (Eigen::Index c = 0; c < nc; ++c) {
        const int source = channels_.source(int(c));
        double d = 0.0;
        if (source >= 0) {
          d = (source < n_ ? state.q[at + source] : state.v[at + source - n_]) / scales_[i];
        } else {
          const auto k = static_cast<Eigen::Index>(-1 - source);
          d = (output_jacobian_.row(k).head(n_).dot(state.q.segment(at, n_)) +
               output_jacobian_.row(k).tail(n_).dot(state.v.segment(at, n_))) /
                  scales_[i] +
              (column_plus_[std::size_t(k)] - column_minus_[std::size_t(k)]) / (2.0 * steps_[i]);
        }
        out_.sensitivities(next_ * nc + c, i) = d;
      }
    }
  }

  // ∂y/∂(q, v) of every output column by central differences at the state.
  void differentiate_outputs(double t) {
    for (int j = 0; j < 2 * n_; ++j) {
      VecX& x = j < n_ ? q_ : v_;
      const int k = j < n_ ? j : j - n_;
      const double x0 = x[k];
      const double h = 1e-6 * std::max(1.0, std::abs(x0));
      x[k] = x0 + h;
      nominal_.outputs.evaluate(nominal_.system, t, q_, v_, column_plus_);
      x[k] = x0 - h;
      nominal_.outputs.evaluate(nominal_.system, t, q_, v_, column_minus_);
      x[k] = x0;
      for (std::size_t c = 0; c < column_plus_.size(); ++c)
        output_jacobian_(Eigen::Index(c), j) = (column_plus_[c] - column_minus_[c]) / (2.0 * h);
    }
  }

  const ChannelSet& channels_;
  Member& nominal_;
  std::vector<std::unique_ptr<Member>>* plus_;
  std::vector<std::unique_ptr<Member>>* minus_;
  const VecX& steps_;
  const VecX& scales_;
  const VecX& times_;
  double spacing_;
  SampledOutputs& out_;
  int n_;
  Eigen::Index next_ = 0;
  bool uses_outputs_ = false;
  VecX q_, v_;
  std::vector<double> column_values_, column_plus_, column_minus_;
  MatX output_jacobian_;
};

}  // namespace

double even_spacing(const VecX& times, const std::string& what) {
  const Eigen::Index N = times.size();
  if (N < 2) {
    throw InvalidArgument(fmt::format("{}: {} samples; at least two are needed", what, N));
  }
  const double spacing = (times[N - 1] - times[0]) / double(N - 1);
  if (!(spacing > 0.0)) {
    throw InvalidArgument(fmt::format("{}: the times do not increase", what));
  }
  for (Eigen::Index k = 0; k < N; ++k) {
    const double expected = times[0] + double(k) * spacing;
    if (std::abs(times[k] - expected) > 1e-6 * spacing) {
      throw InvalidArgument(fmt::format(
          "{}: sample {} is at t = {:.9g} s, not {:.9g} s: the samples must be evenly spaced "
          "({:.6g} s apart; resample the log)",
          what, k + 1, times[k], expected, spacing));
    }
  }
  return spacing;
}

ChannelSet::ChannelSet(const model::Model& model, std::vector<model::OutputSpec> outputs,
                       std::vector<std::string> channels)
    : outputs_(std::move(outputs)), names_(std::move(channels)) {
  check_scope(model);
  const system::OutputSet set(model, outputs_);
  std::vector<std::string_view> candidates;
  for (const std::string& c : set.column_names()) candidates.emplace_back(c);
  for (int i = 0; i < model.nv(); ++i) {
    candidates.emplace_back(model.q_name(i));
    candidates.emplace_back(model.v_name(i));
  }
  for (const std::string& name : names_) {
    const auto& columns = set.column_names();
    const auto column = std::find(columns.begin(), columns.end(), name);
    if (column != columns.end()) {
      const auto k = column - columns.begin();
      source_.push_back(-1 - static_cast<int>(k));
      units_.push_back(set.column_units()[static_cast<std::size_t>(k)]);
      continue;
    }
    int found = -1;
    for (int i = 0; i < model.nv() && found < 0; ++i) {
      if (model.q_name(i) == name) found = i;
      if (model.v_name(i) == name) found = model.nv() + i;
    }
    if (found < 0) {
      throw InvalidArgument(
          fmt::format("'{}' is neither an output of the model nor one of its coordinates{}", name,
                      did_you_mean(name, candidates)));
    }
    const int i = found % model.nv();
    if (model.joint(model.joint_of_v(i)).is_prescribed()) {
      throw InvalidArgument(fmt::format(
          "'{}' is a prescribed coordinate: its motion is an input, not something to fit", name));
    }
    source_.push_back(found);
    units_.push_back(found < model.nv() ? model::q_unit(model, i) : model::v_unit(model, i));
  }
}

SampledOutputs sample_outputs(const ModelFactory& make_model, const VecX& p,
                              const ChannelSet& channels, const VecX& times, bool sensitivities,
                              const SensitivityOptions& options) {
  const double spacing = even_spacing(times, "the sample times");
  const auto np = static_cast<int>(p.size());
  auto nominal = std::make_unique<Member>(make_model(p), channels.outputs());
  check_scope(nominal->model);
  const int n = nominal->model.nv();

  SampledOutputs out;
  integrate::DormandPrince5 method(options.tolerances);
  const integrate::RunOptions run_options{.t_end = times[times.size() - 1], .h = spacing};
  VecX steps(np), forward_steps(np), scales(np);
  std::vector<std::unique_ptr<Member>> plus, minus, forward;
  if (sensitivities) {
    for (int i = 0; i < np; ++i) {
      scales[i] = p[i] != 0.0 ? std::abs(p[i]) : 1.0;
      steps[i] = options.relative_step * scales[i];
      forward_steps[i] = options.forward_step * scales[i];
      VecX shifted = p;
      shifted[i] = p[i] + steps[i];
      plus.push_back(std::make_unique<Member>(make_model(shifted), channels.outputs()));
      shifted[i] = p[i] - steps[i];
      minus.push_back(std::make_unique<Member>(make_model(shifted), channels.outputs()));
      if (options.dynamics == SensitivityOptions::Differences::forward) {
        shifted[i] = p[i] + forward_steps[i];
        forward.push_back(std::make_unique<Member>(make_model(shifted), channels.outputs()));
      }
    }
  }
  Sampler sampler(channels, *nominal, sensitivities ? &plus : nullptr,
                  sensitivities ? &minus : nullptr, steps, scales, times, spacing, out);
  // Called at the start and after every step: past the budget the run stops, named.
  long calls = 0;
  const auto observe = [&](const integrate::State& state) {
    if (options.max_steps > 0 && ++calls > options.max_steps + 1) {
      throw NumericalError(fmt::format(
          "the run took more than {} steps by t = {:.6g} s of {:.6g} s: the model is far "
          "stiffer or faster at these values than where the fit started",
          options.max_steps, state.t, run_options.t_end));
    }
    sampler(state);
  };

  if (!sensitivities) {
    integrate::State state{times[0], nominal->model.initial_q(), nominal->model.initial_v()};
    nominal->system.apply_prescribed_motion(state.t, state.q, state.v);
    const integrate::RunSummary summary =
        integrate::run(nominal->system, method, state, run_options, observe);
    out.evaluations = summary.statistics.evaluations;
    out.steps = summary.statistics.steps;
  } else {
    SensitivitySystem system(*nominal, plus, minus, forward, steps, forward_steps, scales);
    integrate::State state{times[0], VecX::Zero(n * (1 + np)), VecX::Zero(n * (1 + np))};
    VecX q0 = nominal->model.initial_q(), v0 = nominal->model.initial_v();
    nominal->system.apply_prescribed_motion(state.t, q0, v0);
    state.q.head(n) = q0;
    state.v.head(n) = v0;
    for (int i = 0; i < np; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const double factor = scales[i] / (2.0 * steps[i]);
      state.q.segment(n * (1 + i), n) =
          (plus[k]->model.initial_q() - minus[k]->model.initial_q()) * factor;
      state.v.segment(n * (1 + i), n) =
          (plus[k]->model.initial_v() - minus[k]->model.initial_v()) * factor;
      for (int r = 0; r < n; ++r) {
        if (!nominal->model.joint(nominal->model.joint_of_v(r)).is_prescribed()) continue;
        state.q[n * (1 + i) + r] = state.v[n * (1 + i) + r] = 0.0;
      }
    }
    const integrate::RunSummary summary =
        integrate::run(system, method, state, run_options, observe);
    out.evaluations = system.evaluations();
    out.steps = summary.statistics.steps;
  }
  if (!sampler.complete()) {
    throw NumericalError(
        "the run did not reach every sample time (an integration step skipped one)");
  }
  return out;
}

}  // namespace momenta::identify
