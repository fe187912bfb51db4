#include "page_data.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <string_view>

#include "momenta/common/error.hpp"

namespace momenta::report::detail {
namespace {

std::string base64(const unsigned char* bytes, std::size_t size) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < size; i += 3) {
    const std::uint32_t n = (bytes[i] << 16) | (bytes[i + 1] << 8) | bytes[i + 2];
    out += {kAlphabet[(n >> 18) & 63], kAlphabet[(n >> 12) & 63], kAlphabet[(n >> 6) & 63],
            kAlphabet[n & 63]};
  }
  if (i + 1 == size) {
    const std::uint32_t n = bytes[i] << 16;
    out += {kAlphabet[(n >> 18) & 63], kAlphabet[(n >> 12) & 63], '=', '='};
  } else if (i + 2 == size) {
    const std::uint32_t n = (bytes[i] << 16) | (bytes[i + 1] << 8);
    out += {kAlphabet[(n >> 18) & 63], kAlphabet[(n >> 12) & 63], kAlphabet[(n >> 6) & 63], '='};
  }
  return out;
}

static_assert(std::endian::native == std::endian::little, "the page reads little-endian bytes");

thread_local ArraysApart* arrays_apart = nullptr;

}  // namespace

ArraysApart::ArraysApart(std::string marker) : marker_(std::move(marker)), outer_(arrays_apart) {
  if (marker_.empty()) throw InvalidArgument("report data: an empty marker for its arrays");
  for (const char c : marker_) {
    if (c == '"' || c == '\\' || static_cast<unsigned char>(c) < 0x20) {
      throw InvalidArgument("report data: its arrays' marker holds a character JSON escapes");
    }
  }
  arrays_apart = this;
}

ArraysApart::~ArraysApart() { arrays_apart = outer_; }

std::string ArraysApart::put(std::span<const double> values, bool single) {
  arrays_.push_back({{values.begin(), values.end()}, single});
  return marker_ + std::to_string(arrays_.size() - 1);
}

std::string escape_html(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string encode_f64(std::span<const double> values) {
  if (arrays_apart != nullptr) return arrays_apart->put(values, false);
  return "f64:" +
         base64(reinterpret_cast<const unsigned char*>(values.data()), values.size_bytes());
}

std::string encode_f32(std::span<const double> values) {
  if (arrays_apart != nullptr) return arrays_apart->put(values, true);
  std::vector<float> narrow(values.begin(), values.end());
  return "f32:" + base64(reinterpret_cast<const unsigned char*>(narrow.data()),
                         narrow.size() * sizeof(float));
}

json vec_json(const Vec3& v) { return json::array({v.x(), v.y(), v.z()}); }

json mat_json(const Mat3& m) {
  json out = json::array();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out.push_back(m(r, c));
  }
  return out;
}

json part_json(const io::PartSummary& part) {
  json sizes = json::object();
  for (const auto& [key, value] : part.sizes) sizes[key] = value;
  json j = {{"name", part.name},
            {"kind", part.kind},
            {"hole", part.hole},
            {"mass", part.mass_properties.mass()},
            {"sizes", sizes},
            {"R", mat_json(part.R_BS)},
            {"p", vec_json(part.p_BoSo_B)}};
  if (part.mesh) {
    std::vector<double> vertices;
    vertices.reserve(part.mesh->vertices.size() * 3);
    for (const Vec3& v : part.mesh->vertices)
      vertices.insert(vertices.end(), {v.x(), v.y(), v.z()});
    std::vector<double> triangles;
    triangles.reserve(part.mesh->triangles.size() * 3);
    for (const auto& t : part.mesh->triangles)
      triangles.insert(triangles.end(), t.begin(), t.end());
    j["mesh"] = {{"vertices", encode_f32(vertices)}, {"triangles", encode_f64(triangles)}};
  }
  if (part.kind == "inertia") j["equivalent"] = equivalent_ellipsoid_json(part.mass_properties);
  return j;
}

