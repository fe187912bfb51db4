// The report's equations panel: the model's equations of motion in symbols, as LaTeX for the
// page to set (KaTeX, MathML), every nonzero parameter a symbol named as `momenta equations
// --all-symbols` (and the file's `symbols:` section) names it, with the symbols' values.

#include <fmt/format.h>

#include <cctype>
#include <set>
#include <string>
#include <vector>

#include "sections.hpp"

#if MOMENTA_WITH_SYMBOLIC
#include "momenta/common/error.hpp"
#include "momenta/symbolic/equations.hpp"
#endif

namespace momenta::report::detail {

#if MOMENTA_WITH_SYMBOLIC
namespace {

// Models with more free speeds than this get no panel: their equations are pages of terms
// (a 10-link chain's would be megabytes), which `momenta equations --cpp` writes as code.
constexpr int kMaxFreeSpeeds = 8;

json unavailable(const std::string& reason) { return {{"available", false}, {"reason", reason}}; }

// The identifiers a text holds (the symbols an equation uses).
std::set<std::string> identifiers_in(const std::string& text) {
  std::set<std::string> names;
  std::string name;
  for (char c : text + ' ') {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') {
      name += c;
    } else if (!name.empty()) {
      names.insert(name);
      name.clear();
    }
  }
  return names;
}

// Each equation in LaTeX and text; `shown` gathers the text (the symbols the page uses).
json rows_json(const symbolic::Equations& e, std::string& shown) {
  json rows = json::array();
  for (int r = 0; r < static_cast<int>(e.free_speeds().size()); ++r) {
    std::string text = e.equation(r, symbolic::Format::text);
    shown += text + "\n";
    rows.push_back({{"latex", e.equation(r, symbolic::Format::latex)}, {"text", std::move(text)}});
  }
  return rows;
}

// Each constraint row's equation in LaTeX, its text added to `shown`.
json constraints_json(const symbolic::Equations& e, std::string& shown) {
  json constraints = json::array();
  for (int r = 0; r < e.constraint_rows(); ++r) {
    shown += e.constraint_equation(r, symbolic::Format::text) + "\n";
    constraints.push_back({{"name", e.constraint_row_name(r)},
                           {"holonomic", e.constraint_row_holonomic(r)},
                           {"latex", e.constraint_equation(r, symbolic::Format::latex)}});
  }
  return constraints;
}

// An equation with more terms than this is not written again with numbers: a free body's 94
// (a quaternion's products) would be a page of figures no one reads, and its data 100 kB.
constexpr std::size_t kMaxNumberTerms = 40;

// Equation `row`'s terms (symbolic::EquationTerm) for the page to give numbers: [{latex, right,
// c: [[factor, [parameter, exponent, …]], …]}], parameters numbered by `listed` (their place in
// the panel's list, −1 for one not listed); null where a parameter is inside a function or the
// terms are more than kMaxNumberTerms.
json terms_json(const symbolic::Equations& e, int row, const std::vector<int>& listed) {
  const auto terms = e.equation_terms(row);
  if (!terms || terms->size() > kMaxNumberTerms) return nullptr;
  json out = json::array();
  for (const symbolic::EquationTerm& term : *terms) {
    json coefficient = json::array();
    for (const symbolic::EquationTerm::Monomial& m : term.coefficient) {
      json powers = json::array();
      for (const auto& [index, exponent] : m.powers) {
        if (listed[static_cast<std::size_t>(index)] < 0) return nullptr;
        powers.push_back(listed[static_cast<std::size_t>(index)]);
        powers.push_back(exponent);
      }
      coefficient.push_back({m.factor, std::move(powers)});
    }
    json item = {{"latex", term.latex}, {"c", std::move(coefficient)}};
    if (term.right) item["right"] = true;
    out.push_back(std::move(item));
  }
  return out;
}

}  // namespace

json equations_json(const io::ModelFile& file) {
  const model::Model& model = file.model;
  int free_speeds = model.nv();
  for (const model::Joint& j : model.joints())
    if (j.is_prescribed()) free_speeds -= j.nv();
  if (free_speeds > kMaxFreeSpeeds) {
    return unavailable(
        fmt::format("{} free speeds: too many equations to read on a page; "
                    "`momenta equations {} --cpp` writes them as code",
                    free_speeds, file.file));
  }
  symbolic::EquationOptions options;
  options.all_symbols = true;
  options.names = file.given_symbol_names();
  try {
    const symbolic::Equations e = symbolic::derive_equations(model, options);
    std::string shown;
    json equations = rows_json(e, shown);
    json constraints = constraints_json(e, shown);
    // The symbols the equations use (a planar body's I_xx is a parameter, not in them).
    const std::set<std::string> used = identifiers_in(shown);
    json parameters = json::array();
    std::vector<int> listed;
    for (const symbolic::Parameter& p : e.parameters()) {
      const bool shown_here = used.count(p.name) != 0;
      listed.push_back(shown_here ? static_cast<int>(parameters.size()) : -1);
      if (!shown_here) continue;
      json sources = json::array();
      for (const model::ParameterSource& source : p.sources) sources.push_back(source_json(source));
      parameters.push_back({{"name", p.name},
                            {"latex", p.latex},
                            {"value", p.value},
                            {"unit", p.unit},
                            {"sources", std::move(sources)}});
    }
    // The numbers the form depends on (the page's engine checks them after a change).
    json form = json::array();
    for (const symbolic::FormNumber& number : e.form_numbers())
      form.push_back(
          {{"name", number.name}, {"source", source_json(number.source)}, {"value", number.value}});
    for (int r = 0; r < static_cast<int>(equations.size()); ++r)
      equations[static_cast<std::size_t>(r)]["terms"] = terms_json(e, r, listed);
    return {{"available", true},
            {"equations", std::move(equations)},
            {"constraints", std::move(constraints)},
            {"multipliers", e.multiplier_names()},
            {"parameters", std::move(parameters)},
            {"form", std::move(form)}};
  } catch (const InvalidArgument& error) {
    return unavailable(error.what());
  }
}

#else

json equations_json(const io::ModelFile&) {
  return {{"available", false},
          {"reason", "this build leaves the symbolic layer out (MOMENTA_WITH_SYMBOLIC=OFF)"}};
}

#endif  // MOMENTA_WITH_SYMBOLIC

}  // namespace momenta::report::detail
