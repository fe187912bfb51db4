#include "momenta/io/mesh_file.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

#include <fmt/format.h>

#include "mesh/mesh_assimp.hpp"
#include "mesh/mesh_text_formats.hpp"
#include "momenta/common/error.hpp"
#include "momenta/io/files_read.hpp"

namespace momenta::io {
namespace {

namespace fs = std::filesystem;
using inertia::TriangleMesh;

enum class Format { kBinaryStl, kAsciiStl, kObj, kCollada };

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// A uniform scale as its one number, a per-axis one as three.
std::string scale_text(const Vec3& scale) {
  return scale.x() == scale.y() && scale.y() == scale.z()
             ? fmt::format("{}", scale.x())
             : fmt::format("({}, {}, {})", scale.x(), scale.y(), scale.z());
}

InvalidArgument scale_out_of_range(const fs::path& path, const Vec3& scale) {
  return InvalidArgument(fmt::format(
      "{}: unit scale {} is outside 1e-9 … 1e9 metres per unit of the file (0.001 reads "
      "millimetres)",
      path.string(), scale_text(scale)));
}

// Reads up to `count` bytes from `offset` (fewer at the end of the file).
std::string read_bytes(const fs::path& path, std::uintmax_t offset, std::size_t count) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(fmt::format("{}: cannot open the file for reading", path.string()));
  in.seekg(static_cast<std::streamoff>(offset));
  std::string bytes(count, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(count));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  return bytes;
}

// Tells binary from ASCII STL as assimp does (a binary file's size is exactly 84 + 50 n bytes for
// the n triangles its header declares; many binary files also begin with "solid"), and rejects a
// binary file whose size disagrees with its triangle count — assimp itself would read a file too
// long silently.
Format classify_stl(const fs::path& path, std::uintmax_t size) {
  const std::string head = read_bytes(path, 0, 512);
  std::uint64_t declared = 0;
  if (size >= 84) {
    std::uint32_t n = 0;
    std::memcpy(&n, head.data() + 80, 4);  // Little-endian, as the format specifies.
    declared = n;
    if (84 + 50 * declared == size) return Format::kBinaryStl;
  }
  // ASCII: "solid" after optional white space, and text (no NUL, nothing above 127) thereafter.
  const auto start = head.find_first_not_of(" \t\r\n");
  const bool solid = start != std::string::npos && head.compare(start, 5, "solid") == 0;
  const bool text = std::none_of(head.begin(), head.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u == 0 || u > 127;
  });
  if (solid && text) {
    // A truncated ASCII file loses its closing "endsolid"; assimp would keep what it read.
    const std::uintmax_t tail_size = std::min<std::uintmax_t>(size, 1024);
    if (read_bytes(path, size - tail_size, tail_size).find("endsolid") == std::string::npos) {
      throw ParseError(path.string(), 0, 0,
                       "ASCII STL file does not end with 'endsolid': it is truncated");
    }
    return Format::kAsciiStl;
  }
  if (size < 84) {
    throw ParseError(path.string(), 0, 0,
                     fmt::format("file of {} bytes is neither ASCII STL (it does not begin with "
                                 "'solid') nor binary STL (shorter than the 84-byte header)",
                                 size));
  }
  throw ParseError(
      path.string(), 0, 0,
      fmt::format("binary STL header declares {} triangles, which take 84 + 50 × {} = {} bytes, "
                  "but the file has {} bytes ({}); the file is truncated or corrupt",
                  declared, declared, 84 + 50 * declared, size,
                  size < 84 + 50 * declared ? "too short" : "too long"));
}

}  // namespace

inertia::TriangleMesh read_mesh_file(const std::filesystem::path& path, double scale) {
  if (!(scale > 0.0)) throw scale_out_of_range(path, Vec3::Constant(scale));  // no mirroring
  return read_mesh_file(path, Vec3::Constant(scale));
}

inertia::TriangleMesh read_mesh_file(const std::filesystem::path& path, const Vec3& scale) {
  const std::string name = path.string();
  // From a nanometre to a million kilometres a unit: beyond, a triangle's area (scale²) and the
  // solid's volume (scale³) leave double precision, and the mesh would read as empty.
  const Vec3 magnitude = scale.cwiseAbs();
  if (!scale.allFinite() || !(magnitude.minCoeff() >= 1e-9) || !(magnitude.maxCoeff() <= 1e9)) {
    throw scale_out_of_range(path, scale);
  }

  // The file itself: present, a regular file, not empty, of a supported kind.
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status)) throw FileError(fmt::format("{}: mesh file not found", name));
  if (!fs::is_regular_file(status)) {
    throw FileError(fmt::format("{}: not a regular file", name));
  }
  const std::uintmax_t size = fs::file_size(path, error);
  if (error) throw FileError(fmt::format("{}: cannot read its size: {}", name, error.message()));
  note_file_read(path);
  if (size == 0) throw FileError(fmt::format("{}: mesh file is empty", name));
  const std::string extension = lower(path.extension().string());
  Format format;
  if (extension == ".stl") {
    format = classify_stl(path, size);
  } else if (extension == ".obj") {
    format = Format::kObj;
  } else if (extension == ".dae") {
    format = Format::kCollada;
  } else {
    throw ParseError(
        name, 0, 0,
        fmt::format("unsupported mesh file extension '{}': expected .stl, .obj or .dae",
                    path.extension().string()));
  }

  // Text formats by their own grammars, in double precision; binary STL (single precision by the
  // format itself) and COLLADA through assimp, with triangulation only: no vertex joining, normal
  // generation, degenerate removal or any other step that would change the geometry behind our
  // back. COLLADA's <unit meter> is applied; its <up_axis> is not (assimp would turn a Z_UP file
  // to y up): robot descriptions place a mesh by the coordinates it is written in, as ROS does.
  TriangleMesh soup;
  std::size_t skipped = 0;
  if (format == Format::kObj || format == Format::kAsciiStl) {
    const std::string text = read_bytes(path, 0, static_cast<std::size_t>(size));
    soup = format == Format::kObj ? detail::parse_obj(text, name, skipped)
                                  : detail::parse_ascii_stl(text, name);
    for (Vec3& p : soup.vertices) p = p.cwiseProduct(scale);
    // A mirroring scale turns an outward mesh inside out: swap the winding back.
    if (scale.prod() < 0.0) {
      for (auto& t : soup.triangles) std::swap(t[1], t[2]);
    }
  } else {
    soup = detail::read_with_assimp(name, format == Format::kCollada ? "COLLADA" : "STL", scale,
                                    skipped);
  }
  if (soup.triangles.empty()) {
    throw ParseError(name, 0, 0,
                     skipped > 0
                         ? fmt::format("file holds {} points or lines but no triangles", skipped)
                         : std::string("file holds no triangles"));
  }
  // Coordinates that overflow once scaled (or a binary STL's NaN): named with the file.
  for (std::size_t v = 0; v < soup.vertices.size(); ++v) {
    const Vec3& p = soup.vertices[v];
    if (!p.allFinite()) {
      throw ParseError(
          name, 0, 0,
          fmt::format(
              "vertex {} ({}, {}, {}) is not finite{}", v, p.x(), p.y(), p.z(),
              scale != Vec3::Ones() ? fmt::format(" (scaled by {})", scale_text(scale)) : ""));
    }
  }

  // Weld exact repeats (STL stores each triangle's corners apart) so the topology can be checked.
  return inertia::weld_vertices(soup, 0.0);
}

}  // namespace momenta::io
