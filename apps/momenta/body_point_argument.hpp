#pragma once
// Command-line arguments that name a body of the model, a point fixed in one (BODY:x,y,z) or a
// vector (x,y,z), with the errors a person can act on (the names the model has, an example).

#include <string>
#include <utility>

#include "momenta/model/model.hpp"

namespace momenta::cli {

/// The index of the body called `name`; a CLI::ValidationError for `option` naming the bodies
/// there are (with a did-you-mean) otherwise.
int body_named(const model::Model& model, const std::string& name, const char* option);

/// "BODY" or "BODY:x,y,z" (m, in the body's frame) as the body's index and p_BoP_B: a moving
/// body, or the world too where `world_allowed`.
std::pair<int, Vec3> parse_body_point(const model::Model& model, const std::string& text,
                                      const char* option, bool world_allowed = false);

/// "x,y,z": three finite numbers, in `unit` for the message.
Vec3 parse_vector(const std::string& text, const char* option, const char* unit);

}  // namespace momenta::cli
