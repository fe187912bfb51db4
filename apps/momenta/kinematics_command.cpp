// `momenta kinematics MODEL --point BODY:x,y,z --frame BODY [--time T | --state FILE] [--json]`:
// a point's velocity and acceleration seen from a body's frame, split into the rotating-frame
// terms, with the carrying body's momentum and kinetic energy split. Calls
// dynamics::relative_kinematics and dynamics::body_momentum; documented in docs/cli.md and
// docs/kinematics.md.

#include <memory>
#include <optional>
#include <string>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "body_point_argument.hpp"
#include "commands.hpp"
#include "model_argument.hpp"
#include "momenta/common/error.hpp"
#include "momenta/dynamics/momentum.hpp"
#include "momenta/dynamics/relative_kinematics.hpp"
#include "momenta/frontend/model_loading.hpp"
#include "momenta/io/yaml_reader.hpp"
#include "momenta/system/multibody_system.hpp"
#include "output_format.hpp"
#include "state_file.hpp"

namespace momenta::cli {
namespace {

using json = nlohmann::ordered_json;

struct KinematicsOptions {
  ModelArgument model;
  std::string point;  // BODY or BODY:x,y,z
  std::string frame = "world";
  InstantOptions instant;
  bool json = false;
};

struct Result {
  std::string body_name, frame_name;
  Vec3 p_BoP_B;
  double t;
  dynamics::RelativeKinematics k;
  dynamics::BodyMomentum momentum;
  Vec3 H_P_F, H_Fo_F, H_G_F;  // in F's axes
};

// The text columns, round-off (below 1e-12 of the largest term of its kind) shown as 0.
Vec3 chop(const Vec3& v, double scale) {
  Vec3 c = v;
  for (int i = 0; i < 3; ++i)
    if (std::abs(c[i]) <= 1e-12 * scale) c[i] = 0.0;
  return c;
}

void print_text(const std::string& model_name, const Result& r) {
  const auto& k = r.k;
  const double v_scale = std::max({k.v_relative.norm(), k.v_WFo_F.norm(), k.v_rotation.norm()});
  const double a_scale = std::max({k.a_relative.norm(), k.a_WFo_F.norm(), k.a_euler.norm(),
                                   k.a_centripetal.norm(), k.a_coriolis.norm()});
  const auto v = [&](const Vec3& x) { return vec_text(chop(x, v_scale)); };
  const auto a = [&](const Vec3& x) { return vec_text(chop(x, a_scale)); };
  fmt::print("{} at t = {:.6g} s: point P = {} + {} m, seen from the frame of {}\n", model_name,
             r.t, r.body_name, vec_text(r.p_BoP_B), r.frame_name);
  fmt::print("(every vector in {}'s axes)\n", r.frame_name);
  fmt::print("  frame        Ω = {} rad/s, Ω̇ = {} rad/s²\n", vec_text(chop(k.w_WF_F, 0.0)),
             vec_text(chop(k.alpha_WF_F, 0.0)));
  fmt::print("  position     r = p_FoP        {} m\n", vec_text(k.p_FoP_F));
  fmt::print("  velocity (m/s)\n");
  fmt::print("    relative     v_rel          {}\n", v(k.v_relative));
  fmt::print("    frame origin v_Fo           {}\n", v(k.v_WFo_F));
  fmt::print("    rotation     Ω × r          {}\n", v(k.v_rotation));
  fmt::print("    absolute     v_P            {}\n", v(k.v_WP_F));
  fmt::print("  acceleration (m/s²)\n");
  fmt::print("    relative     a_rel          {}\n", a(k.a_relative));
  fmt::print("    frame origin a_Fo           {}\n", a(k.a_WFo_F));
  fmt::print("    Euler        Ω̇ × r          {}\n", a(k.a_euler));
  fmt::print("    centripetal  Ω × (Ω × r)    {}\n", a(k.a_centripetal));
  fmt::print("    Coriolis     2 Ω × v_rel    {}\n", a(k.a_coriolis));
  fmt::print("    transport    a_Fo + Ω̇ × r + Ω × (Ω × r) = {}\n", a(k.a_transport()));
  fmt::print("    absolute     a_P            {}\n", a(k.a_WP_F));
  const auto& m = r.momentum;
  const double h_scale = std::max({r.H_G_F.norm(), r.H_P_F.norm(), r.H_Fo_F.norm()});
  fmt::print("body {}: m = {:.6g} kg\n", r.body_name, m.mass);
  fmt::print("  kinetic energy    T = ½ m v̄² + ½ ωᵀ Ī ω = {:.6g} + {:.6g} = {:.6g} J\n",
             m.kinetic_translation, m.kinetic_rotation, m.kinetic_energy());
  fmt::print("  angular momentum (kg·m²/s)\n");
  fmt::print("    about G         H_G            {}\n", vec_text(chop(r.H_G_F, h_scale)));
  fmt::print("    about P         H_P            {}\n", vec_text(chop(r.H_P_F, h_scale)));
  fmt::print("    about Fo        H_Fo           {}\n", vec_text(chop(r.H_Fo_F, h_scale)));
}

json result_json(const std::string& model_name, const Result& r) {
  const auto& k = r.k;
  const auto& m = r.momentum;
  return {
      {"model", model_name},
      {"t", r.t},
      {"body", r.body_name},
      {"point", vec_json(r.p_BoP_B)},
      {"frame", r.frame_name},
      {"omega", vec_json(k.w_WF_F)},
      {"omega_dot", vec_json(k.alpha_WF_F)},
      {"position", vec_json(k.p_FoP_F)},
      {"velocity",
       {{"relative", vec_json(k.v_relative)},
        {"frame_origin", vec_json(k.v_WFo_F)},
        {"rotation", vec_json(k.v_rotation)},
        {"transport", vec_json(k.v_transport())},
        {"absolute", vec_json(k.v_WP_F)}}},
      {"acceleration",
       {{"relative", vec_json(k.a_relative)},
        {"frame_origin", vec_json(k.a_WFo_F)},
        {"euler", vec_json(k.a_euler)},
        {"centripetal", vec_json(k.a_centripetal)},
        {"coriolis", vec_json(k.a_coriolis)},
        {"transport", vec_json(k.a_transport())},
        {"absolute", vec_json(k.a_WP_F)}}},
      {"body_mass", m.mass},
      {"kinetic_energy",
       {{"translation", m.kinetic_translation},
        {"rotation", m.kinetic_rotation},
        {"total", m.kinetic_energy()}}},
      {"angular_momentum",
       {{"about_com", vec_json(r.H_G_F)},
        {"about_point", vec_json(r.H_P_F)},
        {"about_frame_origin", vec_json(r.H_Fo_F)}}},
  };
}

void run(const KinematicsOptions& o) {
  const io::ModelFile file = load_model(o.model);
  const model::Model& model = file.model;
  const auto [body, p_BoP_B] = parse_body_point(model, o.point, "--point");
  const int frame = body_named(model, o.frame, "--frame");
  const integrate::State state = instant_of(file, o.instant);

  system::MultibodySystem system(model);
  system.evaluate(state.t, state.q, state.v);
  const dynamics::Data& data = system.data();
  Result r;
  r.body_name = model.body(body).name;
  r.frame_name = model.body(frame).name;
  r.p_BoP_B = p_BoP_B;
  r.t = state.t;
  r.k = dynamics::relative_kinematics(model, data, body, p_BoP_B, frame);
  r.momentum = dynamics::body_momentum(model, data, body);
  const Mat3 R_FW = data.X_WB[frame].R.transpose();
  r.H_G_F = R_FW * r.momentum.angular_about_com;
  r.H_P_F = R_FW * r.momentum.angular_about(data.X_WB[body].apply(p_BoP_B));
  r.H_Fo_F = R_FW * r.momentum.angular_about(data.X_WB[frame].p);
  if (o.json) {
    fmt::print("{}\n", json_text(result_json(file.name, r), ListSpacing::spaced));
  } else {
    print_text(file.name, r);
  }
}

}  // namespace

void add_kinematics_command(CLI::App& app) {
  auto options = std::make_shared<KinematicsOptions>();
  CLI::App* command = app.add_subcommand(
      "kinematics",
      "A point's motion seen from a body's frame: relative, transport, Coriolis, centripetal and "
      "Euler terms; its body's momentum and kinetic energy");
  add_model_argument(command, options->model);
  command
      ->add_option("--point", options->point,
                   "BODY or BODY:x,y,z — a point fixed in a body (m, in the body's frame)")
      ->required();
  command->add_option("--frame", options->frame,
                      "The body whose frame the motion is seen from (default: world)");
  add_instant_options(command, options->instant);
  command->add_flag("--json", options->json, "Print JSON instead of text");
  command->footer(
      "Example:\n"
      "  momenta kinematics examples/kinematics/turntable_bead.yaml --point bead --frame "
      "turntable --time 1\n"
      "Terms and conventions: docs/kinematics.md.");
  command->callback([options] { run(*options); });
}

}  // namespace momenta::cli
