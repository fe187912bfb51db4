#include "momenta/inertia/mesh_mass_properties.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta::inertia {
namespace {

using Index = std::int32_t;

// The ten integrals of 1, x, y, z, x², y², z², xy, yz, zx over a body, relative to a reference
// point, each times a constant factor that mass_properties_from() removes.
struct Monomials {
  double volume = 0;              // Σ d            (6 V for solids, 2 A for shells)
  double x = 0, y = 0, z = 0;     // Σ d s
  double xx = 0, yy = 0, zz = 0;  // Σ d (aₓ² + bₓ² + cₓ² + sₓ²)
  double xy = 0, yz = 0, zx = 0;  // Σ d (aₓa_y + bₓb_y + cₓc_y + sₓs_y)
  Monomials& operator+=(const Monomials& o) {
    volume += o.volume;
    x += o.x, y += o.y, z += o.z;
    xx += o.xx, yy += o.yy, zz += o.zz;
    xy += o.xy, yz += o.yz, zx += o.zx;
    return *this;
  }
};

// Triangles per block: gathered into structure-of-arrays form so the arithmetic vectorizes
// across triangles, and summed per block before joining the totals (shorter summation chains).
constexpr int kLanes = 8;
constexpr std::size_t kBlock = 1024;

// Loads the corners of triangles [t, t + count) relative to `origin` into lanes, zero-filling
// unused lanes (a zero triangle adds nothing). Returns false if an index is out of range.
struct Lanes {
  alignas(64) double ax[kLanes], ay[kLanes], az[kLanes];
  alignas(64) double bx[kLanes], by[kLanes], bz[kLanes];
  alignas(64) double cx[kLanes], cy[kLanes], cz[kLanes];
};

inline bool gather(const TriangleMesh& mesh, std::size_t t, int count, const Vec3& origin,
                   Lanes& l) {
  const auto n = static_cast<std::uint32_t>(mesh.vertices.size());
  const Vec3* v = mesh.vertices.data();
  const auto* tri = mesh.triangles.data() + t;
  bool ok = true;
  if (count == kLanes) {
    // Full group: no tail handling, indices checked together.
    std::uint32_t bad = 0;
    for (int k = 0; k < kLanes; ++k) {
      const auto i0 = static_cast<std::uint32_t>(tri[k][0]);
      const auto i1 = static_cast<std::uint32_t>(tri[k][1]);
      const auto i2 = static_cast<std::uint32_t>(tri[k][2]);
      bad |= static_cast<std::uint32_t>(i0 >= n) | (i1 >= n) | (i2 >= n);
    }
    if (bad != 0) return false;
    for (int k = 0; k < kLanes; ++k) {
      const Vec3& a = v[tri[k][0]];
      const Vec3& b = v[tri[k][1]];
      const Vec3& c = v[tri[k][2]];
      l.ax[k] = a.x() - origin.x(), l.ay[k] = a.y() - origin.y(), l.az[k] = a.z() - origin.z();
      l.bx[k] = b.x() - origin.x(), l.by[k] = b.y() - origin.y(), l.bz[k] = b.z() - origin.z();
      l.cx[k] = c.x() - origin.x(), l.cy[k] = c.y() - origin.y(), l.cz[k] = c.z() - origin.z();
    }
    return true;
  }
  for (int k = 0; k < kLanes; ++k) {
    if (k >= count) {
      l.ax[k] = l.ay[k] = l.az[k] = l.bx[k] = l.by[k] = l.bz[k] = l.cx[k] = l.cy[k] = l.cz[k] = 0;
      continue;
    }
    const auto i0 = static_cast<std::uint32_t>(tri[k][0]);
    const auto i1 = static_cast<std::uint32_t>(tri[k][1]);
    const auto i2 = static_cast<std::uint32_t>(tri[k][2]);
    if ((i0 >= n) | (i1 >= n) | (i2 >= n)) {
      ok = false;
      l.ax[k] = l.ay[k] = l.az[k] = l.bx[k] = l.by[k] = l.bz[k] = l.cx[k] = l.cy[k] = l.cz[k] = 0;
      continue;
    }
    const Vec3& a = v[i0];
    const Vec3& b = v[i1];
    const Vec3& c = v[i2];
    l.ax[k] = a.x() - origin.x(), l.ay[k] = a.y() - origin.y(), l.az[k] = a.z() - origin.z();
    l.bx[k] = b.x() - origin.x(), l.by[k] = b.y() - origin.y(), l.bz[k] = b.z() - origin.z();
    l.cx[k] = c.x() - origin.x(), l.cy[k] = c.y() - origin.y(), l.cz[k] = c.z() - origin.z();
  }
  return ok;
}

[[noreturn]] void throw_bad_index(const TriangleMesh& mesh, std::size_t first, std::size_t last) {
  for (std::size_t t = first; t < last; ++t) {
    for (const Index v : mesh.triangles[t]) {
      if (v < 0 || static_cast<std::size_t>(v) >= mesh.vertices.size()) {
        throw MeshError(fmt::format("triangle {} refers to vertex {}, outside the {} vertices", t,
                                    v, mesh.vertices.size()));
      }
    }
  }
  throw MeshError("a triangle refers to a vertex outside the mesh");
}

// The monomial sums of the signed tetrahedra (origin, a, b, c) of every triangle, about `origin`
// (Kallay 2006; Tonon 2004 eq. 2): for a tetrahedron with one vertex at the origin,
//   ∫ dV = d/6,  ∫ xᵢ dV = d sᵢ/24,  ∫ xᵢxⱼ dV = d (aᵢaⱼ + bᵢbⱼ + cᵢcⱼ + sᵢsⱼ)/120,
// with d = a·(b × c) and s = a + b + c. About 90 flops per triangle; no allocation.
Monomials solid_monomials(const TriangleMesh& mesh, const Vec3& origin) {
  Monomials total;
  const std::size_t count = mesh.triangles.size();
  Lanes l;
  for (std::size_t block = 0; block < count; block += kBlock) {
    const std::size_t block_end = std::min(count, block + kBlock);
    // Per-lane partial sums: independent chains the compiler keeps in vector registers.
    double v6[kLanes] = {}, sx[kLanes] = {}, sy[kLanes] = {}, sz[kLanes] = {};
    double sxx[kLanes] = {}, syy[kLanes] = {}, szz[kLanes] = {};
    double sxy[kLanes] = {}, syz[kLanes] = {}, szx[kLanes] = {};
    for (std::size_t t = block; t < block_end; t += kLanes) {
      const int lanes = static_cast<int>(std::min<std::size_t>(kLanes, block_end - t));
      if (!gather(mesh, t, lanes, origin, l)) throw_bad_index(mesh, t, t + lanes);
      for (int k = 0; k < kLanes; ++k) {
        const double ax = l.ax[k], ay = l.ay[k], az = l.az[k];
        const double bx = l.bx[k], by = l.by[k], bz = l.bz[k];
        const double cx = l.cx[k], cy = l.cy[k], cz = l.cz[k];
        // d = a · (b × c): six times the signed volume.
        const double d =
            ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
        const double x = ax + bx + cx, y = ay + by + cy, z = az + bz + cz;
        v6[k] += d;
        sx[k] += d * x;
        sy[k] += d * y;
        sz[k] += d * z;
        sxx[k] += d * (ax * ax + bx * bx + cx * cx + x * x);
        syy[k] += d * (ay * ay + by * by + cy * cy + y * y);
        szz[k] += d * (az * az + bz * bz + cz * cz + z * z);
        sxy[k] += d * (ax * ay + bx * by + cx * cy + x * y);
        syz[k] += d * (ay * az + by * bz + cy * cz + y * z);
        szx[k] += d * (az * ax + bz * bx + cz * cx + z * x);
      }
    }
    Monomials part;
    for (int k = 0; k < kLanes; ++k) {
      part.volume += v6[k];
      part.x += sx[k], part.y += sy[k], part.z += sz[k];
      part.xx += sxx[k], part.yy += syy[k], part.zz += szz[k];
      part.xy += sxy[k], part.yz += syz[k], part.zx += szx[k];
    }
    total += part;
  }
  return total;
}

// The same sums for triangles as thin sheets (Mirtich 1996, surface integrals): for a triangle
// of area A, ∫ dA = A, ∫ xᵢ dA = A sᵢ/3, ∫ xᵢxⱼ dA = A (aᵢaⱼ + bᵢbⱼ + cᵢcⱼ + sᵢsⱼ)/12. Here d = 2A.
Monomials shell_monomials(const TriangleMesh& mesh, const Vec3& origin) {
  Monomials total;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (const Index v : tri) {
      if (v < 0 || static_cast<std::size_t>(v) >= mesh.vertices.size()) {
        throw_bad_index(mesh, t, t + 1);
      }
    }
    const Vec3 a = mesh.vertices[tri[0]] - origin;
    const Vec3 b = mesh.vertices[tri[1]] - origin;
    const Vec3 c = mesh.vertices[tri[2]] - origin;
    const double d = (b - a).cross(c - a).norm();
    const Vec3 s = a + b + c;
    total.volume += d;
    total.x += d * s.x(), total.y += d * s.y(), total.z += d * s.z();
    total.xx += d * (a.x() * a.x() + b.x() * b.x() + c.x() * c.x() + s.x() * s.x());
    total.yy += d * (a.y() * a.y() + b.y() * b.y() + c.y() * c.y() + s.y() * s.y());
    total.zz += d * (a.z() * a.z() + b.z() * b.z() + c.z() * c.z() + s.z() * s.z());
    total.xy += d * (a.x() * a.y() + b.x() * b.y() + c.x() * c.y() + s.x() * s.y());
    total.yz += d * (a.y() * a.z() + b.y() * b.z() + c.y() * c.z() + s.y() * s.z());
    total.zx += d * (a.z() * a.x() + b.z() * b.x() + c.z() * c.x() + s.z() * s.x());
  }
  return total;
}

