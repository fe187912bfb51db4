#include "mesh/mesh_text_formats.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "momenta/common/chars_to_double.hpp"
#include "momenta/common/error.hpp"

namespace momenta::io::detail {
namespace {

using inertia::TriangleMesh;

// Reads a text token by token, with the line and column of each for messages.
class Tokens {
 public:
  Tokens(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  // The next token on the current line, or empty at its end ('#' starts a comment when asked).
  std::string_view next_on_line(bool hash_comments) {
    skip_blanks();
    if (at_ < text_.size() && hash_comments && text_[at_] == '#') {
      while (at_ < text_.size() && text_[at_] != '\n') ++at_;
    }
    const std::size_t begin = at_;
    while (at_ < text_.size() && !is_space(text_[at_])) ++at_;
    token_start_ = begin;
    return text_.substr(begin, at_ - begin);
  }

  // Moves to the start of the next line; false at the end of the text.
  bool next_line() {
    while (at_ < text_.size() && text_[at_] != '\n') ++at_;
    if (at_ >= text_.size()) return false;
    ++at_;
    ++line_;
    line_start_ = at_;
    return true;
  }

  // The next token, across lines; empty at the end of the text.
  std::string_view next() {
    for (;;) {
      const std::string_view token = next_on_line(false);
      if (!token.empty() || !next_line()) return token;
    }
  }

  [[noreturn]] void fail(const std::string& message) const {
    throw ParseError(file_, line_, static_cast<int>(token_start_ - line_start_) + 1, message);
  }

  double number(std::string_view token) const {
    double value = 0.0;
    const char* first = token.data();
    if (!token.empty() && token.front() == '+') ++first;  // chars_to_double takes no '+'
    const char* last = token.data() + token.size();
    const auto [ptr, ec] = chars_to_double(first, last, value);
    if (token.empty() || ptr != last || ec == std::errc::invalid_argument) {
      fail(fmt::format("expected a number, got '{}'", token));
    }
    if (ec == std::errc::result_out_of_range || !std::isfinite(value)) {
      fail(fmt::format("the coordinate '{}' is not a finite double", token));
    }
    return value;
  }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
  void skip_blanks() {
    while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\t' || text_[at_] == '\r'))
      ++at_;
  }

  std::string_view text_;
  const std::string& file_;
  std::size_t at_ = 0;
  std::size_t line_start_ = 0;
  std::size_t token_start_ = 0;
  int line_ = 1;
};

// An OBJ vertex reference "i", "i/t", "i//n" or "i/t/n" as a 0-based index into `count` vertices.
std::int32_t vertex_index(std::string_view ref, std::size_t count, const Tokens& tokens) {
  const std::string_view head = ref.substr(0, ref.find('/'));
  long long i = 0;
  const auto [ptr, ec] = std::from_chars(head.data(), head.data() + head.size(), i);
  if (head.empty() || ec != std::errc() || ptr != head.data() + head.size()) {
    tokens.fail(fmt::format("expected a vertex reference (i, i/t, i//n or i/t/n), got '{}'", ref));
  }
  const long long n = static_cast<long long>(count);
  const long long index = i > 0 ? i - 1 : n + i;  // negative: counted back from the last vertex
  if (i == 0 || index < 0 || index >= n) {
    tokens.fail(
        fmt::format("face refers to vertex {}, but {} vertices are defined before it", i, count));
  }
  return static_cast<std::int32_t>(index);
}

// Appends the triangles of a planar polygon: a fan when convex, ear clipping in the plane of its
// Newell normal when not (a fan of a concave polygon would cover area twice with opposite signs:
// right for volume integrals, wrong for a shell's area).
void triangulate(const std::vector<std::int32_t>& polygon, const std::vector<Vec3>& vertices,
                 std::vector<std::array<std::int32_t, 3>>& out) {
  const std::size_t n = polygon.size();
  const auto p = [&](std::size_t k) { return vertices[polygon[k % n]]; };
  Vec3 normal = Vec3::Zero();
  for (std::size_t k = 0; k < n; ++k) normal += p(k).cross(p(k + 1));
  bool convex = true;
  for (std::size_t k = 0; k < n && convex; ++k) {
    convex = (p(k + 1) - p(k)).cross(p(k + 2) - p(k + 1)).dot(normal) >= 0.0;
  }
  if (convex || n == 3) {
    for (std::size_t k = 1; k + 1 < n; ++k) out.push_back({polygon[0], polygon[k], polygon[k + 1]});
    return;
  }
  // Ear clipping: cut a convex corner with no other vertex inside, until a triangle is left.
  std::vector<std::int32_t> left = polygon;
  // Inside or on the boundary: a vertex on an ear's edge (a reflex corner exactly on the cut)
  // blocks it, or the cut would pass through the polygon's own boundary.
  const auto inside = [&](const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
    if (q == a || q == b || q == c) return false;
    return (b - a).cross(q - a).dot(normal) >= 0 && (c - b).cross(q - b).dot(normal) >= 0 &&
           (a - c).cross(q - c).dot(normal) >= 0;
  };
  while (left.size() > 3) {
    const std::size_t m = left.size();
    bool cut = false;
    for (std::size_t k = 0; k < m && !cut; ++k) {
      const Vec3& a = vertices[left[(k + m - 1) % m]];
      const Vec3& b = vertices[left[k]];
      const Vec3& c = vertices[left[(k + 1) % m]];
      if ((b - a).cross(c - b).dot(normal) <= 0) continue;  // a reflex corner
      bool empty = true;
      for (std::size_t r = 0; r < m && empty; ++r) {
        if (r == k || r == (k + 1) % m || r == (k + m - 1) % m) continue;
        empty = !inside(vertices[left[r]], a, b, c);
      }
      if (!empty) continue;
      out.push_back({left[(k + m - 1) % m], left[k], left[(k + 1) % m]});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(k));
      cut = true;
    }
    if (!cut) break;  // degenerate (self-intersecting) polygon: fan what is left
  }
  for (std::size_t k = 1; k + 1 < left.size(); ++k) out.push_back({left[0], left[k], left[k + 1]});
}

}  // namespace

TriangleMesh parse_obj(std::string_view text, const std::string& file, std::size_t& skipped) {
  TriangleMesh mesh;
  Tokens tokens(text, file);
  std::vector<std::int32_t> polygon;
  do {
    const std::string_view keyword = tokens.next_on_line(true);
    if (keyword == "v") {
      double xyzw[4] = {0, 0, 0, 1};
      int count = 0;
      for (std::string_view t = tokens.next_on_line(true); !t.empty();
           t = tokens.next_on_line(true), ++count) {
        const double value = tokens.number(t);
        if (count < 4) xyzw[count] = value;
      }
      if (count < 3) tokens.fail(fmt::format("a vertex needs x y z, got {} numbers", count));
      if (count == 4 && xyzw[3] == 0.0) tokens.fail("a vertex with w = 0 lies at infinity");
      const double w = count == 4 ? xyzw[3] : 1.0;
      if (mesh.vertices.size() >=
          static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        tokens.fail("more vertices than 32-bit indices hold");
      mesh.vertices.emplace_back(xyzw[0] / w, xyzw[1] / w, xyzw[2] / w);
    } else if (keyword == "f") {
      polygon.clear();
      for (std::string_view t = tokens.next_on_line(true); !t.empty();
           t = tokens.next_on_line(true)) {
        polygon.push_back(vertex_index(t, mesh.vertices.size(), tokens));
      }
      if (polygon.size() < 3) {
        tokens.fail(fmt::format("a face needs at least 3 vertices, got {}", polygon.size()));
      }
      triangulate(polygon, mesh.vertices, mesh.triangles);
    } else if (keyword == "l" || keyword == "p") {
      ++skipped;  // lines and points: no area, no volume
    }
    // Everything else (vt, vn, g, o, s, usemtl, mtllib, ...) carries no geometry of a solid.
  } while (tokens.next_line());
  return mesh;
}

TriangleMesh parse_ascii_stl(std::string_view text, const std::string& file) {
  TriangleMesh mesh;
  Tokens tokens(text, file);
  const auto expect = [&](std::string_view word) {
    const std::string_view t = tokens.next();
    if (t != word) {
      tokens.fail(
          fmt::format("expected '{}', got '{}'", word, t.empty() ? "the end of the file" : t));
    }
  };
  std::string_view t = tokens.next();
  if (t != "solid") tokens.fail(fmt::format("an ASCII STL file begins with 'solid', got '{}'", t));
  tokens.next_line();  // the solid's name, if any
  bool closed = false;
  for (t = tokens.next(); !t.empty(); t = tokens.next()) {
    closed = false;
    if (t == "endsolid") {
      closed = true;
      tokens.next_line();  // its name
      t = tokens.next();
      if (t.empty()) break;
      closed = false;
      if (t != "solid")
        tokens.fail(fmt::format("expected 'solid' or the end of the file, got '{}'", t));
      tokens.next_line();
      continue;
    }
    if (t != "facet") tokens.fail(fmt::format("expected 'facet' or 'endsolid', got '{}'", t));
    expect("normal");
    for (int k = 0; k < 3; ++k) tokens.number(tokens.next());  // the normal: not used
    expect("outer");
    expect("loop");
    std::array<std::int32_t, 3> triangle;
    for (int k = 0; k < 3; ++k) {
      expect("vertex");
      Vec3 p;
      for (int c = 0; c < 3; ++c) p[c] = tokens.number(tokens.next());
      triangle[k] = static_cast<std::int32_t>(mesh.vertices.size());
      mesh.vertices.push_back(p);
    }
    mesh.triangles.push_back(triangle);
    expect("endloop");
    expect("endfacet");
  }
  if (!closed) tokens.fail("the file ends inside a solid: 'endsolid' is missing (truncated?)");
  return mesh;
}

}  // namespace momenta::io::detail
