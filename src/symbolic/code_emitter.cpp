#include "code_emitter.hpp"

#include <algorithm>
#include <sstream>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta::symbolic::detail {

using GiNaC::ex;

namespace {

// FNV-1a over text, and a mixing step for combining hashes (splitmix64's finalizer).
std::uint64_t text_hash(std::string_view text, std::uint64_t h = 1469598103934665603ull) {
  for (const char ch : text) h = (h ^ static_cast<unsigned char>(ch)) * 1099511628211ull;
  return h;
}

std::uint64_t mix(std::uint64_t h, std::uint64_t x) {
  std::uint64_t z = h ^ (x + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2));
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

bool by_hash(const std::pair<std::uint64_t, ex>& a, const std::pair<std::uint64_t, ex>& b) {
  return a.first < b.first;
}

}  // namespace

std::string CodeEmitter::literal(const GiNaC::numeric& n) const {
  const double x = n.to_double();
  std::string s = fmt::format("{:.17g}", x);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // a double, not an int
  return x < 0 ? "(" + s + ")" : s;
}

std::string CodeEmitter::operator()(const ex& e) {
  if (GiNaC::is_a<GiNaC::numeric>(e)) return literal(GiNaC::ex_to<GiNaC::numeric>(e));
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    const auto it = symbols_.find(e);
    return GiNaC::ex_to<GiNaC::symbol>(it != symbols_.end() ? it->second : e).get_name();
  }
  if (const auto it = names_.find(e); it != names_.end()) return it->second;
  const std::string value = compound(e);
  const std::string name = fmt::format("t{}", next_++);
  lines_ += indent_ + (language_ == Language::cpp ? "const double " : "") + name + " = " + value +
            (language_ == Language::cpp ? ";\n" : "\n");
  names_.emplace(e, name);
  return name;
}

// Hashes that do not depend on GiNaC's choices: a sum hashes as it would leading positive (a
// product holding it takes the sign: −c·x·(a + b) and c·x·(−a − b) are one product).
std::uint64_t CodeEmitter::structure_hash(const ex& e) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) return text_hash(GiNaC::ex_to<GiNaC::symbol>(e).get_name());
  if (GiNaC::is_a<GiNaC::numeric>(e)) {
    std::ostringstream os;
    os << GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(e));
    return text_hash(os.str(), 7);
  }
  if (const auto it = hashes_.find(e); it != hashes_.end()) return it->second;
  std::uint64_t h = 0;
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    h = mix(unsigned_hash(e), term_negative(e) ? 1 : 2);
  } else {
    std::vector<std::uint64_t> parts;
    if (GiNaC::is_a<GiNaC::add>(e)) {
      const bool flip = leads_negative(e);
      for (std::size_t i = 0; i < e.nops(); ++i) {
        parts.push_back(mix(unsigned_hash(e.op(i)), term_negative(e.op(i)) != flip ? 1 : 2));
      }
      std::sort(parts.begin(), parts.end());
      h = text_hash("add");
    } else {
      for (std::size_t i = 0; i < e.nops(); ++i) parts.push_back(structure_hash(e.op(i)));
      h = text_hash(GiNaC::is_a<GiNaC::function>(e) ? GiNaC::ex_to<GiNaC::function>(e).get_name()
                                                    : GiNaC::ex_to<GiNaC::basic>(e).class_name());
    }
    for (const std::uint64_t p : parts) h = mix(h, p);
  }
  hashes_.emplace(e, h);
  return h;
}

// A term without its sign: a product's factors, numbers by their magnitude.
std::uint64_t CodeEmitter::unsigned_hash(const ex& term) {
  if (!GiNaC::is_a<GiNaC::mul>(term)) return structure_hash(term);
  std::vector<std::uint64_t> parts;
  GiNaC::numeric magnitude = 1;  // −x is x times −1: a coefficient of magnitude 1 is no factor
  for (std::size_t i = 0; i < term.nops(); ++i) {
    const ex f = term.op(i);
    if (GiNaC::is_a<GiNaC::numeric>(f)) {
      magnitude *= GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(f));
    } else {
      parts.push_back(structure_hash(f));
    }
  }
  if (magnitude != 1) parts.push_back(structure_hash(magnitude));
  std::sort(parts.begin(), parts.end());
  std::uint64_t h = text_hash("mul");
  for (const std::uint64_t p : parts) h = mix(h, p);
  return h;
}

