#include "body_point_argument.hpp"

#include <cstdio>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <CLI/CLI.hpp>

#include "momenta/common/suggest.hpp"
#include "momenta/io/yaml_reader.hpp"

namespace momenta::cli {
namespace {

// Three comma-separated finite numbers of moderate size, or none.
std::optional<Vec3> three_numbers(const std::string& text) {
  double x, y, z;
  char tail;
  if (std::sscanf(text.c_str(), "%lf,%lf,%lf%c", &x, &y, &z, &tail) != 3) return std::nullopt;
  const Vec3 p(x, y, z);
  if (!p.allFinite() || p.cwiseAbs().maxCoeff() > io::kLargestNumber) return std::nullopt;
  return p;
}

}  // namespace

int body_named(const model::Model& model, const std::string& name, const char* option) {
  if (const auto b = model.find_body(name)) return *b;
  std::vector<std::string_view> names;
  for (const model::Body& b : model.bodies()) names.push_back(b.name);
  throw CLI::ValidationError(
      option, fmt::format("no body named '{}'{}; the model has {}", name, did_you_mean(name, names),
                          fmt::join(names, ", ")));
}

std::pair<int, Vec3> parse_body_point(const model::Model& model, const std::string& text,
                                      const char* option, bool world_allowed) {
  const auto colon = text.find(':');
  const std::string name = text.substr(0, colon);
  const int body = body_named(model, name, option);
  if (body == 0 && !world_allowed) {
    throw CLI::ValidationError(option, "the world is not a moving body");
  }
  if (colon == std::string::npos) return {body, Vec3::Zero()};
  const std::optional<Vec3> p = three_numbers(text.substr(colon + 1));
  if (!p) {
    throw CLI::ValidationError(
        option, fmt::format("'{}': expected BODY:x,y,z with three finite numbers (m, in the "
                            "body's frame), e.g. {}:0,0,0.1",
                            text, name));
  }
  return {body, *p};
}

Vec3 parse_vector(const std::string& text, const char* option, const char* unit) {
  const std::optional<Vec3> p = three_numbers(text);
  if (!p) {
    throw CLI::ValidationError(
        option,
        fmt::format("'{}': expected x,y,z, three finite numbers ({}), e.g. 1,0,0", text, unit));
  }
  return *p;
}

}  // namespace momenta::cli
