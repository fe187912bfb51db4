#include "mesh/mesh_assimp.hpp"

#include <array>
#include <cstdint>
#include <limits>
#include <utility>

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>
#include <assimp/Importer.hpp>

#include "momenta/common/error.hpp"

namespace momenta::io::detail {
namespace {

using inertia::TriangleMesh;

// Appends the triangles of every mesh under `node`, each vertex moved by the node's transform
// composed with its parents' (`parent`, row-major 4×4 as assimp stores it).
void collect(const aiScene& scene, const aiNode& node, const Eigen::Matrix4d& parent,
             const Vec3& scale, TriangleMesh& out, std::size_t& skipped) {
  const aiMatrix4x4& t = node.mTransformation;
  Eigen::Matrix4d local;
  local << t.a1, t.a2, t.a3, t.a4, t.b1, t.b2, t.b3, t.b4, t.c1, t.c2, t.c3, t.c4, t.d1, t.d2, t.d3,
      t.d4;
  const Eigen::Matrix4d world = parent * local;
  const Mat3 linear = scale.asDiagonal() * world.topLeftCorner<3, 3>();
  const Vec3 offset = scale.cwiseProduct(world.topRightCorner<3, 1>());
  // A mirroring transform turns an outward mesh inside out: swap the winding back.
  const bool mirrored = linear.determinant() < 0;
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const auto base = static_cast<std::int64_t>(out.vertices.size());
    if (base + mesh.mNumVertices > std::numeric_limits<std::int32_t>::max()) {
      throw MeshError(fmt::format("mesh has more than {} vertices, beyond 32-bit indices",
                                  std::numeric_limits<std::int32_t>::max()));
    }
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& p = mesh.mVertices[v];
      out.vertices.push_back(linear * Vec3(p.x, p.y, p.z) + offset);
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) {  // Points and lines: no area, no volume.
        ++skipped;
        continue;
      }
      std::array<std::int32_t, 3> tri;
      for (int k = 0; k < 3; ++k) {
        if (face.mIndices[k] >= mesh.mNumVertices) {
          throw MeshError(fmt::format("face {} of mesh {} refers to vertex {} of {}", f, m,
                                      face.mIndices[k], mesh.mNumVertices));
        }
        tri[k] = static_cast<std::int32_t>(base + face.mIndices[k]);
      }
      if (mirrored) std::swap(tri[1], tri[2]);
      out.triangles.push_back(tri);
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    collect(scene, *node.mChildren[c], world, scale, out, skipped);
  }
}

}  // namespace

TriangleMesh read_with_assimp(const std::string& name, std::string_view format, const Vec3& scale,
                              std::size_t& skipped) {
  TriangleMesh soup;
  Assimp::Importer importer;
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const aiScene* scene = importer.ReadFile(name, aiProcess_Triangulate);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    throw ParseError(name, 0, 0,
                     fmt::format("cannot read the {} file: {}", format, importer.GetErrorString()));
  }
  // Merge every mesh of the scene, in world coordinates (node transforms applied), scaled.
  std::size_t vertices = 0, faces = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    vertices += scene->mMeshes[m]->mNumVertices;
    faces += scene->mMeshes[m]->mNumFaces;
  }
  soup.vertices.reserve(vertices);
  soup.triangles.reserve(faces);
  collect(*scene, *scene->mRootNode, Eigen::Matrix4d::Identity(), scale, soup, skipped);
  return soup;
}

}  // namespace momenta::io::detail
