#pragma once
// MJCF models (MuJoCo's XML format; mujoco.readthedocs.io, "XML Reference") read as momenta
// models, so that every command and the Python module take `robot.xml` wherever they take a
// model file (format and mapping: docs/model-formats.md).
//
// What is read: <compiler> angle, eulerseq, inertiafromgeom; <option> gravity (and its
// <flag gravity="disable">); <default> classes, nested, with `class` and `childclass`; the
// <worldbody> tree — a body's pos and orientation (quat, axisangle, euler, xyaxes, zaxis), its
// <inertial> (mass, diaginertia or fullinertia, placed by its frame) or, MuJoCo's rule, its geoms'
// mass properties (sphere, capsule, cylinder, ellipsoid, box; size or fromto; density, default
// 1000 kg/m³, or mass), its joints (hinge → revolute, slide → prismatic, ball → spherical, free
// and <freejoint> → free; several in one body become a chain of massless bodies, as MuJoCo
// composes them) with stiffness and springref (a torsional spring), damping; <tendon><fixed> (a
// FixedTendon force element and an output of its length); <equality> connect and weld (loop
// closures fixed at the configuration the file draws), joint and tendon (couplers);
// <actuator> motor and plain general on a hinge or slide (a torque or force pair scaled by an
// input signal named after the actuator, default 0). Angles follow <compiler angle> (degrees
// unless it says radian). A joint's coordinate counts from the configuration the file draws
// (MuJoCo's qpos − ref). What momenta does not use — contacts, limits, spatial tendons, sensors,
// sites, cameras, lights, assets, keyframes, other actuators — is listed in ModelFile::notes, each
// with its line.

#include <filesystem>
#include <string>

#include "momenta/io/model_file.hpp"

namespace momenta::io {

/// True when `path` names an MJCF file (extension .xml or .mjcf, any case).
bool is_mjcf_path(const std::filesystem::path& path);

/// Reads an MJCF file. Throws FileError when it cannot be read; ParseError `file:line:column:
/// message` for malformed XML, a root other than <mujoco>, an unknown element or attribute (with
/// a did-you-mean), a number that is not finite or a list of the wrong length, an unknown class,
/// body, joint or mesh name, a mesh file that cannot be read (relative to <compiler meshdir> or
/// assetdir, each relative to the file's folder) or that bounds no solid where its body's mass
/// is wanted, a body whose mass cannot be found (a plane, height field or sdf geom), an
/// inertia no mass distribution has, what MuJoCo itself refuses (a free joint below the top
/// level, two orientations on one element), a compiler setting that would change the masses, or a
/// problem the model builder finds (at the line of the body or joint it names).
ModelFile read_mjcf_file(const std::filesystem::path& path);

/// The same from text (`file_name` names it in messages; mesh files are found from `base_dir`).
ModelFile parse_mjcf(const std::string& text, const std::string& file_name,
                     const std::filesystem::path& base_dir = {});

}  // namespace momenta::io
