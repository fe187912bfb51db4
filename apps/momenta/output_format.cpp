#include "output_format.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/common/number_text.hpp"

namespace momenta::cli {
namespace {

using json = nlohmann::ordered_json;

// JSON text of a value. A string that is not UTF-8 (a file name in another encoding, echoed back)
// has its bad bytes written as U+FFFD: the JSON stays valid, where nlohmann would throw.
std::string dumped(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }

// Writes `j` at `indent` into `out`; objects and nested lists open one item a line.
void write_json(std::string& out, const json& j, int indent, ListSpacing lists) {
  const auto flat = [](const json& a) {
    return a.is_array() &&
           std::all_of(a.begin(), a.end(), [](const json& e) { return e.is_primitive(); });
  };
  const std::string pad(static_cast<std::size_t>(indent + 2), ' ');
  if (j.is_object() && !j.empty()) {
    out += "{\n";
    std::size_t i = 0;
    for (const auto& [key, value] : j.items()) {
      out += pad + dumped(json(key)) + ": ";
      write_json(out, value, indent + 2, lists);
      out += ++i < j.size() ? ",\n" : "\n";
    }
    out += std::string(static_cast<std::size_t>(indent), ' ') + "}";
  } else if (j.is_array() && !flat(j)) {
    out += "[\n";
    for (std::size_t i = 0; i < j.size(); ++i) {
      out += pad;
      write_json(out, j[i], indent + 2, lists);
      out += i + 1 < j.size() ? ",\n" : "\n";
    }
    out += std::string(static_cast<std::size_t>(indent), ' ') + "]";
  } else if (lists == ListSpacing::compact) {
    out += dumped(j);
  } else {
    // Numbers, strings and lists of them, compact but for ", " between items (a comma inside a
    // string stays as it is).
    const std::string text = dumped(j);
    bool in_string = false;
    for (std::size_t k = 0; k < text.size(); ++k) {
      const char c = text[k];
      if (c == '"' && (k == 0 || text[k - 1] != '\\')) in_string = !in_string;
      out += c;
      if (c == ',' && !in_string) out += ' ';
    }
  }
}

}  // namespace

json vec_json(const Vec3& v) { return json::array({v.x() + 0.0, v.y() + 0.0, v.z() + 0.0}); }

json finite_or_null(double x) { return std::isfinite(x) ? json(x + 0.0) : json(nullptr); }

json matrix_json(const MatX& M) {
  json rows = json::array();
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    json row = json::array();
    for (Eigen::Index k = 0; k < M.cols(); ++k) row.push_back(M(i, k) + 0.0);
    rows.push_back(std::move(row));
  }
  return rows;
}

std::string json_text(const json& j, ListSpacing lists) {
  std::string out;
  write_json(out, j, 0, lists);
  return out;
}

Vec3 shown(const Vec3& v, double scale) {
  return v.unaryExpr([&](double x) { return shown_value(x, scale); });
}

Mat3 shown(const Mat3& M) {
  const double scale = M.cwiseAbs().maxCoeff();
  return M.unaryExpr([&](double x) { return shown_value(x, scale); });
}

double length_scale(const inertia::MassProperties& mp) {
  return std::max(mp.center_of_mass().norm(),
                  std::sqrt(mp.inertia_about_com().trace() / (2 * mp.mass())));
}

std::string vec_text(const Vec3& v) {
  // + 0.0 writes a negative zero (a product's sign, not a value) as 0.
  return fmt::format("[{:.6g}, {:.6g}, {:.6g}]", v.x() + 0.0, v.y() + 0.0, v.z() + 0.0);
}

void check_csv_target(const std::optional<std::string>& csv, bool force) {
  if (csv && *csv != "-" && std::filesystem::exists(*csv) && !force) {
    throw FileError(fmt::format("--csv {}: the file exists; pass --force to overwrite it", *csv));
  }
}

bool emit_csv(const std::optional<std::string>& csv, const std::string& text) {
  if (!csv) return false;
  if (*csv == "-") {
    fmt::print("{}", text);
    return true;
  }
  std::ofstream out(*csv, std::ios::binary);
  if (!out) throw FileError(fmt::format("--csv {}: cannot write the file", *csv));
  out << text;
  return false;
}

}  // namespace momenta::cli