// Mass properties from the monomial sums: `measure_factor`, `first_factor`, `second_factor` turn
// the sums into ∫ dμ, ∫ x dμ, ∫ x x dμ (μ volume or area).
MassProperties mass_properties_from(const Monomials& s, const Vec3& origin, double measure,
                                    double first_factor, double second_factor, double mass,
                                    double recorded_volume) {
  const double density = mass / measure;
  const Vec3 first = first_factor * Vec3(s.x, s.y, s.z);
  const Vec3 c = first / measure;  // Centre of mass from the reference point.
  // Inertia about the reference point: moments ∫(y² + z²) dm, minus products −∫xy dm.
  const double xx = second_factor * s.xx, yy = second_factor * s.yy, zz = second_factor * s.zz;
  const double xy = second_factor * s.xy, yz = second_factor * s.yz, zx = second_factor * s.zx;
  Mat3 I_BO_B;
  I_BO_B << yy + zz, -xy, -zx, -xy, xx + zz, -yz, -zx, -yz, xx + yy;
  I_BO_B *= density;
  // Shift to the centre of mass; the reference point lies inside the bounding box, so the
  // parallel-axis term never dwarfs the result.
  Mat3 I_BBcm_B = I_BO_B - point_mass_inertia(mass, c);
  I_BBcm_B = 0.5 * (I_BBcm_B + I_BBcm_B.transpose());
  return MassProperties(mass, origin + c, I_BBcm_B, recorded_volume);
}

}  // namespace

