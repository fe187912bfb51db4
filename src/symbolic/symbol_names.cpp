// Names as LaTeX: a symbol's name in parts (m_rod → m_{\mathrm{rod}}), Greek letters by name,
// a coordinate's rate and acceleration accents.

#include "derivation.hpp"

#include <cctype>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

namespace momenta::symbolic::detail {
namespace {

// A Greek letter's name (theta, Omega) as LaTeX (\\theta, \\Omega), or "".
std::string greek_latex(std::string_view word) {
  static constexpr std::string_view letters[] = {
      "alpha",   "beta",   "gamma", "delta",   "epsilon", "zeta",  "eta",   "theta", "iota",
      "kappa",   "lambda", "mu",    "nu",      "xi",      "pi",    "rho",   "sigma", "tau",
      "upsilon", "phi",    "chi",   "psi",     "omega",   "Gamma", "Delta", "Theta", "Lambda",
      "Xi",      "Pi",     "Sigma", "Upsilon", "Phi",     "Psi",   "Omega"};
  for (std::string_view letter : letters) {
    if (word == letter) return fmt::format("\\{}", letter);
  }
  return "";
}

// A symbol's name as LaTeX, as a textbook sets it, in two parts: a one-letter or Greek head and
// the rest of the name as its subscript (m_bob → m, \\mathrm{bob}; I_rod_yy → I, \\mathrm{rod},yy;
// theta1 → \\theta, 1); any other name upright and whole, with no subscript
// (\\mathrm{floor\\_plane\\_x}) — or, for a coordinate, as q with the name as its subscript.
struct LatexName {
  std::string base, subscript;
  bool word = false;  // neither a letter nor Greek: the whole name upright in base
  std::string text() const {
    return subscript.empty() ? base : fmt::format("{}_{{{}}}", base, subscript);
  }
};

LatexName latex_parts(const std::string& name) {
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const std::size_t end = name.find('_', start);
    parts.push_back(name.substr(start, end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  std::size_t letters = parts[0].size();
  while (letters > 0 && std::isdigit(static_cast<unsigned char>(parts[0][letters - 1]))) --letters;
  const std::string head = parts[0].substr(0, letters), digits = parts[0].substr(letters);
  const std::string greek = greek_latex(head);
  const bool letter = head.size() == 1 && std::isalpha(static_cast<unsigned char>(head[0]));
  if (greek.empty() && !letter) {
    std::string s;
    for (char c : name) s += c == '_' ? std::string("\\_") : std::string(1, c);
    return {fmt::format("\\mathrm{{{}}}", s), "", true};
  }
  std::vector<std::string> subscript;
  if (!digits.empty()) subscript.push_back(digits);
  for (std::size_t k = 1; k < parts.size(); ++k) {
    const std::string& part = parts[k];
    if (part.empty()) continue;
    const std::string part_greek = greek_latex(part);
    const bool short_part = part.size() <= 2 || std::all_of(part.begin(), part.end(), [](char c) {
                              return std::isdigit(static_cast<unsigned char>(c));
                            });
    subscript.push_back(!part_greek.empty() ? part_greek
                        : short_part        ? part
                                            : fmt::format("\\mathrm{{{}}}", part));
  }
  return {greek.empty() ? head : greek, fmt::format("{}", fmt::join(subscript, ",")), false};
}

}  // namespace

std::string latex_name(const std::string& name) { return latex_parts(name).text(); }

// A coordinate, its rate or acceleration (accent "", "\\dot", "\\ddot") in LaTeX: the accent
// over the letter, a word-named coordinate as q_{name} (\\ddot{q}_{\\mathrm{upper}}), as
// textbooks write generalized coordinates.
std::string coordinate_latex(const std::string& name, std::string_view accent) {
  LatexName parts = latex_parts(name);
  if (parts.word) parts = {"q", parts.base, false};
  if (accent.empty()) return parts.text();
  return LatexName{fmt::format("{}{{{}}}", accent, parts.base), parts.subscript}.text();
}

}  // namespace momenta::symbolic::detail
