#include "code_emitter.hpp"

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta::symbolic::detail {

using GiNaC::ex;

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

std::string CodeEmitter::compound(const ex& e) {
  const bool cpp = language_ == Language::cpp;
  if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
    const char* op = GiNaC::is_a<GiNaC::add>(e) ? " + " : " * ";
    std::string s;
    for (std::size_t i = 0; i < e.nops(); ++i) s += (i ? op : "") + (*this)(e.op(i));
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
