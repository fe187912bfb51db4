#pragma once
// Straight-line code for expressions: every distinct compound subexpression (a sum, product,
// power or function) computed once into a temporary, in dependency order. The equations' entries
// share most of their subexpressions (the recursion builds them as a graph), so this code grows
// with the model, where printing each entry as a tree would grow exponentially. The operands of
// a sum or product go in the order of a hash of their structure and names (GiNaC's own order
// moves from run to run with the addresses its hashes are seeded with), so the same equations
// give the same code, byte for byte.

#include <cstdint>
#include <map>
#include <string>

#include <ginac/ginac.h>

namespace momenta::symbolic::detail {

class CodeEmitter {
 public:
  enum class Language { cpp, python };
  /// `symbols`: what each symbol is called in the code (q[0], u[1], ...); others keep their names.
  CodeEmitter(Language language, std::string indent, const GiNaC::exmap& symbols)
      : language_(language), indent_(std::move(indent)), symbols_(symbols) {}

  /// The code (a temporary's name, a symbol or a literal) of `e`; its temporaries are appended to
  /// lines().
  std::string operator()(const GiNaC::ex& e);
  const std::string& lines() const { return lines_; }

 private:
  std::string literal(const GiNaC::numeric& n) const;
  // A hash of e's structure, symbols' names and numbers' values alone (the same every run).
  std::uint64_t structure_hash(const GiNaC::ex& e);
  std::uint64_t unsigned_hash(const GiNaC::ex& term);
  bool term_negative(const GiNaC::ex& term);
  // Whether a sum's leading term (the least unsigned_hash) is negative: such a sum is written
  // negated, the product holding it taking the minus (GiNaC keeps −c·x·(a + b) or c·x·(−a − b)
  // as its hash order fell).
  bool leads_negative(const GiNaC::ex& sum);
  std::string compound(const GiNaC::ex& e);
  Language language_;
  std::string indent_;
  const GiNaC::exmap& symbols_;
  std::string lines_;
  std::map<GiNaC::ex, std::string, GiNaC::ex_is_less> names_;
  std::map<GiNaC::ex, std::uint64_t, GiNaC::ex_is_less> hashes_;
  std::map<GiNaC::ex, bool, GiNaC::ex_is_less> leads_negative_;
  int next_ = 0;
};

}  // namespace momenta::symbolic::detail
