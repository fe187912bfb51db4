// The equations' numbers for a changed model (report.hpp, equation_numbers), and the parameter
// sources as the report's data writes them (sections.hpp, source_json; the engine reads them
// back). GiNaC-free: the in-page engine runs it where the symbolic layer is not.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "momenta/common/error.hpp"
#include "momenta/model/parameter_source.hpp"
#include "momenta/report/report.hpp"
#include "sections.hpp"

namespace momenta::report {
namespace detail {

json source_json(const model::ParameterSource& source) {
  json out = {{"kind", model::parameter_source_kind_name(source.kind)}, {"index", source.index}};
  if (source.row != 0) out["row"] = source.row;
  if (source.column != 0) out["column"] = source.column;
  if (source.magnitude) out["magnitude"] = true;
  if (source.sign != 1) out["sign"] = source.sign;
  return out;
}

}  // namespace detail

namespace {

// Whether two values are one to 1e-12 of the larger (the derivation's test for one symbol).
bool agree(double a, double b) {
  return std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b));
}

}  // namespace

EquationNumbers equation_numbers(const model::Model& model,
                                 const std::vector<EquationSymbolSources>& symbols,
                                 const std::vector<EquationFormNumber>& form) {
  EquationNumbers out;
  for (const EquationSymbolSources& symbol : symbols) {
    if (symbol.sources.empty())
      throw InvalidArgument(fmt::format("equations: symbol '{}' has no source", symbol.name));
    const model::ParameterSource& first = symbol.sources.front();
    const double value = model::parameter_value(model, first);
    out.values.push_back(value);
    if (value == 0.0) {
      out.zeroed.push_back(symbol.name);
    } else if (first.magnitude && model::parameter_signed_value(model, first) * first.sign < 0) {
      out.form_changes.push_back(
          fmt::format("{} lies the other way along its axis: the signs change", symbol.name));
    }
    for (std::size_t k = 1; k < symbol.sources.size(); ++k) {
      if (!agree(model::parameter_value(model, symbol.sources[k]), value)) {
        out.form_changes.push_back(fmt::format(
            "the numbers the symbols section names {} differ: they are two symbols", symbol.name));
        break;
      }
    }
  }
  for (const EquationFormNumber& number : form) {
    const double now = model::parameter_value(model, number.source);
    if (now == number.value || (number.value != 0.0 && agree(number.value, now))) continue;
    out.form_changes.push_back(
        fmt::format("{} was {}, is {}: no symbol stands for it", number.name, number.value, now));
  }
  return out;
}

}  // namespace momenta::report
