// `momenta equations MODEL [--symbols NAME,...|--all-symbols] [--form lagrange|matrix|linear]
// [--transfer INPUT:OUTPUT] [--time T|--state FILE] [--text|--latex|--json|--cpp|--python]`: a
// model's equations of motion in symbols, their linearization and transfer functions. Calls
// momenta::symbolic (equations.hpp, linear_equations.hpp); documented in docs/equations.md and
// docs/cli.md.

#include <algorithm>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "commands.hpp"
#include "model_argument.hpp"
#include "momenta/common/error.hpp"
#include "momenta/frontend/model_loading.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta/model/euler_coordinates.hpp"
#include "momenta/symbolic/equations.hpp"
#include "momenta/symbolic/linear_equations.hpp"
#include "output_format.hpp"
#include "state_file.hpp"

namespace momenta::cli {
namespace {

using json = nlohmann::ordered_json;

struct EquationsOptions {
  ModelArgument model;
  std::vector<std::string> symbols;
  bool all_symbols = false;
  bool greek = false;  // --greek, or the word greek in --symbols
  std::string form = "lagrange";
  bool principal_axes = false;
  bool normal_tangential = false;  // --nt
  bool text = false, latex = false, json = false, cpp = false, python = false;
  std::string name;                        // the generated code's namespace or module name
  std::string transfer;                    // INPUT:OUTPUT
  InstantOptions instant;                  // the operating point of --form linear and --transfer
  std::string coordinates = "quaternion";  // or euler:SEQUENCE for ball and free joints
};

// The linearization about the instant the options name (the initial state by default).
symbolic::LinearEquations linear_equations(const io::ModelFile& file, const symbolic::Equations& e,
                                           const EquationsOptions& o) {
  const integrate::State point = instant_of(file, o.instant);
  return symbolic::linearize_equations(e, file.model, point.t, point.q, point.v);
}

const char* matrix_name(symbolic::LinearMatrix which) {
  static const char* const names[] = {"M", "D", "K", "B0", "B1", "B2", "A", "B"};
  return names[static_cast<int>(which)];
}

void print_linear(const io::ModelFile& file, const symbolic::LinearEquations& l,
                  symbolic::Format f) {
  using symbolic::LinearMatrix;
  fmt::print(
      "{}: linearized about the operating point, M δq̈ + D δq̇ + K δq = B0 δu + B1 δu̇ + "
      "B2 δü\n",
      file.name);
  fmt::print("coordinates δq = [{}], inputs u = [{}]\n", fmt::join(l.coordinate_names(), ", "),
             fmt::join(l.input_names(), ", "));
  std::vector<LinearMatrix> shown = {LinearMatrix::M, LinearMatrix::D, LinearMatrix::K,
                                     LinearMatrix::B0};
  if (l.has_input_rates()) {
    shown.push_back(LinearMatrix::B1);
    shown.push_back(LinearMatrix::B2);
  }
  if (l.has_state_space()) {
    shown.push_back(LinearMatrix::A);
    shown.push_back(LinearMatrix::B);
  }
  for (const LinearMatrix which : shown) {
    for (int r = 0; r < l.rows(which); ++r)
      for (int c = 0; c < l.columns(which); ++c)
        fmt::print("{}[{},{}] = {}\n", matrix_name(which), r, c, l.entry(which, r, c, f));
  }
  if (!l.has_state_space()) {
    fmt::print("(no A, B: {})\n", l.has_input_rates()
                                      ? "an input's rate enters; use the second-order form"
                                      : "more than four coordinates");
  }
}

// --transfer INPUT:OUTPUT: the input by signal name; the output an `outputs:` entry of a joint's
// position or velocity, or a coordinate's name (its rate with "_dot").
void print_transfer(const io::ModelFile& file, const symbolic::LinearEquations& l,
                    const EquationsOptions& o, symbolic::Format f) {
  const auto colon = o.transfer.find(':');
  if (colon == std::string::npos) {
    throw CLI::ValidationError("--transfer",
                               fmt::format("'{}': expected INPUT:OUTPUT", o.transfer));
  }
  const std::string input = o.transfer.substr(0, colon), output = o.transfer.substr(colon + 1);
  const auto& inputs = l.input_names();
  const auto in = std::find(inputs.begin(), inputs.end(), input);
  if (in == inputs.end()) {
    throw CLI::ValidationError("--transfer", fmt::format("no input '{}'; the inputs are {}", input,
                                                         fmt::join(inputs, ", ")));
  }
  // The coordinate and whether the rate is meant.
  std::string coordinate = output;
  bool rate = false;
  for (const model::OutputSpec& spec : file.outputs) {
    if (spec.name != output) continue;
    if (spec.quantity != model::OutputQuantity::joint_position &&
        spec.quantity != model::OutputQuantity::joint_velocity) {
      throw CLI::ValidationError(
          "--transfer", fmt::format("output '{}' is not a joint's position or velocity", output));
    }
    coordinate = spec.target;
    rate = spec.quantity == model::OutputQuantity::joint_velocity;
  }
  if (coordinate.size() > 4 && coordinate.ends_with("_dot")) {
    coordinate.resize(coordinate.size() - 4);
    rate = true;
  }
  const auto& names = l.coordinate_names();
  const auto k = std::find(names.begin(), names.end(), coordinate);
  if (k == names.end()) {
    throw CLI::ValidationError(
        "--transfer", fmt::format("no free coordinate or joint output '{}'; the coordinates are {}",
                                  output, fmt::join(names, ", ")));
  }
  const std::string G = l.transfer_function(static_cast<int>(in - inputs.begin()),
                                            static_cast<int>(k - names.begin()), rate, f);
  if (o.json) {
    // The transfer function in text and LaTeX, as the equations' JSON gives each equation.
    nlohmann::ordered_json j;
    j["model"] = file.name;
    j["input"] = input;
    j["output"] = output;
    j["text"] = G;
    j["latex"] =
        l.transfer_function(static_cast<int>(in - inputs.begin()),
                            static_cast<int>(k - names.begin()), rate, symbolic::Format::latex);
    fmt::print("{}\n", json_text(j, ListSpacing::spaced));
  } else if (f == symbolic::Format::latex) {
    fmt::print("G(s) = {}\n", G);
  } else {
    fmt::print("{}: G(s) = {}(s) / {}(s) = {}\n", file.name, output, input, G);
  }
}

// The characters a text shows: UTF-8 lead bytes, less the combining dots over θ (U+0307,
// U+0308: "\xCC\x87", "\xCC\x88"), which sit on the letter before them.
std::size_t shown_width(std::string_view text) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    const bool combining = byte == 0xCC && i + 1 < text.size() &&
                           (static_cast<unsigned char>(text[i + 1]) == 0x87 ||
                            static_cast<unsigned char>(text[i + 1]) == 0x88);
    if ((byte & 0xC0) != 0x80 && !combining) ++n;
  }
  return n;
}

