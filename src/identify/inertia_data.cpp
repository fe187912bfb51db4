#include "momenta/identify/inertia_data.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/identify/position_derivatives.hpp"

namespace momenta::identify {
namespace {

// The coordinate's own name after "<joint>.": "angle_rate" of "shoulder.angle_rate".
std::string_view coordinate_part(const std::string& full) {
  const std::size_t dot = full.find('.');
  return std::string_view(full).substr(dot + 1);
}

std::string effort_column(const Model& model, int i) {
  const model::Joint& joint = model.joint(model.joint_of_v(i));
  if (joint.nv() == 1) return joint.name + ".effort";
  return fmt::format("{}.effort_{}", joint.name, coordinate_part(model.v_name(i)));
}

struct Column {
  std::string name;
  std::string what;
};

// q, v, v̇, τ columns in that order, with what each holds for the error message.
std::vector<Column> needed(const Model& model) {
  std::vector<Column> out;
  for (int i = 0; i < model.nq(); ++i)
    out.push_back({model.q_name(i), "a configuration coordinate"});
  for (int i = 0; i < model.nv(); ++i) out.push_back({model.v_name(i), "a velocity coordinate"});
  for (int i = 0; i < model.nv(); ++i) {
    out.push_back({model.v_name(i) + "_dot", fmt::format("the rate of {}", model.v_name(i))});
  }
  for (int i = 0; i < model.nv(); ++i) {
    out.push_back({effort_column(model, i),
                   fmt::format("the effort the actuator applied along {}", model.v_name(i))});
  }
  return out;
}

}  // namespace

std::vector<std::string> inertia_data_columns(const Model& model) {
  std::vector<std::string> names;
  for (const Column& c : needed(model)) names.push_back(c.name);
  return names;
}

InertiaSamples inertia_samples(const Model& model, const std::vector<std::string>& columns,
                               const MatX& values, std::string_view source, int derivative_window) {
  const std::vector<Column> wanted = needed(model);
  const auto find = [&](const std::string& name) -> int {
    const auto at = std::find(columns.begin(), columns.end(), name);
    return at == columns.end() ? -1 : static_cast<int>(at - columns.begin());
  };
  // Rates and accelerations may be left out together per kind (all of a kind, not some): they
  // are then taken from the positions (or the accelerations from the rates).
  const int nq = model.nq(), nv = model.nv();
  const auto none_of_kind = [&](int first, int count) {
    for (int k = first; k < first + count; ++k)
      if (find(wanted[k].name) >= 0) return false;
    return count > 0;
  };
  const bool derive_v = none_of_kind(nq, nv);
  const bool derive_vdot = none_of_kind(nq + nv, nv);
  // Near misses among the columns the route does not read (a needed one is no misspelling).
  std::vector<std::string_view> others;
  for (const std::string& c : columns) {
    if (std::none_of(wanted.begin(), wanted.end(), [&](const Column& w) { return w.name == c; }))
      others.push_back(c);
  }
  std::vector<int> index;
  for (std::size_t k = 0; k < wanted.size(); ++k) {
    const Column& c = wanted[k];
    const bool rate = int(k) >= nq && int(k) < nq + nv,
               acceleration = int(k) >= nq + nv && int(k) < nq + 2 * nv;
    if ((rate && derive_v) || (acceleration && derive_vdot)) {
      index.push_back(-1);
      continue;
    }
    const int at = find(c.name);
    if (at < 0) {
      throw InvalidArgument(fmt::format(
          "{}: no column '{}' ({}){}; the inertia route reads these columns of the model's "
          "coordinates: {} (the rates and the accelerations may be left out, each all together, "
          "to be taken from the positions)",
          source, c.name, c.what, did_you_mean(c.name, others),
          fmt::join(inertia_data_columns(model), ", ")));
    }
    index.push_back(at);
  }
  const Eigen::Index N = values.rows();
  InertiaSamples s{MatX(N, nq), MatX(N, nv), MatX(N, nv), MatX(N, nv), {}};
  int k = 0;
  for (int i = 0; i < nq; ++i) s.q.col(i) = values.col(index[k++]);
  for (MatX* m : {&s.v, &s.vdot, &s.tau}) {
    for (int i = 0; i < nv; ++i, ++k) {
      if (index[k] >= 0) m->col(i) = values.col(index[k]);
    }
  }
  if (!derive_v && !derive_vdot) return s;

  // Differentiated: only where each rate is its position's derivative (q̇ = v, named so).
  const int time = find("time");
  if (time < 0) {
    throw InvalidArgument(fmt::format(
        "{}: the rates or accelerations are left out, and there is no 'time' column to take "
        "them from the positions by",
        source));
  }
  for (int i = 0; i < nv && derive_v; ++i) {
    if (nq != nv || model.v_name(i) != model.q_name(i) + "_rate") {
      throw InvalidArgument(fmt::format(
          "{}: no rate columns, and {} is not the rate of a position (a ball or free joint's "
          "angular velocity is not its quaternion's derivative): give the rates",
          source, model.v_name(i)));
    }
  }
  const VecX t = values.col(time);
  if (derive_v) {
    const PositionDerivatives d = differentiate_positions(t, s.q, derivative_window);
    s.v = d.rate;
    if (derive_vdot) s.vdot = d.acceleration;
    s.derived = fmt::format(
        "rates{} from the positions: the derivatives of a cubic fitted to {} samples about each "
        "(Savitzky–Golay)",
        derive_vdot ? " and accelerations" : "", derivative_window);
  } else {
    s.vdot = differentiate_positions(t, s.v, derivative_window).rate;
    s.derived = fmt::format(
        "accelerations from the rates: the derivative of a cubic fitted to {} samples about each "
        "(Savitzky–Golay)",
        derivative_window);
  }
  return s;
}

}  // namespace momenta::identify
