// Printing the equations (text, LaTeX, C++, Python), evaluating them at a state, and generating
// code (equations.hpp).

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "code_emitter.hpp"
#include "equations_impl.hpp"
#include "momenta/common/error.hpp"

namespace momenta::symbolic {
namespace {

using detail::print;
using GiNaC::ex;
using GiNaC::symbol;

// An expression of the equations printed with its symbols' roles (terms and factors in order),
// the acceleration of velocity coordinate `leading` first where it appears.
std::string print_in(const Equations::Impl& impl, const ex& e, Format format, int leading = -1) {
  detail::PrintRoles roles = impl.roles();
  roles.leading_acceleration = leading;
  return print(e, format, &roles);
}

// Splits Q into the terms with an input (the right-hand side, as a textbook writes u) and the
// rest (moved to the left).
std::pair<ex, ex> split_inputs(const ex& Q, const std::vector<symbol>& inputs) {
  ex with = 0, without = 0;
  const ex e = GiNaC::expand(Q);
  const auto has_input = [&](const ex& term) {
    for (const symbol& u : inputs)
      if (term.has(u)) return true;
    return false;
  };
  if (GiNaC::is_a<GiNaC::add>(e)) {
    for (const ex& term : e) (has_input(term) ? with : without) += term;
  } else {
    (has_input(e) ? with : without) += e;
  }
  return {with, without};
}

void check_row(const Equations::Impl& impl, int row, const char* what) {
  if (row < 0 || row >= static_cast<int>(impl.free.size())) {
    throw InvalidArgument(
        fmt::format("Equations::{}: row {} outside [0, {})", what, row, impl.free.size()));
  }
}

void check_sizes(const Equations::Impl& impl, const VecX& q, const VecX& v, const VecX& vdot,
                 const VecX& u, const char* what) {
  if (q.size() != impl.nq || v.size() != impl.nv || vdot.size() != impl.nv ||
      u.size() != static_cast<Eigen::Index>(impl.inputs.size())) {
    throw InvalidArgument(fmt::format(
        "Equations::{}: q, v, vdot, u have {}, {}, {}, {} values; expected {}, {}, {}, {}", what,
        q.size(), v.size(), vdot.size(), u.size(), impl.nq, impl.nv, impl.nv, impl.inputs.size()));
  }
}

// The map from every symbol to numbers: coordinates, speeds, accelerations, inputs, parameters.
GiNaC::exmap numbers_for(const Equations::Impl& impl, const VecX& q, const VecX& v,
                         const VecX& vdot, const VecX& u) {
  GiNaC::exmap m;
  const auto put = [&](const ex& s, double x) {
    if (GiNaC::is_a<symbol>(s)) m[s] = GiNaC::numeric(x);
  };
  for (int i = 0; i < impl.nq; ++i) put(impl.q[i], q[i]);
  for (int i = 0; i < impl.nv; ++i) {
    put(impl.v[i], v[i]);
    put(impl.vdot[i], vdot[i]);
  }
  for (std::size_t k = 0; k < impl.inputs.size(); ++k)
    put(impl.inputs[k], u[static_cast<Eigen::Index>(k)]);
  for (std::size_t k = 0; k < impl.parameters.size(); ++k)
    put(impl.parameter_symbols[k], impl.parameters[k].value);
  return m;
}

// The value of an expression with every symbol given a number, each distinct subexpression
// evaluated once (the entries share most of theirs: substituting into each as a tree would take
// time exponential in the depth of the tree of bodies).
class Evaluator {
 public:
  explicit Evaluator(const GiNaC::exmap& numbers) : numbers_(numbers) {}
  double operator()(const ex& e) {
    if (GiNaC::is_a<GiNaC::numeric>(e)) return GiNaC::ex_to<GiNaC::numeric>(e).to_double();
    if (const auto it = memo_.find(e); it != memo_.end()) return it->second;
    const double x = compute(e);
    memo_.emplace(e, x);
    return x;
  }