// A long equation broken at its terms, as a textbook sets it: at " + ", " - " and " = " outside
// parentheses, each line kept under `width` characters where the terms allow, the continuation
// lines indented by four spaces. Short equations come back as they are.
std::string wrapped(const std::string& equation, std::size_t width = 100) {
  if (shown_width(equation) <= width) return equation;
  std::string out, line;
  int depth = 0;
  std::size_t start = 0;
  const auto flush_term = [&](std::size_t end) {
    const std::string term = equation.substr(start, end - start);
    if (!line.empty() && shown_width(line) + shown_width(term) > width) {
      out += line + "\n";
      line = "   ";  // the term carries its leading space: four in all
    }
    line += term;
    start = end;
  };
  for (std::size_t i = 0; i < equation.size(); ++i) {
    const char c = equation[i];
    depth += c == '(' ? 1 : c == ')' ? -1 : 0;
    if (depth == 0 && c == ' ' && i + 2 < equation.size() && equation[i + 2] == ' ' &&
        (equation[i + 1] == '+' || equation[i + 1] == '-' || equation[i + 1] == '=')) {
      flush_term(i);
    }
  }
  flush_term(equation.size());
  return out + line;
}

// The constraints' rows after the equations: φ = 0 (or G v = 0 on velocity rows), and with
// --form matrix G's entries and k.
std::string constraint_rows_text(const symbolic::Equations& e, const EquationsOptions& o,
                                 symbolic::Format f) {
  std::string out;
  if (e.constraint_rows() == 0) return out;
  const char* comment = o.latex ? "% " : "";
  fmt::format_to(std::back_inserter(out),
                 "{}constraints: M v̇ + C v + g = Q + Gᵀλ, G v̇ + k = 0; λ the rows' forces [{}]\n",
                 comment, fmt::join(e.multiplier_names(), ", "));
  for (int r = 0; r < e.constraint_rows(); ++r) {
    const std::string equation = e.constraint_equation(r, f);
    fmt::format_to(std::back_inserter(out), "{}{} ({}):\n  {}{}\n", comment,
                   e.constraint_row_name(r),
                   e.constraint_row_holonomic(r) ? "position" : "velocity", equation,
                   equation == "0 = 0" ? "  (identically: the tree's joints impose it)" : "");
  }
  if (o.form != "matrix") return out;
  const int n = static_cast<int>(e.free_speeds().size());
  for (int r = 0; r < e.constraint_rows(); ++r) {
    for (int c = 0; c < n; ++c)
      fmt::format_to(std::back_inserter(out), "G[{},{}] = {}\n", r, c,
                     e.constraint_jacobian_entry(r, c, f));
  }
  for (int r = 0; r < e.constraint_rows(); ++r)
    fmt::format_to(std::back_inserter(out), "k[{}] = {}\n", r, e.constraint_bias(r, f));
  return out;
}

