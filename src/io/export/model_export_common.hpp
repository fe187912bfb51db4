#pragma once
// What the two model writers share (model_export_mjcf.cpp, model_export_urdf.cpp): numbers,
// vectors and rotations as they print them — the shortest text that reads back to the same
// double, −0 as 0 — the tree's joints by parent, a joint's viscous damping, and the loads, stops'
// restitution and mesh parts neither format keeps.

#include <string>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "momenta/io/model_file.hpp"
#include "momenta/math/spatial.hpp"
#include "momenta/model/model.hpp"

namespace momenta::io::detail {

inline std::string number_text(double x) { return fmt::format("{}", x == 0.0 ? 0.0 : x); }

inline std::string vector_text(const Vec3& v) {
  return fmt::format("{} {} {}", number_text(v.x()), number_text(v.y()), number_text(v.z()));
}

/// w x y z, w ≥ 0.
inline std::string quaternion_text(const Mat3& R) {
  Quat q(R);
  q.normalize();
  if (q.w() < 0.0) q.coeffs() *= -1.0;
  return fmt::format("{} {} {} {}", number_text(q.w()), number_text(q.x()), number_text(q.y()),
                     number_text(q.z()));
}

/// The joints out of each body, in the model's joint order: children[b] lists joint indices.
inline std::vector<std::vector<int>> joints_out_of(const model::Model& model) {
  std::vector<std::vector<int>> children(static_cast<std::size_t>(model.num_bodies()));
  for (const model::Joint& joint : model.joints()) {
    children[static_cast<std::size_t>(joint.parent_index)].push_back(joint.index);
  }
  return children;
}

/// A joint's viscous damping: its own plus every joint-friction element's on it (N·m·s/rad or
/// N·s/m).
double joint_viscous_damping(const model::Model& model, int joint);

/// What neither format writes: applied loads and springs between bodies, prescribed motions
/// (and, for "URDF", torsional springs).
std::vector<std::string> loads_not_written(const model::Model& model, std::string_view format);

/// The restitution of stops that are not plastic, one line a joint: neither format keeps it (its
/// limits are read back as plastic stops); `why` says so in the format's terms.
std::vector<std::string> restitution_not_written(const model::Model& model, std::string_view why);

/// The mesh parts neither writer draws (their mass is in the body's inertial), one line a body.
std::vector<std::string> meshes_not_written(const ModelFile& file);

}  // namespace momenta::io::detail
