#include "momenta/inertia/triangle_mesh.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta::inertia {
namespace {

using Index = std::int32_t;

std::string describe_vertex(const TriangleMesh& mesh, Index v) {
  const Vec3& p = mesh.vertices[static_cast<std::size_t>(v)];
  return fmt::format("{} ({:.9g}, {:.9g}, {:.9g})", v, p.x(), p.y(), p.z());
}

// Throws unless every index of every triangle names a vertex.
void check_indices(const TriangleMesh& mesh) {
  const auto n = static_cast<std::uint64_t>(mesh.vertices.size());
  if (n > static_cast<std::uint64_t>(std::numeric_limits<Index>::max())) {
    throw MeshError(fmt::format("mesh has {} vertices, more than 32-bit indices address", n));
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (const Index v : mesh.triangles[t]) {
      if (v < 0 || static_cast<std::uint64_t>(v) >= n) {
        throw MeshError(
            fmt::format("triangle {} refers to vertex {}, outside the {} vertices", t, v, n));
      }
    }
  }
}

// Throws unless every vertex is finite.
void check_finite(const TriangleMesh& mesh, std::string_view name) {
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (!mesh.vertices[i].allFinite()) {
      const Vec3& p = mesh.vertices[i];
      throw MeshError(
          fmt::format("{}vertex {} ({}, {}, {}) is not finite", name, i, p.x(), p.y(), p.z()));
    }
  }
}

bool is_degenerate(const std::array<Index, 3>& t) {
  return t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
}

// Union–find over vertices with path halving; components of the triangle set.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), Index{0});
  }
  Index find(Index x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  void unite(Index a, Index b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<Index> parent_;
};

// 6 × signed volume of the tetrahedra from `origin` and their unsigned sum.
std::pair<double, double> six_volumes(const TriangleMesh& mesh, const Vec3& origin) {
  double signed_sum = 0.0;
  double abs_sum = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]] - origin;
    const Vec3 b = mesh.vertices[t[1]] - origin;
    const Vec3 c = mesh.vertices[t[2]] - origin;
    const double d = a.dot(b.cross(c));
    signed_sum += d;
    abs_sum += std::abs(d);
  }
  return {signed_sum, abs_sum};
}

}  // namespace

