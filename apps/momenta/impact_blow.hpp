#pragma once
// The blow of `momenta impact` and of `momenta diagram`'s impulse–momentum diagram: an applied
// impulse at a body's point (--at, --impulse), or a collision of two bodies' points with
// restitution and Coulomb friction (--between, --normal, --restitution, --friction), and the
// mechanism's response (dynamics::impulsive_motion, restitution_impact, frictional_impact).

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "momenta/dynamics/impulse.hpp"
#include "momenta/integrate/integrator.hpp"
#include "momenta/model/model.hpp"

namespace momenta::cli {

struct BlowOptions {
  std::string at;                    // BODY or BODY:x,y,z
  std::string impulse;               // Px,Py,Pz (N·s, world axes)
  std::vector<std::string> between;  // A[:x,y,z] B[:x,y,z]
  std::string normal;                // nx,ny,nz: B is pushed along it
  std::optional<double> restitution;
  std::vector<double> friction;  // μs[, μk]: Coulomb friction at the contact
  /// Whether any of them was given.
  bool given() const {
    return !at.empty() || !impulse.empty() || !between.empty() || !normal.empty() ||
           restitution.has_value() || !friction.empty();
  }
};

// What struck: an applied impulse, or a collision at a contact (then `impact` is set).
struct Blow {
  std::vector<dynamics::PointImpulse> impulses;  // the applied one, or P on B (see on_bodies)
  std::optional<dynamics::PointContact> contact;
  double restitution = 0.0;
  std::optional<dynamics::Impact> impact;
  // With --friction: the coefficients and what Coulomb's law did (dynamics::frictional_impact).
  std::optional<dynamics::FrictionalImpact> rough;
  double static_friction = 0.0, kinetic_friction = 0.0;
  dynamics::ImpulsiveMotion motion;  // the mechanism's response
  /// The impulses on the bodies: the applied one, or the collision's P on B and −P on A (where
  /// A is a body, not the world).
  std::vector<dynamics::PointImpulse> on_bodies() const;
};

// "sticking", "sliding", or "frictionless" where the mechanism couples the normal and the slip.
const char* friction_outcome(const dynamics::FrictionalImpact& f);

/// The options --at, --impulse, --between, --normal, --friction and --restitution.
void add_blow_options(CLI::App* command, BlowOptions& options);

/// The blow the options describe at `state`, and the mechanism's response to it. Throws
/// CLI::ValidationError where they are incomplete or mixed, and what dynamics throws.
Blow blow_of(const model::Model& model, const BlowOptions& o, const integrate::State& state);

}  // namespace momenta::cli