// The equations as `equations` prints them, whole: nothing is printed when one of them cannot
// be (too large to print: then the error alone).
std::string equations_text(const io::ModelFile& file, const symbolic::Equations& e,
                           const EquationsOptions& o) {
  std::string out;
  const symbolic::Format f = o.latex ? symbolic::Format::latex : symbolic::Format::text;
  const auto& free = e.free_speeds();
  const int n = static_cast<int>(free.size());
  if (!o.latex) fmt::format_to(std::back_inserter(out), "{}: equations of motion\n", file.name);
  if (o.form == "newton-euler") {
    fmt::format_to(
        std::back_inserter(out),
        "{}{}; unknown reactions R_<joint> (force on the child), N_<joint> (moment about J'), in "
        "the child's axes{}\n",
        o.latex ? "% " : "",
        e.newton_euler_planar()
            ? "planar motion, per body in its plane and its own axes: ΣF = m a_G, ΣM_G = Ī α"
            : "per body, in its own axes: ΣF = m a_G, ΣM_G = Ī α + ω × Ī ω",
        e.constraint_rows() > 0 ? "; the constraints' forces by their multipliers λ" : "");
    std::string group;
    for (int r = 0; r < e.newton_euler_rows(); ++r) {
      if (e.newton_euler_group(r) != group) {
        group = e.newton_euler_group(r);
        fmt::format_to(std::back_inserter(out), "{}{}\n", o.latex ? "% " : "", group);
      }
      fmt::format_to(std::back_inserter(out), "  {}\n", e.newton_euler_equation(r, f));
    }
    return out;
  }
  if (o.form == "matrix") {
    fmt::format_to(std::back_inserter(out), "{}M(q) v̇ + C(q, v) v + g(q) = Q(q, v, u), v̇ = [",
                   o.latex ? "% " : "");
    for (int r = 0; r < n; ++r)
      fmt::format_to(std::back_inserter(out), "{}{}", r ? ", " : "",
                     e.acceleration_names()[static_cast<std::size_t>(free[r])]);
    fmt::format_to(std::back_inserter(out), "]\n");
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        fmt::format_to(std::back_inserter(out), "M[{},{}] = {}\n", r, c,
                       e.mass_matrix_entry(r, c, f));
    for (int r = 0; r < n; ++r)
      fmt::format_to(std::back_inserter(out), "(C v)[{}] = {}\n", r, e.velocity_product(r, f));
    for (int r = 0; r < n; ++r)
      fmt::format_to(std::back_inserter(out), "g[{}] = {}\n", r, e.gravity(r, f));
    for (int r = 0; r < n; ++r)
      fmt::format_to(std::back_inserter(out), "Q[{}] = {}\n", r, e.generalized_force(r, f));
    out += constraint_rows_text(e, o, f);
    return out;
  }
  for (int r = 0; r < n; ++r) {
    const std::string equation = e.equation(r, f);
    fmt::format_to(std::back_inserter(out), "{}\n", o.latex ? equation : wrapped(equation));
  }
  out += constraint_rows_text(e, o, f);
  return out;
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
  json constraints = json::array();
  const std::vector<std::string> multipliers = e.multiplier_names();
  for (int r = 0; r < e.constraint_rows(); ++r) {
    json G = json::array();
    for (int c = 0; c < n; ++c)
      G.push_back(e.constraint_jacobian_entry(r, c, symbolic::Format::text));
    constraints.push_back({{"name", e.constraint_row_name(r)},
                           {"multiplier", multipliers[static_cast<std::size_t>(r)]},
                           {"holonomic", e.constraint_row_holonomic(r)},
                           {"equation", e.constraint_equation(r, symbolic::Format::text)},
                           {"equation_latex", e.constraint_equation(r, symbolic::Format::latex)},
                           {"G", std::move(G)},
                           {"k", e.constraint_bias(r, symbolic::Format::text)}});
  }
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
          {"generalized_force", Q},
          {"constraints", constraints}};
}