TriangleMesh weld_vertices(const TriangleMesh& mesh, double tolerance) {
  if (!std::isfinite(tolerance) || tolerance < 0.0) {
    throw InvalidArgument(
        fmt::format("weld_vertices: tolerance {} m is not non-negative and finite", tolerance));
  }
  check_indices(mesh);
  check_finite(mesh, "");
  TriangleMesh out;
  const std::size_t n = mesh.vertices.size();
  if (n == 0) return out;

  // Grid cells no smaller than the tolerance, so a vertex's partners lie in its own cell or the 26
  // around it; never so small that cell indices overflow (1e-12 of the extent).
  Vec3 lo = mesh.vertices.front();
  Vec3 hi = lo;
  for (const Vec3& p : mesh.vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double extent = (hi - lo).maxCoeff();
  double cell = std::max(tolerance, 1e-12 * extent);
  if (!(cell > 0.0)) cell = 1.0;  // All vertices coincide.
  const double inverse_cell = 1.0 / cell;
  const double tolerance2 = tolerance * tolerance;
  using Cell = std::array<std::int64_t, 3>;
  const auto cell_of = [&](const Vec3& p) {
    return Cell{static_cast<std::int64_t>(std::floor((p.x() - lo.x()) * inverse_cell)),
                static_cast<std::int64_t>(std::floor((p.y() - lo.y()) * inverse_cell)),
                static_cast<std::int64_t>(std::floor((p.z() - lo.z()) * inverse_cell))};
  };
  const auto hash = [](const Cell& c) {
    std::uint64_t h = static_cast<std::uint64_t>(c[0]) * 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 32)) + static_cast<std::uint64_t>(c[1]) * 0xC2B2AE3D27D4EB4Full;
    h = (h ^ (h >> 29)) + static_cast<std::uint64_t>(c[2]) * 0x165667B19E3779F9ull;
    return h ^ (h >> 32);
  };

  // Open addressing from cells to the first welded vertex of the cell's list (8-byte slots, the
  // cell itself recomputed from that vertex), grown at half load: small enough to stay in cache.
  struct Slot {
    std::uint32_t tag = 0;
    Index head = -1;
  };
  std::vector<Slot> slots(std::bit_ceil(std::max<std::size_t>(64, n / 4)));
  std::size_t used = 0;
  std::vector<Index> next;  // Next welded vertex in the same cell.
  const auto slot_of = [&](const Cell& c) -> Slot& {
    const std::uint64_t h = hash(c);
    const std::size_t mask = slots.size() - 1;
    const auto tag = static_cast<std::uint32_t>(h >> 32);
    for (std::size_t i = h & mask;; i = (i + 1) & mask) {
      Slot& s = slots[i];
      if (s.head < 0 || (s.tag == tag && cell_of(out.vertices[s.head]) == c)) return s;
    }
  };
  const auto grow = [&] {
    std::vector<Slot> old(slots.size() * 2);
    old.swap(slots);
    for (const Slot& s : old) {
      if (s.head < 0) continue;
      const Cell c = cell_of(out.vertices[s.head]);
      Slot& fresh = slot_of(c);
      fresh = Slot{static_cast<std::uint32_t>(hash(c) >> 32), s.head};
    }
  };
  const auto search = [&](Index head, const Vec3& p) {
    for (Index j = head; j >= 0; j = next[j]) {
      if ((out.vertices[j] - p).squaredNorm() <= tolerance2) return j;
    }
    return Index{-1};
  };

  std::vector<Index> remap(n);
  constexpr std::size_t kPrefetch = 16;  // Vertices ahead whose table slot is fetched early.
  for (std::size_t i = 0; i < n; ++i) {
    if (i + kPrefetch < n) {
      __builtin_prefetch(&slots[hash(cell_of(mesh.vertices[i + kPrefetch])) & (slots.size() - 1)]);
    }
    const Vec3& p = mesh.vertices[i];
    const Cell c = cell_of(p);
    // Its own cell first (exact duplicates always land there), then, with a tolerance, the rest.
    Index match = search(slot_of(c).head, p);
    for (int dx = -1; match < 0 && tolerance > 0.0 && dx <= 1; ++dx) {
      for (int dy = -1; match < 0 && dy <= 1; ++dy) {
        for (int dz = -1; match < 0 && dz <= 1; ++dz) {
          if (dx == 0 && dy == 0 && dz == 0) continue;
          match = search(slot_of(Cell{c[0] + dx, c[1] + dy, c[2] + dz}).head, p);
        }
      }
    }
    if (match < 0) {
      // A new welded vertex, at the head of its cell's list.
      match = static_cast<Index>(out.vertices.size());
      out.vertices.push_back(p);
      Slot& s = slot_of(c);
      if (s.head < 0) {
        s.tag = static_cast<std::uint32_t>(hash(c) >> 32);
        ++used;
      }
      next.push_back(s.head);
      s.head = match;
      if (2 * used > slots.size()) grow();
    }
    remap[i] = match;
  }

  // Remap the triangles, dropping those whose corners merged.
  out.triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const std::array<Index, 3> w{remap[t[0]], remap[t[1]], remap[t[2]]};
    if (!is_degenerate(w)) out.triangles.push_back(w);
  }
  return out;
}

