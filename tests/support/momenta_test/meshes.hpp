#pragma once
// Closed triangle meshes of the standard shapes, generated at run time for the mesh-path tests.
// Every mesh is outward-oriented (counter-clockwise seen from outside) and in the same frame as
// the matching primitive in momenta/inertia/primitives.hpp: centred, axis along z; the cone has
// its apex at the origin.

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "momenta/inertia/triangle_mesh.hpp"

namespace momenta::test {

using inertia::TriangleMesh;
using Tri = std::array<std::int32_t, 3>;

/// A box of edge lengths `size`, centred: 8 vertices, 12 triangles.
inline TriangleMesh box_mesh(const Vec3& size) {
  TriangleMesh m;
  const Vec3 h = size / 2;
  for (int i = 0; i < 8; ++i) {
    m.vertices.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(),
                            (i & 4) ? h.z() : -h.z());
  }
  // Faces −x, +x, −y, +y, −z, +z as two triangles each, outward.
  m.triangles = {Tri{0, 4, 6}, Tri{0, 6, 2}, Tri{1, 3, 7}, Tri{1, 7, 5},
                 Tri{0, 1, 5}, Tri{0, 5, 4}, Tri{2, 6, 7}, Tri{2, 7, 3},
                 Tri{0, 2, 3}, Tri{0, 3, 1}, Tri{4, 5, 7}, Tri{4, 7, 6}};
  return m;
}

/// A UV sphere of radius r with `rings` latitude bands and `segments` longitudes (vertices on the
/// sphere: an inscribed polyhedron), scaled by `semi_axes / r` into an ellipsoid if wanted.
inline TriangleMesh uv_ellipsoid(const Vec3& semi_axes, int rings, int segments) {
  TriangleMesh m;
  const double pi = std::numbers::pi;
  m.vertices.emplace_back(0, 0, semi_axes.z());  // North pole, 0.
  for (int i = 1; i < rings; ++i) {
    const double theta = pi * i / rings;
    for (int j = 0; j < segments; ++j) {
      const double phi = 2 * pi * j / segments;
      m.vertices.emplace_back(semi_axes.x() * std::sin(theta) * std::cos(phi),
                              semi_axes.y() * std::sin(theta) * std::sin(phi),
                              semi_axes.z() * std::cos(theta));
    }
  }
  const auto south = static_cast<std::int32_t>(m.vertices.size());
  m.vertices.emplace_back(0, 0, -semi_axes.z());
  const auto at = [&](int ring, int j) { return 1 + (ring - 1) * segments + (j % segments); };
  for (int j = 0; j < segments; ++j) m.triangles.push_back(Tri{0, at(1, j), at(1, j + 1)});
  for (int i = 1; i + 1 < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      m.triangles.push_back(Tri{at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back(Tri{at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  for (int j = 0; j < segments; ++j) {
    m.triangles.push_back(Tri{south, at(rings - 1, j + 1), at(rings - 1, j)});
  }
  return m;
}

/// A prism over the regular n-gon inscribed in a circle of radius r, length `length` along z,
/// centred (an inscribed approximation of a cylinder).
inline TriangleMesh cylinder_mesh(double r, double length, int n) {
  TriangleMesh m;
  const double pi = std::numbers::pi;
  m.vertices.emplace_back(0, 0, -length / 2);  // 0: bottom centre.
  m.vertices.emplace_back(0, 0, length / 2);   // 1: top centre.
  for (int j = 0; j < n; ++j) {
    const double phi = 2 * pi * j / n;
    m.vertices.emplace_back(r * std::cos(phi), r * std::sin(phi), -length / 2);  // 2 + 2j.
    m.vertices.emplace_back(r * std::cos(phi), r * std::sin(phi), length / 2);   // 3 + 2j.
  }
  const auto bottom = [&](int j) { return 2 + 2 * (j % n); };
  const auto top = [&](int j) { return 3 + 2 * (j % n); };
  for (int j = 0; j < n; ++j) {
    m.triangles.push_back(Tri{0, bottom(j + 1), bottom(j)});
    m.triangles.push_back(Tri{1, top(j), top(j + 1)});
    m.triangles.push_back(Tri{bottom(j), bottom(j + 1), top(j + 1)});
    m.triangles.push_back(Tri{bottom(j), top(j + 1), top(j)});
  }
  return m;
}

/// A pyramid over the regular n-gon inscribed in the base circle: apex at the origin, base at
/// z = height (an inscribed approximation of solid_cone).
inline TriangleMesh cone_mesh(double r, double height, int n) {
  TriangleMesh m;
  const double pi = std::numbers::pi;
  m.vertices.emplace_back(0, 0, 0);       // 0: apex.
  m.vertices.emplace_back(0, 0, height);  // 1: base centre.
  for (int j = 0; j < n; ++j) {
    const double phi = 2 * pi * j / n;
    m.vertices.emplace_back(r * std::cos(phi), r * std::sin(phi), height);
  }
  const auto ring = [&](int j) { return 2 + (j % n); };
  for (int j = 0; j < n; ++j) {
    m.triangles.push_back(Tri{1, ring(j), ring(j + 1)});
    m.triangles.push_back(Tri{0, ring(j + 1), ring(j)});
  }
  return m;
}

/// A torus about z: tube radius r around a centre circle of radius R, n × k quads.
inline TriangleMesh torus_mesh(double R, double r, int n, int k) {
  TriangleMesh m;
  const double pi = std::numbers::pi;
  for (int i = 0; i < n; ++i) {
    const double u = 2 * pi * i / n;
    for (int j = 0; j < k; ++j) {
      const double v = 2 * pi * j / k;
      const double rho = R + r * std::cos(v);
      m.vertices.emplace_back(rho * std::cos(u), rho * std::sin(u), r * std::sin(v));
    }
  }
  const auto at = [&](int i, int j) { return (i % n) * k + (j % k); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < k; ++j) {
      m.triangles.push_back(Tri{at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back(Tri{at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return m;
}

/// The mesh with every vertex moved to R p + offset.
inline TriangleMesh moved(TriangleMesh m, const Mat3& R, const Vec3& offset) {
  for (Vec3& p : m.vertices) p = R * p + offset;
  return m;
}

/// The mesh with every triangle's winding reversed (inside-out).
inline TriangleMesh flipped(TriangleMesh m) {
  for (auto& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

/// Each triangle with its own three vertices, as an STL file stores them.
inline TriangleMesh unwelded(const TriangleMesh& m) {
  TriangleMesh out;
  for (const auto& t : m.triangles) {
    const auto base = static_cast<std::int32_t>(out.vertices.size());
    for (int k = 0; k < 3; ++k) out.vertices.push_back(m.vertices[t[k]]);
    out.triangles.push_back(Tri{base, base + 1, base + 2});
  }
  return out;
}

}  // namespace momenta::test
