#include "momenta/identify/inertia_data.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"

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
                               const MatX& values, std::string_view source) {
  const std::vector<Column> wanted = needed(model);
  // Near misses among the columns the route does not read (a needed one is no misspelling).
  std::vector<std::string_view> others;
  for (const std::string& c : columns) {
    if (std::none_of(wanted.begin(), wanted.end(), [&](const Column& w) { return w.name == c; }))
      others.push_back(c);
  }
  std::vector<int> index;
  for (const Column& c : wanted) {
    const auto at = std::find(columns.begin(), columns.end(), c.name);
    if (at == columns.end()) {
      throw InvalidArgument(fmt::format(
          "{}: no column '{}' ({}){}; the inertia route reads these columns of the model's "
          "coordinates: {}",
          source, c.name, c.what, did_you_mean(c.name, others),
          fmt::join(inertia_data_columns(model), ", ")));
    }
    index.push_back(static_cast<int>(at - columns.begin()));
  }
  const Eigen::Index N = values.rows();
  InertiaSamples s{MatX(N, model.nq()), MatX(N, model.nv()), MatX(N, model.nv()),
                   MatX(N, model.nv())};
  int k = 0;
  for (int i = 0; i < model.nq(); ++i) s.q.col(i) = values.col(index[k++]);
  for (MatX* m : {&s.v, &s.vdot, &s.tau}) {
    for (int i = 0; i < model.nv(); ++i) m->col(i) = values.col(index[k++]);
  }
  return s;
}

}  // namespace momenta::identify
