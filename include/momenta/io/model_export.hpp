#pragma once
// A momenta model written out as MJCF (MuJoCo) or URDF (ROS), so that a model made here can be
// taken to MuJoCo, Pinocchio or ROS (`momenta export`; docs/model-formats.md, "Writing models").
//
// Both writers keep the bodies' mass properties and frames exactly (numbers in their shortest
// form that reads back to the same double) and draw the mechanism in a given configuration,
// normally the model's consistent initial state. MJCF keeps more: every joint type (a planar,
// universal or cylindrical joint as the chain of hinges and slides MuJoCo composes), joint
// damping and torsional springs, point and hinge loop closures (connect: a hinge as two points on
// its axis), welds (with their relative pose), couplers (an equality of joints), gravity and the
// initial velocities (a keyframe). URDF keeps trees of revolute, prismatic, fixed, floating and
// planar joints, damping and couplers (mimic). What a format cannot say is either refused — what
// would change the mechanism: a loop URDF cannot close, a ball joint in URDF, a rolling contact —
// or, for loads, listed in ExportedModel::not_written.

#include <string>
#include <vector>

#include "momenta/io/model_file.hpp"
#include "momenta/math/types.hpp"

namespace momenta::io {

struct ExportedModel {
  std::string text;                      ///< the XML document
  std::vector<std::string> not_written;  ///< what the model has that the format does not keep
};

/// The model as MJCF (MuJoCo 2.2's XML), drawn at `q_drawn` (size nq; the model's consistent
/// initial state for `momenta export`): each body where q_drawn puts it, each hinge's and slide's
/// `ref` its drawn coordinate, so that MuJoCo's qpos is momenta's q for them. Throws
/// InvalidArgument naming what MJCF cannot keep: a free joint that is not on a body of the world
/// or whose child frame is offset from the body's, a slider loop, a distance link, a rolling
/// contact or a knife edge; and for q_drawn of the wrong size or not finite.
ExportedModel write_mjcf(const ModelFile& file, const VecX& q_drawn);

/// The model as URDF, drawn where every q = 0 (URDF has no state), each link's frame its joint's
/// child frame J' (URDF's rule), the mass properties re-expressed there. Throws InvalidArgument
/// naming what URDF cannot keep: a spherical, universal or cylindrical joint, a free joint below
/// the world, any constraint but a coupler.
ExportedModel write_urdf(const ModelFile& file);

}  // namespace momenta::io
