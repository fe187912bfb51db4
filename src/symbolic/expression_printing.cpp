// Printing one expression as text, LaTeX, C++ or Python (equations_impl.hpp): numbers as short
// decimals in text and LaTeX, and sums and products in an order of their own rather than
// GiNaC's. GiNaC orders the operands of a sum or product by a hash seeded with the address of
// its type's name, which moves from run to run (address-space randomization): printed as GiNaC
// keeps them, the same equations came out in a different order each time. Here the terms of a
// sum go accelerations first (in the model's coordinate order), then speeds, then the rest — the
// order a textbook writes M v̇ + C v + g = Q in — and the factors of a product numbers, then
// parameters, inputs, functions, coordinates, speeds and accelerations (m L² θ̈, m g L sin θ);
// ties go by the printed text, so the same equations print as the same bytes every time.

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

#include <fmt/format.h>

#include "equations_impl.hpp"
#include "momenta/common/error.hpp"

namespace momenta::symbolic {
namespace detail {

using GiNaC::print_dflt;
using GiNaC::print_latex;

// Text and LaTeX with numbers as decimals and sums and products in a fixed order (roles set by
// the caller; without them every symbol counts as a parameter).
class decimal_text : public print_dflt {
  GINAC_DECLARE_PRINT_CONTEXT(decimal_text, print_dflt)
 public:
  explicit decimal_text(std::ostream& os, unsigned flags = 0) : print_dflt(os, flags) {}
  const PrintRoles* roles = nullptr;
};
GINAC_IMPLEMENT_PRINT_CONTEXT(decimal_text, print_dflt)

class decimal_latex : public print_latex {
  GINAC_DECLARE_PRINT_CONTEXT(decimal_latex, print_latex)
 public:
  explicit decimal_latex(std::ostream& os, unsigned flags = 0) : print_latex(os, flags) {}
  const PrintRoles* roles = nullptr;
};
GINAC_IMPLEMENT_PRINT_CONTEXT(decimal_latex, print_latex)

decimal_text::decimal_text() : print_dflt(std::cout) {}
decimal_latex::decimal_latex() : print_latex(std::cout) {}

}  // namespace detail

namespace {

using detail::decimal_latex;
using detail::decimal_text;
using detail::PrintRoles;
using detail::SymbolRole;
using GiNaC::ex;

// GiNaC's precedences: a sum 40, a product 50, a power 60 (a child printed at a level at or
// above its own precedence is parenthesized).
constexpr unsigned kSumPrecedence = 40, kProductPrecedence = 50;

// A rational a person reads better as a fraction than as a decimal: one whose decimal does not
// end (its denominator has a factor other than 2 and 5) and whose denominator is small — the
// 1/12 of a rod's m L²/12, the 3/80 of a cone's — not 0.08333333333333333.
bool reads_as_fraction(const GiNaC::numeric& n) {
  if (!n.is_rational() || n.is_integer()) return false;
  GiNaC::numeric q = n.denom();
  if (q > 1000) return false;
  while (GiNaC::irem(q, 2).is_zero()) q /= 2;
  while (GiNaC::irem(q, 5).is_zero()) q /= 5;
  return q != 1;
}

void print_decimal(const GiNaC::numeric& n, const GiNaC::print_context& c, unsigned level) {
  if (reads_as_fraction(n)) {
    const bool latex = dynamic_cast<const GiNaC::print_latex*>(&c) != nullptr;
    const bool parenthesize = level > 0 && (!latex || n.is_negative());
    if (parenthesize) c.s << "(";
    if (latex) {
      c.s << (n.is_negative() ? "-" : "") << "\\frac{" << GiNaC::abs(n.numer()) << "}{" << n.denom()
          << "}";
    } else {
      c.s << n.numer() << "/" << n.denom();
    }
    if (parenthesize) c.s << ")";
    return;
  }
  if (n.is_integer()) {
    // A negative integer inside a product or power keeps its parentheses (x^(-1), not x^-1).
    if (n.is_negative() && level > 0) {
      c.s << "(" << n << ")";
    } else {
      c.s << n;
    }
    return;
  }
  // An exact rational (from a short decimal) reads back exactly; a float shows 12 digits (the
  // generated code keeps all 17).
  const double x = n.to_double();
  const bool parenthesize = x < 0 && level > 0;
  if (parenthesize) c.s << "(";
  c.s << (n.is_rational() ? fmt::format("{}", x) : fmt::format("{:.12g}", x));
  if (parenthesize) c.s << ")";
}

// What a factor is, for ordering a product: lower first.
int factor_class(const ex& f, const PrintRoles* roles, int& index) {
  index = 0;
  const ex base = GiNaC::is_a<GiNaC::power>(f) ? f.op(0) : f;
  if (GiNaC::is_a<GiNaC::numeric>(base)) return 0;
  if (GiNaC::is_a<GiNaC::symbol>(base)) {
    if (roles == nullptr) return 1;
    const auto it = roles->by_name.find(GiNaC::ex_to<GiNaC::symbol>(base).get_name());
    if (it == roles->by_name.end()) return 1;
    index = it->second.index;
    switch (it->second.role) {
      case SymbolRole::parameter:
        return 1;
      case SymbolRole::input:
        return 2;
      case SymbolRole::coordinate:
        return 4;
      case SymbolRole::speed:
        return 5;
      case SymbolRole::acceleration:
        return 6;
    }
  }
  if (GiNaC::is_a<GiNaC::function>(base)) return 3;
  return 7;  // a sum (parenthesized) or anything else
}

// What a term of a sum holds, for ordering the sum: the leading coordinate's acceleration, then
// the other accelerations (by coordinate), then speeds, then the rest.
std::pair<int, int> term_class(const ex& term, const PrintRoles* roles) {
  if (roles == nullptr) return {2, 0};
  if (GiNaC::is_a<GiNaC::symbol>(term)) {
    const auto found = roles->by_name.find(GiNaC::ex_to<GiNaC::symbol>(term).get_name());
    if (found == roles->by_name.end()) return {2, 0};
    const bool own = found->second.role == SymbolRole::acceleration &&
                     found->second.index == roles->leading_acceleration;
    const int rank = own                                              ? -1
                     : found->second.role == SymbolRole::acceleration ? 0
                     : found->second.role == SymbolRole::speed        ? 1
                                                                      : 2;
    return {rank, rank == 2 ? 0 : found->second.index};
  }
  if (term.nops() == 0) return {2, 0};
  // The smallest over its parts, each part worked out once (printing a large tree meets the
  // same parts many times).
  if (const auto known = roles->term_classes.find(term); known != roles->term_classes.end()) {
    return known->second;
  }
  std::pair<int, int> best{2, 0};
  for (std::size_t k = 0; k < term.nops(); ++k)
    best = std::min(best, term_class(term.op(k), roles));
  roles->term_classes.emplace(term, best);
  return best;
}

template <class Context>
std::string text_of(const ex& e, const Context& c, unsigned level) {
  std::ostringstream os;
  Context sub(os, c.options);
  sub.roles = c.roles;
  e.print(sub, level);
  return os.str();
}

template <class Context>
void print_sum(const GiNaC::add& sum, const GiNaC::print_context& context, unsigned level) {
  const auto& c = static_cast<const Context&>(context);
  struct Term {
    std::pair<int, int> order;
    std::string text;
  };
  std::vector<Term> terms;
  for (std::size_t i = 0; i < sum.nops(); ++i) {
    const ex term = sum.op(i);
    // A number prints bare (−1, not (−1)): the sum places its sign.
    const unsigned term_level = GiNaC::is_a<GiNaC::numeric>(term) ? 0 : kSumPrecedence;
    terms.push_back({term_class(term, c.roles), text_of(term, c, term_level)});
  }
  const auto unsigned_text = [](const std::string& t) {
    return t.starts_with("-") ? std::string_view(t).substr(1) : std::string_view(t);
  };
  std::sort(terms.begin(), terms.end(), [&](const Term& a, const Term& b) {
    return std::make_tuple(a.order, unsigned_text(a.text), std::string_view(a.text)) <
           std::make_tuple(b.order, unsigned_text(b.text), std::string_view(b.text));
  });
  const bool parenthesize = level >= kSumPrecedence;
  if (parenthesize) c.s << (std::is_same_v<Context, decimal_latex> ? "\\left(" : "(");
  for (std::size_t i = 0; i < terms.size(); ++i) {
    const std::string& t = terms[i].text;
    if (i == 0) {
      c.s << t;
    } else {
      c.s << (t.starts_with("-") ? " - " : " + ") << unsigned_text(t);
    }
  }
  if (parenthesize) c.s << (std::is_same_v<Context, decimal_latex> ? "\\right)" : ")");
}

// Whether `e` holds the leading coordinate's (the equation's own) coordinate or speed.
bool holds_own_coordinate(const ex& e, const PrintRoles* roles) {
  if (roles == nullptr || roles->leading_acceleration < 0) return false;
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    const auto found = roles->by_name.find(GiNaC::ex_to<GiNaC::symbol>(e).get_name());
    return found != roles->by_name.end() && found->second.index == roles->leading_acceleration &&
           (found->second.role == SymbolRole::coordinate ||
            found->second.role == SymbolRole::speed);
  }
  for (std::size_t k = 0; k < e.nops(); ++k) {
    if (holds_own_coordinate(e.op(k), roles)) return true;
  }
  return false;
}

// A sum that is a factor of a product, as text: where a term holds the equation's own coordinate
// or speed, that term first (its sign the product's): k_s (x − y) and b (ẋ − ẏ) in equation x,
// k_s (y − x) in equation y, as the notes write a spring and a damper. Nothing otherwise.
template <class Context>
std::optional<std::string> own_coordinate_first(const ex& sum, const Context& c) {
  if (sum.nops() > 6) return std::nullopt;
  ex own = 0, rest = 0;
  for (std::size_t k = 0; k < sum.nops(); ++k) {
    (holds_own_coordinate(sum.op(k), c.roles) ? own : rest) += sum.op(k);
  }
  if (own.is_zero() || rest.is_zero() || GiNaC::is_a<GiNaC::add>(own)) return std::nullopt;
  const std::string first = text_of(own, c, kSumPrecedence);
  const std::string others = text_of(rest, c, 0);
  return first + (others.starts_with("-") ? " - " + others.substr(1) : " + " + others);
}

template <class Context>
void print_product(const GiNaC::mul& product, const GiNaC::print_context& context, unsigned level) {
  const auto& c = static_cast<const Context&>(context);
  constexpr bool latex = std::is_same_v<Context, decimal_latex>;
  GiNaC::numeric coefficient = 1;
  struct Factor {
    int kind = 0, index = 0;
    std::string text;
  };
  std::vector<Factor> numerator, denominator;
  // GiNaC takes a sum's common fraction out of it (m L²/12 + m d² times θ̈ is kept as
  // 1/12 θ̈ (m L² + 12 m d²)): the fraction goes back into the sum, as the textbook writes it.
  int sums = 0;
  GiNaC::numeric common = 1;
  for (std::size_t i = 0; i < product.nops(); ++i) {
    if (GiNaC::is_a<GiNaC::add>(product.op(i))) ++sums;
    if (GiNaC::is_a<GiNaC::numeric>(product.op(i))) {
      common *= GiNaC::ex_to<GiNaC::numeric>(product.op(i));
    }
  }
  const bool into_sum = sums == 1 && reads_as_fraction(common);
  for (std::size_t i = 0; i < product.nops(); ++i) {
    ex f = product.op(i);
    if (GiNaC::is_a<GiNaC::numeric>(f)) {
      if (!into_sum) coefficient *= GiNaC::ex_to<GiNaC::numeric>(f);
      continue;
    }
    if (into_sum && GiNaC::is_a<GiNaC::add>(f)) f = GiNaC::expand(common * f);
    const bool divides = GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::numeric>(f.op(1)) &&
                         GiNaC::ex_to<GiNaC::numeric>(f.op(1)).is_negative();
    ex shown = divides ? GiNaC::pow(f.op(0), -f.op(1)) : f;
    Factor factor;
    if (GiNaC::is_a<GiNaC::add>(shown)) {
      // A sum leads with a positive term, the product taking the minus (GiNaC keeps −c·(a − b)
      // or c·(b − a) as its hash order fell); printed bare, parenthesized here.
      std::string sum = text_of(shown, c, 0);
      if (const auto own = own_coordinate_first(shown, c)) {
        sum = *own;
        if (sum.starts_with("-")) {
          shown = -shown;
          coefficient = -coefficient;
          sum = *own_coordinate_first(shown, c);
        }
      } else if (sum.starts_with("-")) {
        shown = -shown;
        coefficient = -coefficient;
        sum = text_of(shown, c, 0);
      }
      factor.text = latex ? "\\left(" + sum + "\\right)" : "(" + sum + ")";
    } else {
      factor.text = text_of(shown, c, kProductPrecedence);
    }
    factor.kind = factor_class(shown, c.roles, factor.index);
    (divides ? denominator : numerator).push_back(std::move(factor));
  }
  const auto by_order = [](const Factor& a, const Factor& b) {
    return std::tie(a.kind, a.index, a.text) < std::tie(b.kind, b.index, b.text);
  };
  std::sort(numerator.begin(), numerator.end(), by_order);
  std::sort(denominator.begin(), denominator.end(), by_order);
  const char* times = latex ? " " : "*";
  // In LaTeX a product juxtaposes its factors; a multi-letter name (upright, \mathrm{tip\_qw})
  // is set apart from its neighbours by a thin space, or tip_qw tip_qy would read as one word.
  const auto word = [](const std::string& text) { return text.starts_with("\\mathrm{"); };
  const auto join = [&](const std::vector<Factor>& factors) {
    std::string s;
    for (std::size_t i = 0; i < factors.size(); ++i) {
      if (i > 0)
        s += latex && (word(factors[i - 1].text) || word(factors[i].text)) ? " \\, " : times;
      s += factors[i].text;
    }
    return s;
  };

  const bool negative = coefficient.is_negative();
  GiNaC::numeric magnitude = GiNaC::abs(coefficient);
  // A fraction's denominator below the line: m*length^2/12, \frac{m length^2}{12}.
  if (reads_as_fraction(magnitude) && !numerator.empty()) {
    denominator.push_back({0, 0, text_of(ex(magnitude.denom()), c, kProductPrecedence)});
    magnitude = magnitude.numer();
  }
  std::string top = join(numerator);
  if (magnitude != 1 || top.empty()) {
    const std::string number = text_of(ex(magnitude), c, kProductPrecedence);
    top = top.empty() ? number : number + times + top;
  }
  std::string body = top;
  if (!denominator.empty()) {
    const std::string bottom = join(denominator);
    if (latex) {
      body = "\\frac{" + top + "}{" + bottom + "}";
    } else {
      body = top + "/" + (denominator.size() > 1 ? "(" + bottom + ")" : bottom);
    }
  }
  const bool parenthesize = level >= kProductPrecedence;
  if (parenthesize) c.s << (latex ? "\\left(" : "(");
  c.s << (negative ? "-" : "") << body;
  if (parenthesize) c.s << (latex ? "\\right)" : ")");
}

// A symbol: as its Display where the roles give one, else its name (its TeX name in LaTeX).
template <class Context>
void print_symbol(const GiNaC::symbol& s, const Context& c, unsigned) {
  constexpr bool latex = std::is_same_v<Context, decimal_latex>;
  if (c.roles != nullptr) {
    if (const auto it = c.roles->display.find(s.get_name()); it != c.roles->display.end()) {
      c.s << (latex ? it->second.latex : it->second.text);
      return;
    }
  }
  c.s << (latex ? s.get_TeX_name() : s.get_name());
}

// Registered once, before the first print.
void register_printers() {
  static const bool done = [] {
    GiNaC::set_print_func<GiNaC::numeric, decimal_text>(print_decimal);
    GiNaC::set_print_func<GiNaC::numeric, decimal_latex>(print_decimal);
    GiNaC::set_print_func<GiNaC::add, decimal_text>(print_sum<decimal_text>);
    GiNaC::set_print_func<GiNaC::add, decimal_latex>(print_sum<decimal_latex>);
    GiNaC::set_print_func<GiNaC::mul, decimal_text>(print_product<decimal_text>);
    GiNaC::set_print_func<GiNaC::mul, decimal_latex>(print_product<decimal_latex>);
    GiNaC::set_print_func<GiNaC::symbol, decimal_text>(print_symbol<decimal_text>);
    GiNaC::set_print_func<GiNaC::symbol, decimal_latex>(print_symbol<decimal_latex>);
    return true;
  }();
  (void)done;
}

// The number of nodes e has printed as a tree (its subexpressions repeated wherever they
// occur), counted over the graph once per distinct subexpression; saturates at `limit`.
double tree_size(const ex& e, std::map<ex, double, GiNaC::ex_is_less>& memo, double limit) {
  if (e.nops() == 0) return 1;
  if (const auto it = memo.find(e); it != memo.end()) return it->second;
  double n = 1;
  for (std::size_t i = 0; i < e.nops() && n < limit; ++i) n += tree_size(e.op(i), memo, limit);
  memo.emplace(e, std::min(n, limit));
  return std::min(n, limit);
}

}  // namespace