 private:
  double compute(const ex& e) {
    if (GiNaC::is_a<symbol>(e)) {
      const auto it = numbers_.find(e);
      if (it == numbers_.end()) {
        throw InvalidArgument(fmt::format("Equations::evaluate: no value for '{}'",
                                          GiNaC::ex_to<symbol>(e).get_name()));
      }
      return GiNaC::ex_to<GiNaC::numeric>(it->second).to_double();
    }
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
      const bool sum = GiNaC::is_a<GiNaC::add>(e);
      double x = sum ? 0.0 : 1.0;
      for (std::size_t i = 0; i < e.nops(); ++i)
        x = sum ? x + (*this)(e.op(i)) : x * (*this)(e.op(i));
      return x;
    }
    if (GiNaC::is_a<GiNaC::power>(e)) return std::pow((*this)(e.op(0)), (*this)(e.op(1)));
    if (GiNaC::is_a<GiNaC::function>(e)) {
      const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
      const double x = (*this)(e.op(0));
      if (name == "sin") return std::sin(x);
      if (name == "cos") return std::cos(x);
      if (name == "sqrt") return std::sqrt(x);
    }
    throw InvalidArgument(
        fmt::format("Equations::evaluate: cannot evaluate '{}'", print(e, Format::text)));
  }
  const GiNaC::exmap& numbers_;
  std::map<ex, double, GiNaC::ex_is_less> memo_;
};

// Code symbols: q[i], v[i], vdot[i], u[k]; parameters keep their names (declared as constants).
GiNaC::exmap code_symbols(const Equations::Impl& impl) {
  GiNaC::exmap m;
  const auto put = [&](const ex& s, const std::string& name) {
    if (GiNaC::is_a<symbol>(s) && m.count(s) == 0) m[s] = symbol(name);
  };
  for (int i = 0; i < impl.nq; ++i) put(impl.q[i], fmt::format("q[{}]", i));
  for (int i = 0; i < impl.nv; ++i) {
    put(impl.v[i], fmt::format("v[{}]", i));
    put(impl.vdot[i], fmt::format("vdot[{}]", i));
  }
  for (std::size_t k = 0; k < impl.inputs.size(); ++k) put(impl.inputs[k], fmt::format("u[{}]", k));
  return m;
}

}  // namespace

std::string Equations::mass_matrix_entry(int row, int column, Format format) const {
  check_row(*impl_, row, "mass_matrix_entry");
  check_row(*impl_, column, "mass_matrix_entry");
  return print_in(*impl_, impl_->M(static_cast<unsigned>(row), static_cast<unsigned>(column)),
                  format);
}

std::string Equations::velocity_product(int row, Format format) const {
  check_row(*impl_, row, "velocity_product");
  return print_in(*impl_, impl_->rest[static_cast<std::size_t>(row)], format);
}

std::string Equations::gravity(int row, Format format) const {
  check_row(*impl_, row, "gravity");
  return print_in(*impl_, impl_->g[static_cast<std::size_t>(row)], format);
}

std::string Equations::generalized_force(int row, Format format) const {
  check_row(*impl_, row, "generalized_force");
  return print_in(*impl_, impl_->Q[static_cast<std::size_t>(row)], format);
}

