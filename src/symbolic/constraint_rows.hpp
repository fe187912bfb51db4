#pragma once
// The model's constraints in symbols: each row's position function φ(q) (holonomic rows) and the
// wrench a unit multiplier applies, written as dynamics/constraints.hpp writes them numerically
// (the same rows, in the same order, with the same signs), so that G v = wᵀ (V_b − V_a) and the
// multipliers mean the same forces in both.

#include <functional>
#include <string>
#include <vector>

#include "expression_algebra.hpp"
#include "momenta/model/model.hpp"
#include "momenta/model/parameter_source.hpp"

namespace momenta::symbolic::detail {

/// A parameter of the model by its name and value: a symbol or the number (equations.cpp).
using ParameterFn =
    std::function<ex(const std::string& name, const model::ParameterSource& source)>;

/// One constraint row. A wrench row acts on body b with w = [moment; force] in W about Wo (and
/// with −w on body a); a coupler's row is a row of G in joint space instead.
struct SymbolicRow {
  std::string name;  ///< "<constraint>.<label>", as dynamics::ConstraintRows names it
  bool holonomic = false;
  ex position = 0;  ///< φ(q) on a holonomic row, else 0
  int body_a = 0, body_b = 0;
  V3 moment, force;                           ///< w on body b (wrench rows)
  std::vector<std::pair<int, ex>> joint_row;  ///< (v index, coefficient) (a coupler's row)
};

/// The rows of every constraint of `model`, model order, at the symbolic body poses R_WB and
/// p_WB (per body, body 0 the world) and coordinates q (per model coordinate).
std::vector<SymbolicRow> constraint_rows(const model::Model& model, const std::vector<M3>& R_WB,
                                         const std::vector<V3>& p_WB, const std::vector<ex>& q,
                                         const ParameterFn& parameter);

}  // namespace momenta::symbolic::detail
