#pragma once
// Bodies: rigid parts with mass properties, connected into a tree by joints.

#include <optional>
#include <string>

#include "momenta/inertia/mass_properties.hpp"
#include "momenta/inertia/unit_moments.hpp"

namespace momenta::model {

/// Name of the ground body, index 0 in every Model. It has no mass and never moves.
inline constexpr const char* kWorldBodyName = "world";

/// A rigid body B: a name and its mass properties described in its own frame B (centre of mass
/// p_BoBcm_B, inertia I_BBcm_B about the centre of mass). Its pose is set by the joint that
/// carries it (model/joint.hpp).
///
/// A body may be massless (mass 0) only if the subtree it carries has mass wherever it has
/// degrees of freedom; ModelBuilder::build() rejects a massless leaf carried by a joint with
/// degrees of freedom, whose mass matrix would be singular.
struct Body {
  std::string name;
  inertia::MassProperties mass_properties;
  /// Whether the mass properties are a uniform solid's (a `shape` or `mesh` of one density): its
  /// inertia then scales with its mass, I = m × (its tensor per unit mass), as the equations in
  /// symbols keep it when the mass is a symbol (I_G = m L²/12 for a rod).
  bool inertia_scales_with_mass = false;
  /// The standard shape it is, when it is one (a model file's `shape:`): its kind, sizes and
  /// orientation in B, from which the equations in symbols keep its inertia in its dimensions
  /// when those are symbols (I_G = m L²/12 with L the rod's `length_<body>`).
  std::optional<inertia::PrimitiveShape> shape;

  // --- set by ModelBuilder::build() ----------------------------------------------------------
  int index = -1;         ///< Index in Model::bodies(); 0 is the world.
  int parent_index = -1;  ///< Index of the parent body; −1 for the world.
  int joint_index = -1;   ///< Index of the joint that carries it (index − 1); −1 for the world.
};

}  // namespace momenta::model