namespace {

// Equation `row`'s sides as a textbook writes them: on the left M v̇ + C v + g less the
// generalized forces without an input (collected by acceleration and by each spring's and
// damper's constant), on the right those with one and Gᵀλ; both negated where the row's own
// acceleration's term would lead with a minus.
struct Sides {
  ex left, right, constraint_force;
  std::string left_text;  // in the format asked
};

Sides sides_of(const Equations::Impl& impl, int row, Format format) {
  const auto r = static_cast<std::size_t>(row);
  const auto [right, moved] = split_inputs(impl.Q[r], impl.inputs);
  ex left = impl.rest[r] + impl.g[r] - moved;
  GiNaC::lst accelerations;
  for (std::size_t c = 0; c < impl.free.size(); ++c) {
    left += impl.M(static_cast<unsigned>(row), static_cast<unsigned>(c)) *
            impl.vdot[static_cast<std::size_t>(impl.free[c])];
    accelerations.append(impl.vdot[static_cast<std::size_t>(impl.free[c])]);
  }
  detail::check_printable(left);  // before expanding: that is what takes the time
  // Each spring's and damper's terms over its constant, as the notes write them: k_s (x − y),
  // b (ẋ − ẏ) — the stiffnesses and dampings are the parameters in those units.
  GiNaC::lst grouped = accelerations;
  for (std::size_t k = 0; k < impl.parameters.size(); ++k) {
    const std::string& unit = impl.parameters[k].unit;
    if (unit == "N/m" || unit == "N·s/m" || unit == "N·m/rad" || unit == "N·m·s/rad") {
      grouped.append(impl.parameter_symbols[k]);
    }
  }
  left = GiNaC::collect(GiNaC::expand(left), grouped);
  // The constraint forces' generalized forces Gᵀλ on the right, each λ once.
  ex constraint_force = 0;
  for (const auto& c : impl.constraints)
    constraint_force += c.G[static_cast<std::size_t>(impl.free[r])] * c.multiplier;
  // As a textbook writes equation k: its own acceleration's term first, and positive.
  const int own = impl.free[r];
  std::string left_text = print_in(impl, left, format, own);
  const bool negated = left_text.starts_with("-");
  if (negated) left_text = print_in(impl, -left, format, own);
  const ex sign = negated ? -1 : 1;
  return {sign * left, sign * right, sign * constraint_force, std::move(left_text)};
}

// Whether `factor` is a parameter or a power of one.
bool parameter_factor(const Equations::Impl& impl, const ex& factor, int& index, int& exponent) {
  ex base = factor;
  exponent = 1;
  if (GiNaC::is_a<GiNaC::power>(factor)) {
    const ex e = factor.op(1);
    if (!GiNaC::is_a<GiNaC::numeric>(e) || !GiNaC::ex_to<GiNaC::numeric>(e).is_integer())
      return false;
    base = factor.op(0);
    exponent = GiNaC::ex_to<GiNaC::numeric>(e).to_int();
  }
  if (!GiNaC::is_a<symbol>(base)) return false;
  for (std::size_t k = 0; k < impl.parameter_symbols.size(); ++k) {
    if (base.is_equal(impl.parameter_symbols[k])) {
      index = static_cast<int>(k);
      return true;
    }
  }
  return false;
}

bool has_parameter(const Equations::Impl& impl, const ex& e) {
  for (const symbol& p : impl.parameter_symbols)
    if (e.has(p)) return true;
  return false;
}

// The terms of `e` (expanded) grouped by what multiplies their parameters, appended to `terms`;
// false where a parameter is inside another factor (a function's argument, a sum's power).
bool add_terms(const Equations::Impl& impl, const ex& e, bool right, int own,
               std::vector<EquationTerm>& terms) {
  const ex expanded = GiNaC::expand(e);
  std::vector<ex> sums;
  if (GiNaC::is_a<GiNaC::add>(expanded)) {
    for (const ex& term : expanded) sums.push_back(term);
  } else if (!expanded.is_zero()) {
    sums.push_back(expanded);
  }
  std::map<ex, std::size_t, GiNaC::ex_is_less> group_of;
  std::vector<ex> rests;
  const std::size_t first = terms.size();
  for (const ex& term : sums) {
    std::vector<ex> factors;
    if (GiNaC::is_a<GiNaC::mul>(term)) {
      for (const ex& f : term) factors.push_back(f);
    } else {
      factors.push_back(term);
    }
    EquationTerm::Monomial monomial{1.0, {}};
    ex rest = 1;
    for (const ex& f : factors) {
      int index = 0, exponent = 0;
      if (GiNaC::is_a<GiNaC::numeric>(f)) {
        monomial.factor *= GiNaC::ex_to<GiNaC::numeric>(f).to_double();
      } else if (parameter_factor(impl, f, index, exponent)) {
        monomial.powers.emplace_back(index, exponent);
      } else {
        rest *= f;
      }
    }
    if (has_parameter(impl, rest)) return false;
    auto [it, added] = group_of.try_emplace(rest, terms.size());
    if (added) {
      terms.push_back({{}, print_in(impl, rest, Format::latex, own), right});
      rests.push_back(rest);
    }
    terms[it->second].coefficient.push_back(std::move(monomial));
  }
  // As a textbook orders them: the terms with the row's own acceleration, with the other
  // accelerations, with its own rate, with another free rate, with its own coordinate (where
  // coordinates and speeds are numbered alike: no quaternion), then the rest (other coordinates,
  // prescribed motions, inputs, constants).
  const auto o = static_cast<std::size_t>(own);
  const auto rank = [&](const ex& rest) {
    if (rest.has(impl.vdot[o])) return 0;
    for (int f : impl.free)
      if (rest.has(impl.vdot[static_cast<std::size_t>(f)])) return 1;
    if (rest.has(impl.v[o])) return 2;
    for (int f : impl.free)
      if (rest.has(impl.v[static_cast<std::size_t>(f)])) return 3;
    if (impl.nq == impl.nv && rest.has(impl.q[o])) return 4;
    return 5;
  };
  std::vector<std::size_t> order(rests.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  // Within a rank the shorter first (q̈ before cos(q) q̈), then by their LaTeX: GiNaC's order of a
  // sum's terms follows its symbols' serial numbers, which differ from process to process (the
  // Python module's page must be the CLI's).
  std::vector<int> ranks(rests.size());
  for (std::size_t k = 0; k < rests.size(); ++k) ranks[k] = rank(rests[k]);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (ranks[a] != ranks[b]) return ranks[a] < ranks[b];
    const std::string& la = terms[first + a].latex;
    const std::string& lb = terms[first + b].latex;
    return la.size() != lb.size() ? la.size() < lb.size() : la < lb;
  });
  // Each coefficient's monomials in one order too: their sum's last bit depends on it.
  for (std::size_t k = first; k < terms.size(); ++k) {
    auto& monomials = terms[k].coefficient;
    for (auto& m : monomials) std::sort(m.powers.begin(), m.powers.end());
    std::sort(monomials.begin(), monomials.end(), [](const auto& a, const auto& b) {
      return std::tie(a.powers, a.factor) < std::tie(b.powers, b.factor);
    });
  }
  std::vector<EquationTerm> sorted;
  for (std::size_t k : order) sorted.push_back(std::move(terms[first + k]));
  terms.resize(first);
  for (EquationTerm& t : sorted) terms.push_back(std::move(t));
  return true;
}

}  // namespace

