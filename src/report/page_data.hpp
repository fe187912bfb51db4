#pragma once
// Internal to the report: how numbers travel to the page. Long arrays go as base64 of their
// little-endian IEEE bytes ("f64:" or "f32:" then the text), which the page decodes into typed
// arrays: exact for float64, a third of the text of decimal, and no parsing of digits.
// Short arrays and scalars are plain JSON numbers (written to round-trip exactly).

#include <nlohmann/json.hpp>

#include <span>
#include <string>
#include <vector>

#include "momenta/io/part_file.hpp"
#include "momenta/math/types.hpp"
#include "momenta/model/model.hpp"
#include "momenta/report/report.hpp"

namespace momenta::report::detail {

using json = nlohmann::ordered_json;

/// "f64:<base64>" of the values (float64, exact).
std::string encode_f64(std::span<const double> values);
/// "f32:<base64>" of the values rounded to float32 (for what is only drawn).
std::string encode_f32(std::span<const double> values);

/// While one lives on this thread, encode_f64 and encode_f32 set the arrays apart instead of
/// writing them as text: each becomes `marker` followed by its index in arrays() (report::
/// simulation_report_parts; the in-page engine hands them over as typed arrays). Scoped, and
/// nested ones restore the outer one.
class ArraysApart {
 public:
  explicit ArraysApart(std::string marker);
  ~ArraysApart();
  ArraysApart(const ArraysApart&) = delete;
  ArraysApart& operator=(const ArraysApart&) = delete;

  std::string put(std::span<const double> values, bool single);
  std::vector<ReportArray> take() { return std::move(arrays_); }

 private:
  std::string marker_;
  std::vector<ReportArray> arrays_;
  ArraysApart* outer_;
};

json vec_json(const Vec3& v);
/// A 3 × 3 matrix as 9 numbers, row by row.
json mat_json(const Mat3& m);

/// The drawable description of a part placed in its body frame B: kind, sizes, pose, hole, mesh.
json part_json(const io::PartSummary& part);
/// The uniform solid ellipsoid with the same mass, centre of mass and inertia: semi-axes along
/// the principal axes (columns of R), for bodies given by their inertia alone.
json equivalent_ellipsoid_json(const inertia::MassProperties& mp);

/// Points on the surface of a part, in its body frame B (its pose applied), enough that their
/// convex hull in any view is its silhouette to a few per cent: a cone's apex and base circle, a
/// cylinder's end circles, a sphere's or ellipsoid's sample of its surface, a box's corners, a
/// rod's ends, a mesh's vertices (at most 4096 of them). Shapes drawn as the web page draws them
/// (web/src/shapes.js: a cone's apex at S's origin, its base at z = height). Empty for a hole and
/// for a part given by its inertia alone.
std::vector<Vec3> part_outline_points(const io::PartSummary& part);

/// Text made safe inside HTML or SVG markup and attribute values (& < > " escaped).
std::string escape_html(const std::string& text);

/// The HTML page: `data` (kind "simulation" or "inertia") with the embedded front-end.
std::string html_page(const std::string& title, const json& data, bool with_engine = false);

/// Whether this build embeds the in-page engine (MOMENTA_WASM_ENGINE): html_page's `with_engine`
/// then inlines it before the page's script, which finds it as window.createMomentaEngine.
bool engine_embedded();

}  // namespace momenta::report::detail
