#include "impact_blow.hpp"

#include <cmath>

#include <fmt/format.h>

#include "body_point_argument.hpp"

namespace momenta::cli {

const char* friction_outcome(const dynamics::FrictionalImpact& f) {
  // A slip at rest before (to the course's own 1e-13 of the relative speed) that slides again
  // starts from rest.
  const double speed = std::hypot(f.slip_before_W.norm(), f.approach_speed);
  if (f.course == dynamics::SlipCourse::slides_again && f.slip_before_W.norm() <= 1e-13 * speed) {
    return "sliding from rest";
  }
  return dynamics::slip_course_name(f.course);
}

std::vector<dynamics::PointImpulse> Blow::on_bodies() const {
  std::vector<dynamics::PointImpulse> out = impulses;
  if (contact && contact->body_a != 0) {
    out.push_back({contact->body_a, contact->p_AoPa_A, -impulses.front().impulse_W});
  }
  return out;
}

void add_blow_options(CLI::App* command, BlowOptions& options) {
  command->add_option("--at", options.at,
                      "BODY or BODY:x,y,z — where an applied impulse acts: a point fixed in a "
                      "body (m, in the body's frame)");
  command->add_option("--impulse", options.impulse,
                      "Px,Py,Pz — the applied impulse (N·s, in the world's axes)");
  command
      ->add_option("--between", options.between,
                   "A[:x,y,z] B[:x,y,z] — a collision: the points of bodies A (or the world) and "
                   "B that touch")
      ->expected(2);
  command->add_option("--normal", options.normal,
                      "nx,ny,nz — the contact normal, along which B is pushed away from A (world "
                      "axes; normalized)");
  command
      ->add_option("--friction", options.friction,
                   "μs[,μk] — Coulomb friction at the contact (μk ≤ μs, the same when left out): "
                   "the impact sticks or slides (docs/contacts.md)")
      ->delimiter(',');
  command->add_option("--restitution", options.restitution,
                      "e in [0, 1]: the separation speed is e times the approach speed (0 "
                      "plastic, 1 elastic)");
}

namespace {

// The blow the options describe: --at and --impulse, or --between, --normal and --restitution.
Blow blow_without_motion(const model::Model& model, const BlowOptions& o,
                         const integrate::State& state) {
  const bool applied = !o.at.empty() || !o.impulse.empty();
  const bool contact = !o.between.empty() || !o.normal.empty() || o.restitution.has_value();
  if (applied == contact) {
    throw CLI::ValidationError(
        "impact",
        "give an applied impulse (--at BODY:x,y,z --impulse Px,Py,Pz) or a collision "
        "(--between A:x,y,z B:x,y,z --normal nx,ny,nz --restitution e), one of them");
  }
  Blow blow;
  if (applied) {
    if (o.at.empty() || o.impulse.empty()) {
      throw CLI::ValidationError("impact", "an applied impulse needs both --at and --impulse");
    }
    const auto [body, p] = parse_body_point(model, o.at, "--at");
    blow.impulses.push_back(
        {body, p, parse_vector(o.impulse, "--impulse", "N·s, in the world's axes")});
    return blow;
  }
  if (o.between.size() != 2 || o.normal.empty() || !o.restitution) {
    throw CLI::ValidationError(
        "impact", "a collision needs --between A:x,y,z B:x,y,z, --normal and --restitution");
  }
  const auto [a, p_a] = parse_body_point(model, o.between[0], "--between", true);
  const auto [b, p_b] = parse_body_point(model, o.between[1], "--between");
  Vec3 n = parse_vector(o.normal, "--normal", "the direction B is pushed, in the world's axes");
  if (!(n.norm() > 0.0)) throw CLI::ValidationError("--normal", "the normal is zero");
  n.normalize();
  blow.contact = dynamics::PointContact{a, p_a, b, p_b, n};
  blow.restitution = *o.restitution;
  if (o.friction.empty()) {
    blow.impact =
        dynamics::restitution_impact(model, state.q, state.v, *blow.contact, blow.restitution);
    blow.impulses.push_back({b, p_b, blow.impact->normal_impulse * n});
    return blow;
  }
  if (o.friction.size() > 2) {
    throw CLI::ValidationError("--friction", "give μs, or μs,μk (μk ≤ μs)");
  }
  blow.static_friction = o.friction[0];
  blow.kinetic_friction = o.friction.size() == 2 ? o.friction[1] : o.friction[0];
  blow.rough = dynamics::frictional_impact(model, state.q, state.v, *blow.contact, blow.restitution,
                                           blow.static_friction, blow.kinetic_friction);
  blow.impact = dynamics::Impact{blow.rough->normal_impulse, blow.rough->approach_speed,
                                 blow.rough->separation_speed, blow.rough->motion};
  blow.impulses.push_back({b, p_b, blow.rough->impulse_W});
  return blow;
}

}  // namespace

Blow blow_of(const model::Model& model, const BlowOptions& o, const integrate::State& state) {
  Blow blow = blow_without_motion(model, o, state);
  blow.motion = blow.impact ? blow.impact->motion
                            : dynamics::impulsive_motion(model, state.q, state.v, blow.impulses);
  return blow;
}

}  // namespace momenta::cli