json equivalent_ellipsoid_json(const inertia::MassProperties& mp) {
  // A uniform solid ellipsoid of semi-axes a, b, c has I1 = m (b² + c²)/5, ... so
  // a² = 5 (I2 + I3 − I1) / (2 m). Principal moments of a physical body obey the triangle
  // inequality, so a² ≥ 0; a point mass gives a point.
  if (!(mp.mass() > 0.0)) return nullptr;
  const auto axes = mp.principal_axes();
  const Vec3 I = axes.moments;
  Vec3 semi;
  for (int k = 0; k < 3; ++k) {
    const double s2 = 5.0 * (I.sum() - 2.0 * I[k]) / (2.0 * mp.mass());
    semi[k] = std::sqrt(std::max(s2, 0.0));
  }
  return {{"semi_axes", vec_json(semi)},
          {"R", mat_json(axes.R_BP)},
          {"center", vec_json(mp.center_of_mass())}};
}

namespace {

// The size a part file gives under `key`, 0 where it gives none.
double size_of(const io::PartSummary& part, std::string_view key) {
  for (const auto& [name, value] : part.sizes)
    if (name == key) return value;
  return 0.0;
}

// n points round the circle of radius r about S's z-axis at height z.
void add_circle(std::vector<Vec3>& out, double r, double z, int n = 32) {
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * std::numbers::pi * k / n;
    out.emplace_back(r * std::cos(a), r * std::sin(a), z);
  }
}

// Points spread evenly over the ellipsoid of semi-axes `semi` (a Fibonacci lattice).
void add_ellipsoid(std::vector<Vec3>& out, const Vec3& semi, int n = 200) {
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < n; ++k) {
    const double z = 1.0 - 2.0 * (k + 0.5) / n, r = std::sqrt(1.0 - z * z);
    out.emplace_back(semi.x() * r * std::cos(golden * k), semi.y() * r * std::sin(golden * k),
                     semi.z() * z);
  }
}

}  // namespace

std::vector<Vec3> part_outline_points(const io::PartSummary& part) {
  std::vector<Vec3> s;  // in the part's frame S
  if (part.hole) return s;
  const std::string& kind = part.kind;
  const double r = size_of(part, "radius"), outer = size_of(part, "outer_radius");
  const double length = size_of(part, "length");
  if (kind == "point_mass") {
    s.emplace_back(0.0, 0.0, 0.0);
  } else if (kind == "slender_rod") {
    s = {Vec3(0, 0, -length / 2), Vec3(0, 0, length / 2)};
  } else if (kind == "cone") {
    s.emplace_back(0.0, 0.0, 0.0);
    add_circle(s, r, size_of(part, "height"));
  } else if (kind == "cylinder" || kind == "hollow_cylinder" || kind == "cylindrical_shell" ||
             kind == "thin_disk") {
    add_circle(s, kind == "hollow_cylinder" ? outer : r, -length / 2);
    add_circle(s, kind == "hollow_cylinder" ? outer : r, length / 2);
  } else if (kind == "thin_ring" || kind == "annulus") {
    add_circle(s, kind == "annulus" ? outer : r, 0.0);
  } else if (kind == "sphere" || kind == "hollow_sphere" || kind == "spherical_shell") {
    add_ellipsoid(s, Vec3::Constant(kind == "hollow_sphere" ? outer : r));
  } else if (kind == "ellipsoid") {
    add_ellipsoid(s, Vec3(size_of(part, "semi_axes.x"), size_of(part, "semi_axes.y"),
                          size_of(part, "semi_axes.z")));
  } else if (kind == "box" || kind == "thin_plate") {
    const Vec3 half =
        kind == "box"
            ? 0.5 * Vec3(size_of(part, "size.x"), size_of(part, "size.y"), size_of(part, "size.z"))
            : 0.5 * Vec3(size_of(part, "width"), size_of(part, "height"), 0.0);
    for (int k = 0; k < 8; ++k) {
      s.emplace_back((k & 1 ? 1 : -1) * half.x(), (k & 2 ? 1 : -1) * half.y(),
                     (k & 4 ? 1 : -1) * half.z());
    }
  } else if (kind == "mesh" && part.mesh) {
    const std::vector<Vec3>& vertices = part.mesh->vertices;
    const std::size_t step = std::max<std::size_t>(1, vertices.size() / 4096);
    for (std::size_t i = 0; i < vertices.size(); i += step) s.push_back(vertices[i]);
  }
  std::vector<Vec3> b;
  b.reserve(s.size());
  for (const Vec3& p : s) b.push_back(part.p_BoSo_B + part.R_BS * p);
  return b;
}

}  // namespace momenta::report::detail
