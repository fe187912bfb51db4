#pragma once
// What symbolic::Equations holds: the symbols and the derived expressions (equations.cpp derives
// them, printing.cpp prints them and generates code).

#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <ginac/ginac.h>

#include "momenta/symbolic/equations.hpp"

namespace momenta::symbolic {

namespace detail {
/// What each symbol of the equations stands for, by name: the printer orders terms and factors
/// by it (symbolic/term_order.hpp).
enum class SymbolRole { parameter, input, coordinate, speed, acceleration };
struct PrintRoles {
  struct Entry {
    SymbolRole role = SymbolRole::parameter;
    int index = 0;  // the coordinate's place in the model (speeds and accelerations alike)
  };
  std::map<std::string, Entry, std::less<>> by_name;
  /// The coordinate (velocity index) whose acceleration leads a sum: an equation's own, as a
  /// textbook writes equation k with its diagonal term first; −1 for none.
  int leading_acceleration = -1;
  /// What text and LaTeX write for a symbol instead of its name (EquationOptions::greek).
  struct Display {
    std::string text, latex;
  };
  std::map<std::string, Display, std::less<>> display;
  /// The printer's memo of each term's place in a sum (term_class), by expression: a term met
  /// again deeper in the tree is not walked again.
  struct Hash {
    std::size_t operator()(const GiNaC::ex& e) const { return e.gethash(); }
  };
  mutable std::unordered_map<GiNaC::ex, std::pair<int, int>, Hash, GiNaC::ex_is_equal> term_classes;
};

/// The most terms and factors an expression may print as in text or LaTeX (a few megabytes).
inline constexpr double kMaxPrintedNodes = 3e5;

/// Throws InvalidArgument when e printed as a tree (every shared part repeated) would pass
/// kMaxPrintedNodes, saying `instead` what to use (by default the generated code). Counts over
/// the graph: fast.
void check_printable(const GiNaC::ex& e, std::string_view instead =
                                             "the same equations written as code (‹code›) compute "
                                             "each shared part once");
/// A name fit for code and for GiNaC's parser: letters, digits and '_' (others become '_').
std::string identifier(const std::string& name);
/// An expression printed in `format`: numbers as short decimals in text and LaTeX; in text and
/// LaTeX sums and products in a fixed order that `roles` gives (accelerations first, then
/// speeds, then the rest; parameters before functions before coordinates within a product), the
/// same bytes on every run. Throws InvalidArgument when the text would pass kMaxPrintedNodes.
std::string print(const GiNaC::ex& e, Format format, const PrintRoles* roles = nullptr);
}  // namespace detail

struct Equations::Impl {
  // Per model coordinate: the expression standing for q_i, v_i and v̇_i (a symbol of its own, or
  // a prescribing signal's value, rate and acceleration).
  std::vector<GiNaC::ex> q, v, vdot;
  std::vector<std::string> q_names, v_names, a_names;
  std::vector<int> free;  // model v indices with an equation
  // Signals that scale loads (inputs u), and the parameters kept as symbols.
  std::vector<GiNaC::symbol> inputs;
  std::vector<std::string> input_names;
  std::vector<GiNaC::symbol> parameter_symbols;
  std::vector<Parameter> parameters;
  std::vector<FormNumber> form_numbers;
  // The equations: for each free speed k, Σ_j M(k, j) v̇_j + rest[k] + g[k] = Q[k].
  GiNaC::matrix M;
  std::vector<GiNaC::ex> rest, g, Q;
  int nq = 0, nv = 0;
  // Symbols written otherwise in text and LaTeX (θ̈ for pivot_ddot with EquationOptions::greek).
  std::map<std::string, detail::PrintRoles::Display, std::less<>> display;
  // The Newton–Euler form: per body six rows (those not 0 = 0), then each free joint's rows
  // along its motion; the reactions' symbols per joint R_x, R_y, R_z, N_x, N_y, N_z.
  struct NewtonEulerRow {
    std::string body, label;
    GiNaC::ex loads, kinetic;
  };
  std::vector<NewtonEulerRow> newton_euler;
  bool newton_euler_planar = false;             // three rows per body in its plane of motion
  std::vector<GiNaC::symbol> reaction_symbols;  // the joints', then the multipliers
  // The constraints (model order, the rows of dynamics::ConstraintRows): φ(q) on holonomic rows,
  // G over every model speed, k = Ġ v at v̇ = 0, the multiplier λ. The equations above read
  // M v̇ + C v + g = Q + Gᵀλ (free columns of G) with G v̇ + k = 0.
  struct ConstraintRow {
    std::string name;
    bool holonomic = false;
    GiNaC::ex position, bias;
    std::vector<GiNaC::ex> G;
    GiNaC::symbol multiplier;
  };
  std::vector<ConstraintRow> constraints;

  /// The roles of q, v, v̇ and the inputs (every other symbol a parameter or an unknown force).
  detail::PrintRoles roles() const;
};

}  // namespace momenta::symbolic