void detail::check_printable(const ex& e, std::string_view instead) {
  std::map<ex, double, GiNaC::ex_is_less> memo;
  if (tree_size(e, memo, 2.0 * kMaxPrintedNodes) > kMaxPrintedNodes) {
    throw InvalidArgument(OptionMessage{fmt::format(
        "this equation prints as a tree of more than {:.0f} terms and factors (its parts repeat "
        "wherever they occur: tens of megabytes of text, and minutes to expand): {}",
        kMaxPrintedNodes, instead)});
  }
}

std::string detail::print(const ex& e, Format format, const PrintRoles* roles) {
  register_printers();
  if (format == Format::text || format == Format::latex) check_printable(e);
  std::ostringstream os;
  switch (format) {
    case Format::text: {
      decimal_text context(os);
      context.roles = roles;
      e.print(context);
      break;
    }
    case Format::latex: {
      decimal_latex context(os);
      context.roles = roles;
      e.print(context);
      break;
    }
    case Format::cpp:
      e.print(GiNaC::print_csrc_double(os));
      break;
    case Format::python:
      e.print(GiNaC::print_python(os));
      break;
  }
  return os.str();
}

detail::PrintRoles Equations::Impl::roles() const {
  detail::PrintRoles r;
  const auto put = [&](const ex& s, SymbolRole role, int index) {
    if (GiNaC::is_a<GiNaC::symbol>(s)) {
      r.by_name[GiNaC::ex_to<GiNaC::symbol>(s).get_name()] = {role, index};
    }
  };
  for (int i = 0; i < nq; ++i) put(q[static_cast<std::size_t>(i)], SymbolRole::coordinate, i);
  for (int i = 0; i < nv; ++i) {
    put(v[static_cast<std::size_t>(i)], SymbolRole::speed, i);
    put(vdot[static_cast<std::size_t>(i)], SymbolRole::acceleration, i);
  }
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    put(inputs[k], SymbolRole::input, static_cast<int>(k));
  }
  r.display = display;
  return r;
}

}  // namespace momenta::symbolic
