#include <cmath>

#include <fmt/format.h>

#include "equations_impl.hpp"
#include "expression_algebra.hpp"
#include "momenta/common/error.hpp"
#include "momenta/symbolic/linear_equations.hpp"

namespace momenta::symbolic {

using GiNaC::ex;
using GiNaC::matrix;
using GiNaC::symbol;

// Above this many free coordinates A = [0 I; −M⁻¹K −M⁻¹D] is not formed: M⁻¹ in symbols grows
// like n! terms.
constexpr int kMaxStateSpaceCoordinates = 4;

struct LinearEquations::Impl {
  std::vector<std::string> coordinates, inputs;
  matrix M, D, K, B0, B1, B2, A, B;
  bool input_rates = false, state_space = false;
  symbol s{"s"};
  GiNaC::exmap parameter_values;  // every parameter symbol at its model value
};

namespace {

// A number of the operating point: exact where it is an integer (so sin 0 = 0 exactly).
ex operating_number(double x) {
  if (std::isfinite(x) && x == std::round(x) && std::abs(x) < 1e15)
    return GiNaC::numeric(static_cast<long>(x));
  return detail::exact_number(x);
}

ex simplified(const ex& e) { return GiNaC::normal(GiNaC::expand(e)); }

// A rational expression as "numerator/(denominator)" (c_road/m_car rather than c_road*m_car^(-1)),
// each collected; a polynomial as itself.
std::string ratio_text(const ex& e, Format format, const ex& variable = ex(0)) {
  const ex nd = GiNaC::numer_denom(GiNaC::normal(e));
  const auto tidy = [&](const ex& x) {
    return GiNaC::is_a<symbol>(variable) ? GiNaC::collect(GiNaC::expand(x), variable)
                                         : GiNaC::expand(x);
  };
  const std::string num = detail::print(tidy(nd.op(0)), format);
  if (nd.op(1).is_equal(1)) return num;
  const std::string den = detail::print(tidy(nd.op(1)), format);
  if (format == Format::latex) return fmt::format("\\frac{{{}}}{{{}}}", num, den);
  // Parentheses only where the reading needs them: a sum on top, anything but a name below.
  const auto has_any_after_first = [](const std::string& text, const char* operators) {
    return text.find_first_of(operators, 1) != std::string::npos;
  };
  const auto wrapped = [](const std::string& text, bool parenthesize) {
    return parenthesize ? "(" + text + ")" : text;
  };
  return wrapped(num, has_any_after_first(num, "+-")) + "/" +
         wrapped(den, has_any_after_first(den, "+-*/^"));
}

const matrix& pick(const LinearEquations::Impl& impl, LinearMatrix which) {
  switch (which) {
    case LinearMatrix::M:
      return impl.M;
    case LinearMatrix::D:
      return impl.D;
    case LinearMatrix::K:
      return impl.K;
    case LinearMatrix::B0:
      return impl.B0;
    case LinearMatrix::B1:
      return impl.B1;
    case LinearMatrix::B2:
      return impl.B2;
    case LinearMatrix::A:
      return impl.A;
    case LinearMatrix::B:
      return impl.B;
  }
  return impl.M;
}

// The free coordinates' symbols: q, v and v̇ of each free speed (joints with nq == nv).
struct FreeSymbols {
  std::vector<ex> q, v, a;
};

FreeSymbols free_symbols(const Equations::Impl& e, const model::Model& model) {
  FreeSymbols f;
  for (const int vi : e.free) {
    const model::Joint& j = model.joint(model.joint_of_v(vi));
    if (j.nq() != j.nv()) {
      throw InvalidArgument(fmt::format(
          "the {} joint {} has a quaternion: its linearization in symbols is not written (a "
          "rotation tangent per speed); `momenta linearize` gives the numbers",
          model::joint_type_name(j.type), j.name));
    }
    const int qi = j.q_index + (vi - j.v_index);
    f.q.push_back(e.q[static_cast<std::size_t>(qi)]);
    f.v.push_back(e.v[static_cast<std::size_t>(vi)]);
    f.a.push_back(e.vdot[static_cast<std::size_t>(vi)]);
  }
  return f;
}

// The inputs: each load signal, then each prescribed coordinate's signal (its value, rate and
// acceleration symbols), with their values at the operating point.
struct Inputs {
  std::vector<std::string> names;
  std::vector<ex> value, rate, acceleration;  // rate and acceleration 0 for a load's scale
};

Inputs inputs_of(const Equations::Impl& e, const model::Model& model,
                 std::span<const model::SignalSample> signals, GiNaC::exmap& point) {
  Inputs in;
  for (std::size_t k = 0; k < e.inputs.size(); ++k) {
    in.names.push_back(e.input_names[k]);
    in.value.push_back(e.inputs[k]);
    in.rate.push_back(0);
    in.acceleration.push_back(0);
    const int signal = model.signal_index(e.input_names[k]);
    point[e.inputs[k]] = operating_number(signals[static_cast<std::size_t>(signal)].value);
  }
  for (const model::Joint& j : model.joints()) {
    if (j.is_prescribed() && j.nq() != j.nv()) {
      throw InvalidArgument(fmt::format(
          "the prescribed {} joint {} enters its equations by its quaternion and ω, not by its "
          "signals: its linearization in symbols is not written; `momenta linearize` gives the "
          "numbers",
          model::joint_type_name(j.type), j.name));
    }
    for (int k = 0; k < static_cast<int>(j.prescribed_signal_indices.size()); ++k) {
      if (model.is_driven(j.prescribed_signal_indices[static_cast<std::size_t>(k)])) {
        throw InvalidArgument(fmt::format(
            "joint {}'s acceleration is commanded by a controller: its linearization in symbols "
            "is not written; `momenta linearize` gives the numbers (the coordinate and its rate "
            "states, the acceleration an input)",
            j.name));
      }
      const model::SignalSample& sample = signals[static_cast<std::size_t>(
          j.prescribed_signal_indices[static_cast<std::size_t>(k)])];
      const ex& value = e.q[static_cast<std::size_t>(j.q_index + k)];
      const ex& rate = e.v[static_cast<std::size_t>(j.v_index + k)];
      const ex& acceleration = e.vdot[static_cast<std::size_t>(j.v_index + k)];
      in.names.push_back(j.prescribed_signals[static_cast<std::size_t>(k)]);
      in.value.push_back(value);
      in.rate.push_back(rate);
      in.acceleration.push_back(acceleration);
      point[value] = operating_number(sample.value);
      point[rate] = operating_number(sample.rate);
      point[acceleration] = operating_number(sample.acceleration);
    }
  }
  return in;
}

// ∂e/∂x for an x that is a symbol (0 for a constant: an input's rate that does not exist).
ex derivative(const ex& e, const ex& x) {
  return GiNaC::is_a<symbol>(x) ? e.diff(GiNaC::ex_to<symbol>(x)) : ex(0);
}

}  // namespace

LinearEquations linearize_equations(const Equations& equations, const model::Model& model, double t,
                                    const VecX& q0, const VecX& v0) {
  const Equations::Impl& e = *equations.impl_;
  if (q0.size() != e.nq || v0.size() != e.nv) {
    throw InvalidArgument(
        fmt::format("linearize_equations: q0, v0 have {}, {} values; expected {}, {}", q0.size(),
                    v0.size(), e.nq, e.nv));
  }
  if (!e.constraints.empty()) {
    throw InvalidArgument(fmt::format(
        "linearize_equations: constraint '{}': a constrained model linearizes in independent "
        "coordinates chosen at the operating point; `momenta linearize` does that numerically "
        "(docs/constraints.md)",
        model::constraint_name(model.constraints().front())));
  }
  std::vector<model::SignalSample> signals;
  for (const model::Signal& signal : model.signals()) signals.push_back(signal.sample(t));
  const FreeSymbols x = free_symbols(e, model);
  GiNaC::exmap point;
  for (std::size_t k = 0; k < e.free.size(); ++k) {
    const int vi = e.free[k];
    const model::Joint& j = model.joint(model.joint_of_v(vi));
    point[x.q[k]] = operating_number(q0[j.q_index + (vi - j.v_index)]);
    point[x.v[k]] = operating_number(v0[vi]);
  }
  const Inputs u = inputs_of(e, model, signals, point);

  auto impl = std::make_shared<LinearEquations::Impl>();
  const auto n = static_cast<unsigned>(e.free.size());
  const auto m = static_cast<unsigned>(u.names.size());
  for (const int vi : e.free) impl->coordinates.push_back(e.q_names[static_cast<std::size_t>(vi)]);
  impl->inputs = u.names;
  for (std::size_t k = 0; k < e.parameters.size(); ++k)
    impl->parameter_values[e.parameter_symbols[k]] = detail::exact_number(e.parameters[k].value);

  // b = C v + g − Q per free row; M at the point; v̇0 = −M⁻¹ b there (zero at an equilibrium).
  std::vector<ex> b(n);
  for (unsigned r = 0; r < n; ++r) b[r] = e.rest[r] + e.g[r] - e.Q[r];
  // Differentiating and simplifying expressions that print as huge trees takes minutes (a
  // 10-link chain: more than two); refused first, pointing to the numeric linearization.
  for (unsigned r = 0; r < n; ++r) {
    constexpr std::string_view kNumeric =
        "the numeric linearization (‹linearize›) takes the same model in milliseconds";
    detail::check_printable(b[r], kNumeric);
    for (unsigned c = 0; c < n; ++c) detail::check_printable(e.M(r, c), kNumeric);
  }
  impl->M = matrix(n, n);
  matrix b0(n, 1);
  for (unsigned r = 0; r < n; ++r) {
    for (unsigned c = 0; c < n; ++c) impl->M(r, c) = simplified(e.M(r, c).subs(point));
    b0(r, 0) = simplified(b[r].subs(point));
  }
  matrix a0(n, 1);
  if (!b0.is_zero_matrix()) {
    a0 = impl->M.inverse().mul(b0).mul_scalar(-1);
    for (unsigned r = 0; r < n; ++r) a0(r, 0) = simplified(a0(r, 0));
  }

  // The residual r = M v̇0 + b, differentiated at the point.
  impl->D = matrix(n, n);
  impl->K = matrix(n, n);
  impl->B0 = matrix(n, m);
  impl->B1 = matrix(n, m);
  impl->B2 = matrix(n, m);
  for (unsigned r = 0; r < n; ++r) {
    ex residual = b[r];
    for (unsigned c = 0; c < n; ++c) residual += e.M(r, c) * a0(c, 0);
    for (unsigned c = 0; c < n; ++c) {
      impl->K(r, c) = simplified(derivative(residual, x.q[c]).subs(point));
      impl->D(r, c) = simplified(derivative(b[r], x.v[c]).subs(point));
    }
    for (unsigned c = 0; c < m; ++c) {
      impl->B0(r, c) = simplified(-derivative(residual, u.value[c]).subs(point));
      impl->B1(r, c) = simplified(-derivative(b[r], u.rate[c]).subs(point));
      impl->B2(r, c) = simplified(-derivative(b[r], u.acceleration[c]).subs(point));
    }
  }
  impl->input_rates = !impl->B1.is_zero_matrix() || !impl->B2.is_zero_matrix();

  // ẋ = A x + B u where the inputs' rates do not enter and M⁻¹ stays small.
  impl->state_space = !impl->input_rates && n > 0 && n <= kMaxStateSpaceCoordinates;
  if (impl->state_space) {
    const matrix M_inv = impl->M.inverse();
    const matrix MK = M_inv.mul(impl->K), MD = M_inv.mul(impl->D), MB = M_inv.mul(impl->B0);
    impl->A = matrix(2 * n, 2 * n);
    impl->B = matrix(2 * n, m);
    for (unsigned r = 0; r < n; ++r) {
      impl->A(r, n + r) = 1;
      for (unsigned c = 0; c < n; ++c) {
        impl->A(n + r, c) = simplified(-MK(r, c));
        impl->A(n + r, n + c) = simplified(-MD(r, c));
      }
      for (unsigned c = 0; c < m; ++c) impl->B(n + r, c) = simplified(MB(r, c));
    }
  }
  return LinearEquations(std::move(impl));
}

LinearEquations::LinearEquations(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
LinearEquations::~LinearEquations() = default;
LinearEquations::LinearEquations(const LinearEquations&) = default;
LinearEquations& LinearEquations::operator=(const LinearEquations&) = default;

const std::vector<std::string>& LinearEquations::coordinate_names() const {
  return impl_->coordinates;
}
const std::vector<std::string>& LinearEquations::input_names() const { return impl_->inputs; }
bool LinearEquations::has_input_rates() const { return impl_->input_rates; }
bool LinearEquations::has_state_space() const { return impl_->state_space; }

int LinearEquations::rows(LinearMatrix which) const {
  return static_cast<int>(pick(*impl_, which).rows());
}
int LinearEquations::columns(LinearMatrix which) const {
  return static_cast<int>(pick(*impl_, which).cols());
}

std::string LinearEquations::entry(LinearMatrix which, int r, int c, Format format) const {
  if ((which == LinearMatrix::A || which == LinearMatrix::B) && !impl_->state_space) {
    throw InvalidArgument(
        "LinearEquations::entry: no A, B (an input's rate enters, or more than four free "
        "coordinates)");
  }
  const matrix& X = pick(*impl_, which);
  if (r < 0 || c < 0 || r >= static_cast<int>(X.rows()) || c >= static_cast<int>(X.cols())) {
    throw InvalidArgument(
        fmt::format("LinearEquations::entry: ({}, {}) outside {} × {}", r, c, X.rows(), X.cols()));
  }
  return ratio_text(X(static_cast<unsigned>(r), static_cast<unsigned>(c)), format);
}

namespace {

// s^d e_kᵀ (s² M + s D + K)⁻¹ (B0 + s B1 + s² B2) e_i, as a normalized ratio.
ex transfer(const LinearEquations::Impl& impl, int input, int coordinate, bool rate) {
  const unsigned n = impl.M.rows();
  if (input < 0 || input >= static_cast<int>(impl.inputs.size()) || coordinate < 0 ||
      coordinate >= static_cast<int>(n)) {
    throw InvalidArgument(
        fmt::format("LinearEquations::transfer_function: input {} of {}, coordinate {} of {}",
                    input, impl.inputs.size(), coordinate, n));
  }
  const ex& s = impl.s;
  matrix Z(n, n), rhs(n, 1), unknowns(n, 1);
  const auto i = static_cast<unsigned>(input);
  for (unsigned r = 0; r < n; ++r) {
    for (unsigned c = 0; c < n; ++c)
      Z(r, c) = s * s * impl.M(r, c) + s * impl.D(r, c) + impl.K(r, c);
    rhs(r, 0) = impl.B0(r, i) + s * impl.B1(r, i) + s * s * impl.B2(r, i);
    unknowns(r, 0) = symbol(fmt::format("x{}", r));
  }
  const matrix X = Z.solve(unknowns, rhs);
  return GiNaC::normal((rate ? s : ex(1)) * X(static_cast<unsigned>(coordinate), 0));
}

}  // namespace

std::string LinearEquations::transfer_function(int input, int coordinate, bool rate,
                                               Format format) const {
  return ratio_text(transfer(*impl_, input, coordinate, rate), format, impl_->s);
}

std::complex<double> LinearEquations::transfer_function_at(int input, int coordinate, bool rate,
                                                           std::complex<double> s) const {
  GiNaC::exmap values = impl_->parameter_values;
  values[impl_->s] = GiNaC::numeric(s.real()) + GiNaC::I * GiNaC::numeric(s.imag());
  const ex G = GiNaC::evalf(transfer(*impl_, input, coordinate, rate).subs(values));
  const ex re = GiNaC::evalf(GiNaC::real_part(G)), im = GiNaC::evalf(GiNaC::imag_part(G));
  if (!GiNaC::is_a<GiNaC::numeric>(re) || !GiNaC::is_a<GiNaC::numeric>(im)) {
    throw InvalidArgument(
        fmt::format("LinearEquations::transfer_function_at: '{}' has symbols left",
                    detail::print(G, Format::text)));
  }
  return {GiNaC::ex_to<GiNaC::numeric>(re).to_double(),
          GiNaC::ex_to<GiNaC::numeric>(im).to_double()};
}

}  // namespace momenta::symbolic
