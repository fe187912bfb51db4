// The report's free-body diagrams: each body's diagrams (report/free_body_svg.hpp) at a few
// instants of the run, for the page to show one at a time.

#include <algorithm>

#include "momenta/analysis/free_body.hpp"
#include "momenta/common/error.hpp"
#include "momenta/report/free_body_svg.hpp"
#include "sections.hpp"

namespace momenta::report::detail {

json diagrams_json(const SimulationRun& run) {
  const model::Model& model = run.file->model;
  const int rows = static_cast<int>(run.rows.size());
  // Evenly spread recorded rows, the first and the last among them.
  std::vector<int> kept;
  for (int k = 0; k < kDiagramInstants; ++k) {
    const int r = rows <= 1 ? 0 : k * (rows - 1) / (kDiagramInstants - 1);
    if (kept.empty() || kept.back() != r) kept.push_back(r);
  }
  json bodies = json::array();
  json times = json::array();
  for (const int r : kept) times.push_back(run.rows[static_cast<std::size_t>(r)][0]);
  system::MultibodySystem system(model);
  const int shown = std::min(model.num_bodies() - 1, kMaxDiagramBodies);
  for (int b = 1; b <= shown; ++b) {
    json pictures = json::array();
    json residuals = json::array();
    for (const int r : kept) {
      const std::vector<double>& row = run.rows[static_cast<std::size_t>(r)];
      const VecX q = Eigen::Map<const VecX>(row.data() + 1, model.nq());
      const VecX v = Eigen::Map<const VecX>(row.data() + 1 + model.nq(), model.nv());
      try {
        const analysis::FreeBodyDiagram d =
            analysis::free_body_diagram(system, model.body(b).name, row[0], q, v);
        pictures.push_back(free_body_svg(d, run.file->name, run.file->parts_of(b)));
        residuals.push_back({d.force_residual().norm(), d.moment_residual().norm()});
      } catch (const Error& e) {
        // A state where the dynamics cannot be evaluated (a singular constraint): said there.
        pictures.push_back(nullptr);
        residuals.push_back(e.what());
      }
    }
    bodies.push_back({{"name", model.body(b).name}, {"svg", pictures}, {"residuals", residuals}});
  }
  return {{"times", times}, {"bodies", bodies}, {"omitted", model.num_bodies() - 1 - shown}};
}

}  // namespace momenta::report::detail
