// `momenta equations MODEL [--symbols NAME,...|--all-symbols] [--form lagrange|matrix]
// [--latex|--json|--cpp|--python]`: a model's equations of motion in symbols. Calls
// momenta::symbolic (equations.hpp); documented in docs/equations.md and docs/cli.md.

#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "momenta/common/error.hpp"
#include "momenta/frontend/model_loading.hpp"
#include "momenta/symbolic/equations.hpp"
#include "output_format.hpp"

namespace momenta::cli {
namespace {

using json = nlohmann::ordered_json;

struct EquationsOptions {
  std::string model;
  std::vector<std::string> symbols;
  bool all_symbols = false;
  std::string form = "lagrange";
  bool latex = false, json = false, cpp = false, python = false;
  std::string name;  // the generated code's namespace or module name
};

void print_equations(const io::ModelFile& file, const symbolic::Equations& e,
                     const EquationsOptions& o) {
  const symbolic::Format f = o.latex ? symbolic::Format::latex : symbolic::Format::text;
  const auto& free = e.free_speeds();
  const int n = static_cast<int>(free.size());
  if (!o.latex) fmt::print("{}: equations of motion\n", file.name);
  if (o.form == "matrix") {
    fmt::print("{}M(q) v̇ + C(q, v) v + g(q) = Q(q, v, u), v̇ = [", o.latex ? "% " : "");
    for (int r = 0; r < n; ++r)
      fmt::print("{}{}", r ? ", " : "", e.acceleration_names()[static_cast<std::size_t>(free[r])]);
    fmt::print("]\n");
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) fmt::print("M[{},{}] = {}\n", r, c, e.mass_matrix_entry(r, c, f));
    for (int r = 0; r < n; ++r) fmt::print("(C v)[{}] = {}\n", r, e.velocity_product(r, f));
    for (int r = 0; r < n; ++r) fmt::print("g[{}] = {}\n", r, e.gravity(r, f));
    for (int r = 0; r < n; ++r) fmt::print("Q[{}] = {}\n", r, e.generalized_force(r, f));
    return;
  }
  for (int r = 0; r < n; ++r) fmt::print("{}\n", e.equation(r, f));
}

json equations_json(const io::ModelFile& file, const symbolic::Equations& e) {
  const auto& free = e.free_speeds();
  const int n = static_cast<int>(free.size());
  json parameters = json::object();
  for (const symbolic::Parameter& p : e.parameters()) parameters[p.name] = p.value;
  json M = json::array(), rest = json::array(), g = json::array(), Q = json::array(),
       equations = json::array(), equations_latex = json::array();
  for (int r = 0; r < n; ++r) {
    json row = json::array();
    for (int c = 0; c < n; ++c) row.push_back(e.mass_matrix_entry(r, c, symbolic::Format::text));
    M.push_back(std::move(row));
    rest.push_back(e.velocity_product(r, symbolic::Format::text));
    g.push_back(e.gravity(r, symbolic::Format::text));
    Q.push_back(e.generalized_force(r, symbolic::Format::text));
    equations.push_back(e.equation(r, symbolic::Format::text));
    equations_latex.push_back(e.equation(r, symbolic::Format::latex));
  }
  std::vector<std::string> accelerations;
  for (int i : free) accelerations.push_back(e.acceleration_names()[static_cast<std::size_t>(i)]);
  return {{"model", file.name},
          {"coordinates", e.configuration_names()},
          {"speeds", e.speed_names()},
          {"accelerations", accelerations},
          {"inputs", e.input_names()},
          {"parameters", parameters},
          {"equations", equations},
          {"equations_latex", equations_latex},
          {"M", M},
          {"velocity_product", rest},
          {"gravity", g},
          {"generalized_force", Q}};
}

void run(const EquationsOptions& o) {
  const io::ModelFile file = frontend::load_model(o.model);
  symbolic::EquationOptions options;
  options.symbols = o.symbols;
  options.all_symbols = o.all_symbols;
  const symbolic::Equations e = symbolic::derive_equations(file.model, options);
  if (o.cpp || o.python) {
    fmt::print("{}", e.generate_code(o.cpp ? symbolic::Format::cpp : symbolic::Format::python,
                                     o.name.empty() ? file.name : o.name));
  } else if (o.json) {
    fmt::print("{}\n", json_text(equations_json(file, e), ListSpacing::spaced));
  } else {
    print_equations(file, e, o);
  }
}

}  // namespace

void add_equations_command(CLI::App& app) {
  auto options = std::make_shared<EquationsOptions>();
  CLI::App* command = app.add_subcommand(
      "equations", "Equations of motion in symbols: M(q) v̇ + C(q, v) v + g(q) = Q (GiNaC)");
  command->add_option("MODEL", options->model, "A model file (.yaml)")->required();
  CLI::Option* symbols =
      command
          ->add_option("--symbols", options->symbols,
                       "Parameters to keep as symbols, comma-separated (m_<body>, g, k_<spring>, "
                       "...; docs/equations.md)")
          ->delimiter(',');
  command->add_flag("--all-symbols", options->all_symbols, "Every nonzero parameter a symbol")
      ->excludes(symbols);
  command
      ->add_option("--form", options->form,
                   "lagrange: one equation per coordinate (default); matrix: M, C v, g and Q")
      ->check(CLI::IsMember({"lagrange", "matrix"}));
  CLI::Option* latex = command->add_flag("--latex", options->latex, "Print LaTeX");
  CLI::Option* json_flag =
      command->add_flag("--json", options->json, "Print JSON (text and LaTeX strings)");
  CLI::Option* cpp =
      command->add_flag("--cpp", options->cpp, "Print a C++ header computing M and b");
  CLI::Option* python =
      command->add_flag("--python", options->python, "Print a Python module computing M and b");
  latex->excludes(json_flag)->excludes(cpp)->excludes(python);
  json_flag->excludes(cpp)->excludes(python);
  cpp->excludes(python);
  command->add_option("--name", options->name,
                      "Namespace (C++) or module name of the generated code (default: the "
                      "model's name)");
  command->footer(
      "Example:\n"
      "  momenta equations examples/cruise_control.yaml --all-symbols\n"
      "Conventions and proofs: docs/equations.md.");
  command->callback([options] { run(*options); });
}

}  // namespace momenta::cli