MeshTopology analyze_topology(const TriangleMesh& mesh) {
  check_indices(mesh);
  MeshTopology topology;
  const std::size_t n = mesh.vertices.size();

  // Bucket every directed edge by its lower vertex (a counting sort, O(n)).
  struct EdgeUse {
    Index other;     // The higher vertex.
    Index triangle;  // The triangle using the edge.
    bool forward;    // Traversed from lower to higher vertex.
  };
  std::vector<Index> start(n + 1, 0);
  std::string degenerate_example;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    if (is_degenerate(tri)) {
      if (topology.degenerate_triangles++ == 0) {
        degenerate_example = fmt::format("degenerate triangle {} with vertices {}, {}, {}", t,
                                         tri[0], tri[1], tri[2]);
      }
      continue;
    }
    for (int k = 0; k < 3; ++k) ++start[std::min(tri[k], tri[(k + 1) % 3]) + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<EdgeUse> uses(static_cast<std::size_t>(start[n]));
  std::vector<Index> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    if (is_degenerate(tri)) continue;
    for (int k = 0; k < 3; ++k) {
      const Index a = tri[k];
      const Index b = tri[(k + 1) % 3];
      uses[fill[std::min(a, b)]++] = EdgeUse{std::max(a, b), static_cast<Index>(t), a < b};
    }
  }

  // Group each bucket by the higher vertex and classify the edge by its uses.
  std::string non_manifold_example, boundary_example, inconsistent_example;
  for (std::size_t v = 0; v < n; ++v) {
    const auto first = uses.begin() + start[v];
    const auto last = uses.begin() + start[v + 1];
    std::sort(first, last, [](const EdgeUse& a, const EdgeUse& b) {
      return a.other < b.other || (a.other == b.other && a.triangle < b.triangle);
    });
    for (auto group = first; group != last;) {
      auto end = group;
      int forward = 0;
      while (end != last && end->other == group->other) forward += (end++)->forward;
      const auto count = end - group;
      const auto edge = [&] {
        return fmt::format("edge between vertices {} and {}",
                           describe_vertex(mesh, static_cast<Index>(v)),
                           describe_vertex(mesh, group->other));
      };
      if (count == 1) {
        if (topology.boundary_edges++ == 0) {
          boundary_example = fmt::format("{} is used by triangle {} only", edge(), group->triangle);
        }
      } else if (count >= 3) {
        if (topology.non_manifold_edges++ == 0) {
          non_manifold_example = fmt::format("{} is shared by {} triangles ({}, {}, {}{})", edge(),
                                             count, group[0].triangle, group[1].triangle,
                                             group[2].triangle, count > 3 ? ", ..." : "");
        }
      } else if (forward != 1) {
        if (topology.inconsistent_edges++ == 0) {
          inconsistent_example =
              fmt::format("{} is traversed in the same direction by triangles {} and {}", edge(),
                          group[0].triangle, group[1].triangle);
        }
      }
      group = end;
    }
  }
  for (const std::string* e :
       {&non_manifold_example, &boundary_example, &inconsistent_example, &degenerate_example}) {
    if (!e->empty()) {
      topology.example = *e;
      break;
    }
  }

  // Components: vertices joined by triangles; count the roots of vertices that triangles use.
  DisjointSets sets(n);
  std::vector<bool> used(n, false);
  for (const auto& tri : mesh.triangles) {
    sets.unite(tri[0], tri[1]);
    sets.unite(tri[0], tri[2]);
    used[tri[0]] = used[tri[1]] = used[tri[2]] = true;
  }
  for (std::size_t v = 0; v < n; ++v) {
    if (used[v] && sets.find(static_cast<Index>(v)) == static_cast<Index>(v)) {
      ++topology.components;
    }
  }

  topology.signed_volume = six_volumes(mesh, bounding_box_centre(mesh)).first / 6.0;
  return topology;
}

bool prepare_solid_mesh(TriangleMesh& mesh, std::string_view name) {
  if (mesh.triangles.empty()) {
    throw MeshError(fmt::format("mesh '{}' has no triangles, so it bounds no solid", name));
  }
  check_indices(mesh);
  check_finite(mesh, fmt::format("mesh '{}': ", name));
  mesh = weld_vertices(mesh, 0.0);
  if (mesh.triangles.empty()) {
    throw MeshError(fmt::format(
        "mesh '{}' has only degenerate triangles (each repeats a vertex), so it bounds no solid",
        name));
  }

  // Topology: every edge shared by exactly two triangles, in opposite directions.
  const MeshTopology topology = analyze_topology(mesh);
  if (!topology.is_closed_manifold()) {
    std::string defects;
    const auto add = [&](std::size_t count, std::string_view what) {
      if (count == 0) return;
      if (!defects.empty()) defects += ", ";
      defects += fmt::format("{} {}", count, what);
    };
    add(topology.boundary_edges, "open boundary edges (holes: used by one triangle only)");
    add(topology.non_manifold_edges, "non-manifold edges (shared by three or more triangles)");
    add(topology.inconsistent_edges,
        "inconsistently oriented edges (neighbouring triangles wound in opposite senses)");
    throw MeshError(fmt::format(
        "mesh '{}' ({} vertices, {} triangles) does not bound a solid: {}; e.g. {}. Repair it "
        "(close holes, make the normals consistent) or treat it as a thin shell",
        name, mesh.vertices.size(), mesh.triangles.size(), defects, topology.example));
  }

  // Volume: reject a mesh that encloses none (all its tetrahedra cancel), flip an inside-out one.
  const auto [six_signed, six_unsigned] = six_volumes(mesh, bounding_box_centre(mesh));
  if (!(std::abs(six_signed) > 1e-12 * six_unsigned)) {
    throw MeshError(fmt::format(
        "mesh '{}' is closed but encloses no volume (signed volume {:.3g} m³ against {:.3g} m³ "
        "of tetrahedra that cancel): it is flat or degenerate",
        name, six_signed / 6.0, six_unsigned / 6.0));
  }
  if (six_signed > 0.0) return false;
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  return true;
}

Vec3 bounding_box_centre(const TriangleMesh& mesh) {
  if (mesh.vertices.empty()) return Vec3::Zero();
  Vec3 lo = mesh.vertices.front();
  Vec3 hi = lo;
  for (const Vec3& p : mesh.vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return 0.5 * (lo + hi);
}

}  // namespace momenta::inertia