MassProperties solid_mesh_mass_properties(const TriangleMesh& mesh, Amount amount) {
  // A reference point near the mesh: coordinates relative to it are no larger than the mesh, so a
  // mesh far from the origin loses no digits to cancellation.
  const Vec3 origin = bounding_box_centre(mesh);
  const Monomials s = solid_monomials(mesh, origin);
  const double volume = s.volume / 6.0;
  if (!std::isfinite(volume) || !(volume > 0.0)) {
    throw MeshError(fmt::format(
        "a mesh of {} triangles encloses a volume of {:.6g} m³, not a positive one: it must be "
        "closed, outward-facing and finite (call prepare_solid_mesh first)",
        mesh.triangles.size(), volume));
  }
  const double mass = amount.mass_for(volume, "solid mesh");
  return mass_properties_from(s, origin, volume, 1.0 / 24.0, 1.0 / 120.0, mass, volume);
}

MassProperties shell_mesh_mass_properties(const TriangleMesh& mesh, Amount amount) {
  const Vec3 origin = bounding_box_centre(mesh);
  const Monomials s = shell_monomials(mesh, origin);
  const double area = s.volume / 2.0;
  if (!std::isfinite(area) || !(area > 0.0)) {
    throw MeshError(fmt::format(
        "a shell mesh of {} triangles has an area of {:.6g} m², not a positive finite one",
        mesh.triangles.size(), area));
  }
  const double mass = amount.mass_for(area, "shell mesh");
  return mass_properties_from(s, origin, area, 1.0 / 6.0, 1.0 / 24.0, mass, 0.0);
}

}  // namespace momenta::inertia
