#include "momenta/simulate/state_at.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta::simulate {
namespace {

// Keeps one row's time, q and v (the table's columns 0, 1..nq, nq+1..nq+nv): the last, or with
// `first` the first.
class StateRow final : public RowSink {
 public:
  StateRow(int nq, int nv, bool first) : first_(first) {
    state.q.resize(nq);
    state.v.resize(nv);
  }
  void begin(std::span<const std::string>) override {}
  void row(std::span<const double> values) override {
    if (first_ && rows_++ > 0) return;
    state.t = values[0];
    const auto nq = state.q.size();
    for (Eigen::Index i = 0; i < nq; ++i) state.q[i] = values[1 + i];
    for (Eigen::Index i = 0; i < state.v.size(); ++i) state.v[i] = values[1 + nq + i];
  }
  integrate::State state;

 private:
  bool first_;
  long rows_ = 0;
};

}  // namespace

integrate::State state_at(const model::Model& model, double t, SimulationOptions options) {
  if (!(std::isfinite(t) && t >= 0.0)) {
    throw InvalidArgument(fmt::format("state_at: the time {} s must be zero or positive", t));
  }
  // At t = 0 a run of one step's length still records the initial row first; keep that one.
  const bool initial = t == 0.0;
  options.duration = initial ? options.step : t;
  options.every = std::numeric_limits<long>::max();
  options.reactions = false;
  Simulation simulation(model, {}, options);
  StateRow row(model.nq(), model.nv(), initial);
  simulation.run(row);
  return row.state;
}

}  // namespace momenta::simulate