// A term's sign once every sum in it leads positive: a number's own, a product's coefficient's
// times a minus per factor sum that leads negative.
bool CodeEmitter::term_negative(const ex& term) {
  if (GiNaC::is_a<GiNaC::numeric>(term)) return GiNaC::ex_to<GiNaC::numeric>(term).is_negative();
  if (!GiNaC::is_a<GiNaC::mul>(term)) return false;
  bool negative = false;
  for (std::size_t i = 0; i < term.nops(); ++i) {
    const ex f = term.op(i);
    const bool minus = GiNaC::is_a<GiNaC::numeric>(f)
                           ? GiNaC::ex_to<GiNaC::numeric>(f).is_negative()
                           : GiNaC::is_a<GiNaC::add>(f) && leads_negative(f);
    negative = negative != minus;
  }
  return negative;
}

// Whether a sum's leading term — the least unsigned_hash — is negative.
bool CodeEmitter::leads_negative(const ex& sum) {
  if (const auto it = leads_negative_.find(sum); it != leads_negative_.end()) return it->second;
  std::uint64_t lead = 0;
  bool negative = false;
  for (std::size_t i = 0; i < sum.nops(); ++i) {
    const std::uint64_t h = unsigned_hash(sum.op(i));
    if (i > 0 && h >= lead) continue;
    lead = h;
    negative = term_negative(sum.op(i));
  }
  leads_negative_.emplace(sum, negative);
  return negative;
}

std::string CodeEmitter::compound(const ex& e) {
  const bool cpp = language_ == Language::cpp;
  if (GiNaC::is_a<GiNaC::add>(e)) {
    std::vector<std::pair<std::uint64_t, ex>> terms;
    for (std::size_t i = 0; i < e.nops(); ++i) terms.emplace_back(structure_hash(e.op(i)), e.op(i));
    std::stable_sort(terms.begin(), terms.end(), by_hash);
    std::string s;
    for (std::size_t i = 0; i < terms.size(); ++i) s += (i ? " + " : "") + (*this)(terms[i].second);
    return s;
  }
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    // Every factor sum leading positive, the product's number taking the signs.
    std::vector<std::pair<std::uint64_t, ex>> factors;
    GiNaC::numeric coefficient = 1;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      const ex f = e.op(i);
      if (GiNaC::is_a<GiNaC::numeric>(f)) {
        coefficient *= GiNaC::ex_to<GiNaC::numeric>(f);
      } else if (GiNaC::is_a<GiNaC::add>(f) && leads_negative(f)) {
        coefficient = -coefficient;
        factors.emplace_back(structure_hash(f), -f);
      } else {
        factors.emplace_back(structure_hash(f), f);
      }
    }
    std::stable_sort(factors.begin(), factors.end(), by_hash);
    std::string s = coefficient == 1 ? "" : literal(coefficient);
    for (const auto& factor : factors) s += (s.empty() ? "" : " * ") + (*this)(factor.second);
    return s;
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const std::string base = (*this)(e.op(0));
    const ex exponent = e.op(1);
    if (exponent.is_equal(-1)) return "1.0 / " + base;
    if (exponent.is_equal(2)) return base + " * " + base;
    if (exponent.is_equal(GiNaC::numeric(1, 2))) return (cpp ? "std::sqrt(" : "sqrt(") + base + ")";
    return cpp ? "std::pow(" + base + ", " + (*this)(exponent) + ")"
               : base + " ** " + (*this)(exponent);
  }
  if (GiNaC::is_a<GiNaC::function>(e)) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    std::string s = (cpp ? "std::" : "") + name + "(";
    for (std::size_t i = 0; i < e.nops(); ++i) s += (i ? ", " : "") + (*this)(e.op(i));
    return s + ")";
  }
  throw InvalidArgument(fmt::format("generate_code: cannot write an expression of class {}",
                                    GiNaC::ex_to<GiNaC::basic>(e).class_name()));
}

}  // namespace momenta::symbolic::detail
