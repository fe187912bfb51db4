#include <fmt/format.h>

#include "mesh/mesh_assimp.hpp"
#include "momenta/common/error.hpp"

namespace momenta::io::detail {

// The build without assimp (the report's in-page engine, wasm/): the formats only assimp reads
// are refused by name, with what to use instead.
inertia::TriangleMesh read_with_assimp(const std::string& name, std::string_view format,
                                       const Vec3&, std::size_t&) {
  throw ParseError(name, 0, 0,
                   fmt::format("a {} file is read through assimp, which the report's in-page "
                               "engine is built without; give the mesh as OBJ or ASCII STL, or "
                               "run the model with the momenta command",
                               format == "STL" ? "binary STL" : std::string(format)));
}

}  // namespace momenta::io::detail