// The equations with the options' symbols and the file's names for them (its `symbols:`
// section, whose entries a mistake is reported at).
symbolic::Equations derive(const io::ModelFile& file, const EquationsOptions& o) {
  symbolic::EquationOptions options;
  options.greek = o.greek;
  for (const std::string& name : o.symbols) {
    if (name == "greek") {
      options.greek = true;
    } else {
      options.symbols.push_back(name);
    }
  }
  if (o.all_symbols && !options.symbols.empty()) {
    throw CLI::ValidationError("--symbols", "names parameters; --all-symbols keeps every one");
  }
  options.all_symbols = o.all_symbols;
  options.newton_euler = o.form == "newton-euler";
  options.principal_axes = o.principal_axes;
  options.normal_tangential = o.normal_tangential;
  options.names = file.given_symbol_names();
  try {
    return symbolic::derive_equations(file.model, options);
  } catch (const InvalidArgument& error) {
    // A name the symbols: section gives (or gives as) that the equations refuse: at its line.
    if (error.symbol()) {
      for (const auto& [name, given] : file.symbol_names) {
        if (name != *error.symbol() && given.name != *error.symbol()) continue;
        throw ParseError(file.file, given.line, given.column, error.what());
      }
    }
    throw;
  }
}

void run(const EquationsOptions& o) {
  io::ModelFile file = load_model(o.model);
  // Ball and free joints in Euler angles (precession, nutation, spin), as the notes write a top:
  // every form below, and a state file, then speak of those coordinates.
  if (o.coordinates.starts_with("euler:")) {
    file.model = model::with_euler_coordinates(file.model, o.coordinates.substr(6));
  }
  // The instant is the operating point of a linearization; the equations themselves hold at
  // every instant, so --time or --state elsewhere is a mistake, not something to ignore.
  const bool linearizes = !o.transfer.empty() || o.form == "linear";
  if (!linearizes && (o.instant.time || o.instant.state)) {
    throw CLI::ValidationError(o.instant.time ? "--time" : "--state",
                               "sets the operating point of --form linear and --transfer; the "
                               "equations of motion hold at every instant");
  }
  const symbolic::Equations e = derive(file, o);
  const symbolic::Format f = o.latex ? symbolic::Format::latex : symbolic::Format::text;
  if (!o.transfer.empty()) {
    print_transfer(file, linear_equations(file, e, o), o, f);
  } else if (o.form == "linear") {
    print_linear(file, linear_equations(file, e, o), f);
  } else if (o.cpp || o.python) {
    fmt::print("{}", e.generate_code(o.cpp ? symbolic::Format::cpp : symbolic::Format::python,
                                     o.name.empty() ? file.name : o.name));
  } else if (o.json) {
    fmt::print("{}\n", json_text(equations_json(file, e), ListSpacing::spaced));
  } else {
    fmt::print("{}", equations_text(file, e, o));
  }
}

}  // namespace

