#include "page_data.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

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

}  // namespace

std::string encode_f64(std::span<const double> values) {
  return "f64:" +
         base64(reinterpret_cast<const unsigned char*>(values.data()), values.size_bytes());
}

std::string encode_f32(std::span<const double> values) {
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

}  // namespace momenta::report::detail
