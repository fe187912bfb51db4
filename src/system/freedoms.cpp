#include "momenta/system/freedoms.hpp"

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
    f.constraint_rows = solver.rows().count;
    f.independent_rows = f.constraint_rows - static_cast<int>(solver.redundant_rows().size());
  }
  return f;
}

}  // namespace momenta::system