void add_equations_command(CLI::App& app) {
  auto options = std::make_shared<EquationsOptions>();
  CLI::App* command = app.add_subcommand(
      "equations", "Equations of motion in symbols: M(q) v̇ + C(q, v) v + g(q) = Q (GiNaC)");
  add_model_argument(command, options->model);
  CLI::Option* symbols =
      command
          ->add_option("--symbols", options->symbols,
                       "Parameters to keep as symbols, comma-separated (m_<body>, g, L_<body>, "
                       "k_<spring>, ...; docs/equations.md); the word greek: as --greek")
          ->delimiter(',');
  (void)symbols;
  command->add_flag("--all-symbols", options->all_symbols, "Every nonzero parameter a symbol");
  command->add_flag("--greek", options->greek,
                    "Text and LaTeX write revolute joints' angles θ (θ₁, θ₂, …), their rates θ̇ "
                    "and accelerations θ̈");
  command
      ->add_option("--form", options->form,
                   "lagrange: one equation per coordinate (default); matrix: M, C v, g and Q; "
                   "newton-euler: each body's ΣF = m a_G and ΣM_G = Ḣ_G with the reactions; "
                   "linear: M, D, K, B (and A, B) about the operating point")
      ->check(CLI::IsMember({"lagrange", "matrix", "newton-euler", "linear"}));
  command->add_flag("--principal-axes", options->principal_axes,
                    "With --form newton-euler: a body with products of inertia in its principal "
                    "axes at G (Euler's equations I1 α1 − (I2 − I3) ω2 ω3 = ΣM_G1 ...)");
  command->add_flag("--nt", options->normal_tangential,
                    "With --form newton-euler on a planar model: a body on a fixed pivot with "
                    "ΣF_n = m r̄ ω² and ΣF_t = m r̄ α (n towards the pivot, t along G's motion)");
  command
      ->add_option("--coordinates", options->coordinates,
                   "Ball and free joints' rotation: quaternion (the default, as the engine "
                   "integrates it) or euler:SEQUENCE, three Euler angles phi, theta, psi as the "
                   "notes write a top (euler:ZXZ: precession, nutation, spin)")
      ->check(CLI::Validator(
          [](std::string& value) -> std::string {
            if (value == "quaternion") return {};
            if (value.starts_with("euler:")) {
              try {
                check_euler_sequence(value.substr(6));
                return {};
              } catch (const InvalidArgument& e) {
                return e.what();
              }
            }
            return fmt::format("'{}': give quaternion or euler:SEQUENCE (euler:ZXZ)", value);
          },
          "quaternion|euler:ZXZ"));
  command->add_option("--transfer", options->transfer,
                      "INPUT:OUTPUT — the transfer function in s from a signal to a joint "
                      "output (or a coordinate, its rate with _dot), about the operating point");
  add_instant_options(command, options->instant);
  CLI::Option* text = command->add_flag("--text", options->text, "Print text (the default)");
  CLI::Option* latex = command->add_flag("--latex", options->latex, "Print LaTeX");
  CLI::Option* json_flag =
      command->add_flag("--json", options->json, "Print JSON (text and LaTeX strings)");
  CLI::Option* cpp =
      command->add_flag("--cpp", options->cpp, "Print a C++ header computing M and b");
  CLI::Option* python =
      command->add_flag("--python", options->python, "Print a Python module computing M and b");
  text->excludes(latex)->excludes(json_flag)->excludes(cpp)->excludes(python);
  latex->excludes(json_flag)->excludes(cpp)->excludes(python);
  json_flag->excludes(cpp)->excludes(python);
  cpp->excludes(python);
  command->add_option("--name", options->name,
                      "Namespace (C++) or module name of the generated code (default: the "
                      "model's name)");
  command->footer(
      "Example:\n"
      "  momenta equations examples/cruise_control.yaml --all-symbols\n"
      "  momenta equations examples/cruise_control.yaml --all-symbols --transfer u:speed\n"
      "Conventions and proofs: docs/equations.md.");
  command->callback([options] { run(*options); });
}

}  // namespace momenta::cli
