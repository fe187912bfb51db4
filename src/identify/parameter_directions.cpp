#include "parameter_directions.hpp"

#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace momenta::identify::detail {
namespace {

std::string join_names(const std::vector<std::string>& names) {
  if (names.size() == 1) return names[0];
  std::string text;
  for (std::size_t i = 0; i + 1 < names.size(); ++i) text += (i ? ", " : "") + names[i];
  return text + " and " + names.back();
}

}  // namespace

std::string describe_direction(const VecX& v, const std::vector<std::string>& names) {
  const double largest = v.cwiseAbs().maxCoeff();
  std::vector<int> involved;
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (std::abs(v[i]) >= 0.1 * largest) involved.push_back(int(i));
  std::vector<std::string> who;
  for (const int i : involved) who.push_back(names[std::size_t(i)]);
  bool equal = true, same_sign = true;
  for (const int i : involved) {
    equal = equal && std::abs(std::abs(v[i]) / largest - 1.0) < 0.1;
    same_sign = same_sign && (v[i] > 0) == (v[involved[0]] > 0);
  }
  if (involved.size() == 1) {
    return fmt::format("{} changes no output: the data do not determine it", who[0]);
  }
  if (equal && same_sign) {
    std::vector<std::string> ratios;
    for (std::size_t k = 1; k < who.size(); ++k) ratios.push_back(who[k] + "/" + who[0]);
    return fmt::format(
        "{} scaled by one factor together change no output: the data determine only {} {}",
        join_names(who), ratios.size() == 1 ? "the ratio" : "the ratios", join_names(ratios));
  }
  if (equal && involved.size() == 2) {
    return fmt::format(
        "{} raised and {} lowered by one factor change no output: the data determine only the "
        "product {}·{}",
        who[0], who[1], who[0], who[1]);
  }
  std::vector<std::string> terms;
  for (const int i : involved)
    terms.push_back(fmt::format("{:+.2f} δln {}", v[i] / largest, names[std::size_t(i)]));
  return fmt::format(
      "{} change no output moved together as {}: the data do not determine that "
      "combination",
      join_names(who), fmt::join(terms, " "));
}

std::string combination(const VecX& v, const std::vector<std::string>& names) {
  const double largest = v.cwiseAbs().maxCoeff();
  std::vector<std::string> terms;
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (std::abs(v[i]) >= 0.1 * largest)
      terms.push_back(fmt::format("{:+.2f} ln {}", v[i] / largest, names[std::size_t(i)]));
  return fmt::format("{}", fmt::join(terms, " "));
}

}  // namespace momenta::identify::detail