std::string Equations::equation(int row, Format format) const {
  check_row(*impl_, row, "equation");
  const Sides sides = sides_of(*impl_, row, format);
  std::string right_text = print_in(*impl_, sides.right, format);
  if (!sides.constraint_force.is_zero()) {
    GiNaC::lst multipliers;
    for (const auto& c : impl_->constraints) multipliers.append(c.multiplier);
    const std::string forces =
        print_in(*impl_, GiNaC::collect(sides.constraint_force, multipliers), format);
    if (sides.right.is_zero()) {
      right_text = forces;
    } else {
      right_text += forces.starts_with("-") ? " - " + forces.substr(1) : " + " + forces;
    }
  }
  return sides.left_text + " = " + right_text;
}

std::optional<std::vector<EquationTerm>> Equations::equation_terms(int row) const {
  check_row(*impl_, row, "equation_terms");
  const Sides sides = sides_of(*impl_, row, Format::text);
  const int own = impl_->free[static_cast<std::size_t>(row)];
  std::vector<EquationTerm> terms;
  if (!add_terms(*impl_, sides.left, false, own, terms) ||
      !add_terms(*impl_, sides.right, true, own, terms) ||
      !add_terms(*impl_, sides.constraint_force, true, own, terms)) {
    return std::nullopt;
  }
  return terms;
}

int Equations::constraint_rows() const { return static_cast<int>(impl_->constraints.size()); }

const std::string& Equations::constraint_row_name(int row) const {
  return impl_->constraints.at(static_cast<std::size_t>(row)).name;
}

bool Equations::constraint_row_holonomic(int row) const {
  return impl_->constraints.at(static_cast<std::size_t>(row)).holonomic;
}

