#pragma once
// The MuJoCo geoms a model's contacts with ground planes are written as (model_export_mjcf.cpp):
// the shapes momenta's MJCF reader poses as those same contacts (io/mjcf/mjcf_contacts.cpp) —
// a sphere as itself, a cylinder as the rims of its two faces, a box as its eight corners. So a
// sphere's contact is one geom; two disks' rims on one body, coaxial, of one radius, one friction
// and on one plane, a cylinder; eight points on one body that are a box's corners, a box. A point
// alone, a disk alone and a contact with another body have no MuJoCo geom: they are not written.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "momenta/math/spatial.hpp"
#include "momenta/model/model.hpp"

namespace momenta::io::detail {

/// One geom standing for one or more contacts.
struct MjcfContactGeom {
  std::string name;
  std::string type;  ///< "sphere", "cylinder" or "box"
  Vec3 size;         ///< MuJoCo's: the radius; the radius and half length; the half lengths
  int body = 0;
  Transform X_BG;     ///< the geom's frame in its body's
  std::size_t plane;  ///< its ground plane, an index into MjcfContactGeoms::planes
  double friction = 0.0;
  std::vector<std::size_t> contacts;  ///< the constraints' indices it stands for
};

struct MjcfContactGeoms {
  std::vector<MjcfContactGeom> geoms;
  /// The distinct ground planes of the geoms, as (unit normal, point), in first use.
  std::vector<std::pair<Vec3, Vec3>> planes;
};

/// The geoms of `model`'s contacts with ground planes, in the order of their first contacts;
/// `taken` are names the file already uses for geoms (a geom standing for several contacts is
/// named after what their names share, and made unique).
MjcfContactGeoms mjcf_contact_geoms(const model::Model& model, std::vector<std::string> taken);

}  // namespace momenta::io::detail
