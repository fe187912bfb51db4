#include "momenta/system/freedoms.hpp"

#include <algorithm>

#include "momenta/system/constraint_solver.hpp"

namespace momenta::system {

Freedoms count_freedoms(const model::Model& model) {
  Freedoms f;
  f.speeds = model.nv();
  for (const model::Joint& j : model.joints()) {
    if (j.is_prescribed()) f.prescribed += j.nv();
  }
  if (model.has_constraints()) {
    const ConstraintSolver solver(model);
    // A contact's row is off (open) outside a run: it takes no freedom.
    const std::vector<char>& on = solver.rows().enabled;
    f.constraint_rows = static_cast<int>(std::count(on.begin(), on.end(), 1));
    f.independent_rows = f.constraint_rows - static_cast<int>(solver.redundant_rows().size());
  }
  return f;
}

}  // namespace momenta::system