std::string Equations::constraint_equation(int row, Format format) const {
  const auto& c = impl_->constraints.at(static_cast<std::size_t>(row));
  if (c.holonomic) return print_in(*impl_, c.position, format) + " = 0";
  ex Gv = 0;
  GiNaC::lst speeds;
  for (std::size_t i = 0; i < c.G.size(); ++i) {
    Gv += c.G[i] * impl_->v[i];
    if (!c.G[i].is_zero()) speeds.append(impl_->v[i]);
  }
  return print_in(*impl_, GiNaC::collect(GiNaC::expand(Gv), speeds), format) + " = 0";
}

std::string Equations::constraint_jacobian_entry(int row, int column, Format format) const {
  check_row(*impl_, column, "constraint_jacobian_entry");
  const auto& c = impl_->constraints.at(static_cast<std::size_t>(row));
  return print_in(
      *impl_, c.G[static_cast<std::size_t>(impl_->free[static_cast<std::size_t>(column)])], format);
}

std::string Equations::constraint_bias(int row, Format format) const {
  return print_in(*impl_, impl_->constraints.at(static_cast<std::size_t>(row)).bias, format);
}

std::vector<std::string> Equations::multiplier_names() const {
  std::vector<std::string> names;
  for (const auto& c : impl_->constraints) names.push_back(c.multiplier.get_name());
  return names;
}

void Equations::evaluate_constraints(const VecX& q, const VecX& v, const VecX& u, VecX& position,
                                     MatX& G, VecX& k) const {
  const Impl& impl = *impl_;
  const VecX vdot = VecX::Zero(impl.nv);
  check_sizes(impl, q, v, vdot, u, "evaluate_constraints");
  const GiNaC::exmap numbers = numbers_for(impl, q, v, vdot, u);
  Evaluator value(numbers);
  const auto rows = static_cast<Eigen::Index>(impl.constraints.size());
  position.resize(rows);
  G.resize(rows, impl.nv);
  k.resize(rows);
  for (Eigen::Index r = 0; r < rows; ++r) {
    const auto& c = impl.constraints[static_cast<std::size_t>(r)];
    position[r] = value(c.position);
    for (int i = 0; i < impl.nv; ++i) G(r, i) = value(c.G[static_cast<std::size_t>(i)]);
    k[r] = value(c.bias);
  }
}

int Equations::newton_euler_rows() const { return static_cast<int>(impl_->newton_euler.size()); }

bool Equations::newton_euler_planar() const { return impl_->newton_euler_planar; }

std::string Equations::newton_euler_group(int row) const {
  return impl_->newton_euler.at(static_cast<std::size_t>(row)).body;
}

std::string Equations::newton_euler_equation(int row, Format format) const {
  const auto& r = impl_->newton_euler.at(static_cast<std::size_t>(row));
  return r.label + ":  " + print_in(*impl_, r.loads, format) + " = " +
         print_in(*impl_, r.kinetic, format);
}

std::vector<std::string> Equations::reaction_names() const {
  std::vector<std::string> names;
  for (const symbol& s : impl_->reaction_symbols) names.push_back(s.get_name());
  return names;
}

VecX Equations::newton_euler_residuals(const VecX& q, const VecX& v, const VecX& vdot,
                                       const VecX& u, const VecX& reactions) const {
  const Impl& impl = *impl_;
  if (reactions.size() != static_cast<Eigen::Index>(impl.reaction_symbols.size())) {
    throw InvalidArgument(fmt::format("Equations::newton_euler_residuals: {} reactions for {}",
                                      reactions.size(), impl.reaction_symbols.size()));
  }
  GiNaC::exmap numbers = numbers_for(impl, q, v, vdot, u);
  for (std::size_t k = 0; k < impl.reaction_symbols.size(); ++k)
    numbers[impl.reaction_symbols[k]] = GiNaC::numeric(reactions[static_cast<Eigen::Index>(k)]);
  Evaluator value(numbers);
  VecX residuals(static_cast<Eigen::Index>(impl.newton_euler.size()));
  for (std::size_t k = 0; k < impl.newton_euler.size(); ++k) {
    residuals[static_cast<Eigen::Index>(k)] =
        value(impl.newton_euler[k].loads) - value(impl.newton_euler[k].kinetic);
  }
  return residuals;
}

