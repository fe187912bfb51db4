#pragma once
// URDF robot descriptions (the Unified Robot Description Format of ROS; wiki.ros.org/urdf/XML) read
// as momenta models, so that every command and the Python module take `robot.urdf` wherever they
// take a model file (format and mapping: docs/model-formats.md).
//
// Links become bodies (mass, centre of mass and inertia from <inertial>, its <origin> placing the
// inertia frame in the link's), joints become joints of the same kind (revolute and continuous →
// revolute, prismatic, fixed, floating → free, planar → planar about the axis), their <origin>
// placing the joint frame in the parent link's and the child link's frame at the joint frame;
// <dynamics damping> is the joint's viscous damping and <mimic> a coupler q = multiplier ·
// q_mimicked
// + offset. URDF's <inertia> gives the tensor's entries (ixy = −∫xy dm), as momenta's does.
// The root link is welded to the world, unless it is named "world" (then it is the world). What
// momenta does not use — limits, effort and velocity, friction, calibration, safety controllers,
// materials, transmissions, gazebo extensions — is listed in ModelFile::notes, each with its line,
// not silently dropped. A link's <visual> geometry (box, cylinder, sphere, mesh: STL, OBJ, DAE) is
// what the report draws (its <collision> geometry where it has no visual); a link without
// <inertial> takes its mass properties from its geometry when ModelFileOptions::link_density is
// given.

#include <filesystem>
#include <string>

#include "momenta/io/model_file.hpp"

namespace momenta::io {

/// True when `path` names a URDF file (extension .urdf, any case).
bool is_urdf_path(const std::filesystem::path& path);

/// Reads a URDF file. Mesh file names are `package://NAME/path` (NAME found on
/// options.package_path, then ROS_PACKAGE_PATH), `file:///absolute/path`, or paths relative to
/// the URDF's folder. Throws FileError when it or a mesh cannot be read; ParseError
/// `file:line: message` for malformed XML, a missing or unknown element, attribute or name (with
/// a did-you-mean), a number that is not finite or out of range, a link that is the child of two
/// joints, more than one root, an inertia no mass distribution has, a package that is not found
/// (naming the folders searched), a mesh that cannot be read or — where its mass is wanted — does
/// not bound a solid, or a problem the model builder finds (at the line of the link or joint it
/// names; a massless link that needs a mass with the hint to give an <inertial> or a
/// link_density).
ModelFile read_urdf_file(const std::filesystem::path& path, const ModelFileOptions& options = {});

/// The same from text (`file_name` names it in messages; relative mesh paths are taken from
/// `base_dir`).
ModelFile parse_urdf(const std::string& text, const std::string& file_name,
                     const ModelFileOptions& options = {},
                     const std::filesystem::path& base_dir = {});

}  // namespace momenta::io