void Equations::evaluate(const VecX& q, const VecX& v, const VecX& vdot, const VecX& u, MatX& M,
                         VecX& bias) const {
  const Impl& impl = *impl_;
  check_sizes(impl, q, v, vdot, u, "evaluate");
  const GiNaC::exmap numbers = numbers_for(impl, q, v, vdot, u);
  Evaluator value(numbers);
  const auto n = static_cast<Eigen::Index>(impl.free.size());
  M.resize(n, n);
  bias.resize(n);
  for (Eigen::Index r = 0; r < n; ++r) {
    for (Eigen::Index c = 0; c < n; ++c)
      M(r, c) = value(impl.M(static_cast<unsigned>(r), static_cast<unsigned>(c)));
    const auto k = static_cast<std::size_t>(r);
    bias[r] = value(impl.rest[k]) + value(impl.g[k]) - value(impl.Q[k]);
  }
}

std::string Equations::generate_code(Format language, const std::string& module) const {
  if (language != Format::cpp && language != Format::python) {
    throw InvalidArgument("Equations::generate_code: the language is cpp or python");
  }
  const std::string name = detail::identifier(module);
  const Impl& impl = *impl_;
  const GiNaC::exmap code = code_symbols(impl);
  const std::size_t n = impl.free.size();
  const bool cpp = language == Format::cpp;
  using detail::CodeEmitter;
  const CodeEmitter::Language lang =
      cpp ? CodeEmitter::Language::cpp : CodeEmitter::Language::python;
  const std::string indent = cpp ? "  " : "    ";

  // M's entries and b's, each function's shared subexpressions computed once.
  CodeEmitter mass(lang, indent, code), bias(lang, indent, code);
  std::vector<std::string> M_entries, b_entries;
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < n; ++c)
      M_entries.push_back(mass(impl.M(static_cast<unsigned>(r), static_cast<unsigned>(c))));
  for (std::size_t r = 0; r < n; ++r)
    b_entries.push_back(bias(impl.rest[r] + impl.g[r] - impl.Q[r]));
  // The constraints: φ, G on the free speeds (row-major), and k with the prescribed speeds'
  // accelerations in it, so that G vdot_free + k = 0.
  CodeEmitter rows(lang, indent, code);
  std::vector<std::string> phi_entries, G_entries, k_entries, row_names;
  std::vector<bool> is_free(static_cast<std::size_t>(impl.nv), false);
  for (const int vi : impl.free) is_free[static_cast<std::size_t>(vi)] = true;
  for (const auto& c : impl.constraints) {
    row_names.push_back(c.name);
    phi_entries.push_back(rows(c.position));
    ex k = c.bias;
    for (std::size_t vi = 0; vi < is_free.size(); ++vi)
      if (!is_free[vi]) k += c.G[vi] * impl.vdot[vi];
    for (const int vi : impl.free) G_entries.push_back(rows(c.G[static_cast<std::size_t>(vi)]));
    k_entries.push_back(rows(k));
  }
  const std::size_t m = impl.constraints.size();

  std::string out;
  if (cpp) {
    out += fmt::format(
        "// Generated by `momenta equations --cpp`: M(q) vdot_free + b(q, v, vdot, u) = 0 "
        "(docs/equations.md).\n// q, v, vdot: the model's coordinates, speeds and accelerations "
        "(prescribed ones included); u: the inputs.\n#pragma once\n#include <cmath>\n\nnamespace "
        "{} {{\n\ninline constexpr int nq = {}, nv = {}, nfree = {}, nu = {};\n",
        name, impl.nq, impl.nv, n, impl.inputs.size());
    out += fmt::format("// Speeds with an equation (indices into v): {}\n",
                       fmt::join(impl.free, ", "));
    for (const Parameter& p : impl.parameters)
      out += fmt::format("inline constexpr double {} = {:.17g};\n", p.name, p.value);
    out +=
        "\n// M: nfree × nfree, row-major.\ninline void mass_matrix(const double* q, double* M) {\n"
        "  (void)q;\n" +
        mass.lines();
    for (std::size_t k = 0; k < M_entries.size(); ++k)
      out += fmt::format("  M[{}] = {};\n", k, M_entries[k]);
    out +=
        "}\n\n// b = C(q, v) v + g(q) − Q(q, v, u), with the prescribed accelerations' terms.\n"
        "inline void bias(const double* q, const double* v, const double* vdot, const double* "
        "u, double* b) {\n  (void)q; (void)v; (void)vdot; (void)u;\n" +
        bias.lines();
    for (std::size_t k = 0; k < b_entries.size(); ++k)
      out += fmt::format("  b[{}] = {};\n", k, b_entries[k]);
    out += "}\n";
    if (m > 0) {
      out += fmt::format(
          "\n// The constraints' {} rows ({}): M vdot_free + b = G^T lambda, G vdot_free + k = 0;\n"
          "// phi (0 on velocity-only rows), G: rows x nfree, row-major; k with the prescribed\n"
          "// accelerations' terms.\ninline constexpr int nrows = {};\n"
          "inline void constraints(const double* q, const double* v, const double* vdot, const "
          "double* u, double* phi, double* G, double* k) {{\n  (void)q; (void)v; (void)vdot; "
          "(void)u;\n",
          m, fmt::join(row_names, ", "), m);
      out += rows.lines();
      for (std::size_t k = 0; k < m; ++k)
        out += fmt::format("  phi[{}] = {};\n  k[{}] = {};\n", k, phi_entries[k], k, k_entries[k]);
      for (std::size_t k = 0; k < G_entries.size(); ++k)
        out += fmt::format("  G[{}] = {};\n", k, G_entries[k]);
      out += "}\n";
    }
    out += fmt::format("\n}}  // namespace {}\n", name);
    return out;
  }
  out += fmt::format(
      "\"\"\"{}: generated by `momenta equations --python`. M(q) vdot_free + b(q, v, vdot, u) = 0 "
      "(docs/equations.md).\n\nq, v, vdot: the model's coordinates, speeds and accelerations "
      "(prescribed ones included); u: the inputs.\n\"\"\"\nfrom math import cos, sin, sqrt\n\n"
      "nq, nv, nfree, nu = {}, {}, {}, {}\nfree_speeds = [{}]\n",
      name, impl.nq, impl.nv, n, impl.inputs.size(), fmt::join(impl.free, ", "));
  for (const Parameter& p : impl.parameters) out += fmt::format("{} = {:.17g}\n", p.name, p.value);
  out += "\n\ndef mass_matrix(q):\n    \"\"\"M as a list of rows.\"\"\"\n" + mass.lines() +
         "    return [\n";
  for (std::size_t r = 0; r < n; ++r) {
    out += "        [";
    for (std::size_t c = 0; c < n; ++c) out += (c ? ", " : "") + M_entries[r * n + c];
    out += "],\n";
  }
  out +=
      "    ]\n\n\ndef bias(q, v, vdot, u):\n    \"\"\"b = C v + g - Q, one per free "
      "speed.\"\"\"\n" +
      bias.lines() + "    return [" + fmt::format("{}", fmt::join(b_entries, ", ")) + "]\n";
  if (m > 0) {
    out += fmt::format(
        "\n\ndef constraints(q, v, vdot, u):\n    \"\"\"The constraints' rows ({}): phi (0 on "
        "velocity-only rows),\n    G (rows of the free speeds) and k, with M vdot_free + b = G^T "
        "lambda and\n    G vdot_free + k = 0.\"\"\"\n",
        fmt::join(row_names, ", "));
    out += rows.lines() + "    phi = [" + fmt::format("{}", fmt::join(phi_entries, ", ")) +
           "]\n    G = [\n";
    for (std::size_t r = 0; r < m; ++r) {
      out += "        [";
      for (std::size_t c = 0; c < n; ++c) out += (c ? ", " : "") + G_entries[r * n + c];
      out += "],\n";
    }
    out += "    ]\n    k = [" + fmt::format("{}", fmt::join(k_entries, ", ")) +
           "]\n    return phi, G, k\n";
  }
  return out;
}

}  // namespace momenta::symbolic
