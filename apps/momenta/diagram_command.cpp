// `momenta diagram MODEL --body NAME [--time T | --state FILE] [-o fbd.svg] [--json]`: a body's
// free-body and kinetic diagrams at one instant — every load with its point, the kinetic terms
// and the balance residuals printed; the picture written as SVG. With a blow (`momenta impact`'s
// --at/--impulse or --between/--normal/--restitution[/--friction]): the body's impulse–momentum
// diagram at that impact instead. Calls analysis::free_body_diagram, impulse_momentum_diagram
// and report::free_body_svg, impulse_momentum_svg; documented in docs/cli.md and
// docs/diagrams.md.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "commands.hpp"
#include "impact_blow.hpp"
#include "model_argument.hpp"
#include "momenta/analysis/free_body.hpp"
#include "momenta/analysis/impulse_momentum.hpp"
#include "momenta/common/error.hpp"
#include "momenta/frontend/model_loading.hpp"
#include "momenta/report/free_body_svg.hpp"
#include "momenta/report/impulse_momentum_svg.hpp"
#include "momenta/report/report.hpp"
#include "momenta/simulate/unilaterals.hpp"
#include "option_checks.hpp"
#include "output_format.hpp"
#include "state_file.hpp"

namespace momenta::cli {
namespace {

using json = nlohmann::ordered_json;

struct DiagramOptions {
  ModelArgument model;
  std::string body;
  InstantOptions instant;
  BlowOptions blow;  // given: the impulse–momentum diagram of that impact
  std::optional<std::string> output;
  bool force = false;
  bool json = false;
};

void print_text(const std::string& model_name, const analysis::FreeBodyDiagram& d) {
  fmt::print("{}: body {} at t = {:.6g} s, m = {:.6g} kg, G at {} m\n", model_name, d.body, d.t,
             d.mass, vec_text(d.p_WoG_W));
  if (d.plane_normal) {
    fmt::print("planar: every force in the plane normal to {}\n", vec_text(*d.plane_normal));
  } else {
    fmt::print("three-dimensional\n");
  }
  fmt::print("free-body diagram (world axes; forces N at points m, couples N·m)\n");
  for (const analysis::Load& load : d.loads) {
    fmt::print("  {:<9} {}\n", analysis::load_kind_name(load.kind), load.description);
    fmt::print("            F = {} at {}", vec_text(load.force_W), vec_text(load.p_WoP_W));
    if (!load.couple_W.isZero(0.0)) fmt::print(", couple {}", vec_text(load.couple_W));
    fmt::print("\n");
  }
  fmt::print("kinetic diagram\n");
  fmt::print("  m a_G     = {} N\n", vec_text(d.m_a_G()));
  fmt::print("  Ī α       = {} N·m\n", vec_text(d.I_alpha()));
  fmt::print("  ω × H_G   = {} N·m\n", vec_text(d.w_cross_H()));
  fmt::print("balance\n");
  fmt::print("  ΣF        = {} N,   ΣF − m a_G = {} N\n", vec_text(d.sum_of_forces()),
             vec_text(d.force_residual()));
  fmt::print("  ΣM_G      = {} N·m, ΣM_G − Ḣ_G = {} N·m\n", vec_text(d.sum_of_moments_about_G()),
             vec_text(d.moment_residual()));
}

json diagram_json(const std::string& model_name, const analysis::FreeBodyDiagram& d) {
  json loads = json::array();
  for (const analysis::Load& load : d.loads) {
    loads.push_back({{"kind", analysis::load_kind_name(load.kind)},
                     {"name", load.name},
                     {"description", load.description},
                     {"point", vec_json(load.p_WoP_W)},
                     {"force", vec_json(load.force_W)},
                     {"couple", vec_json(load.couple_W)}});
  }
  return {{"model", model_name},
          {"body", d.body},
          {"t", d.t},
          {"mass", d.mass},
          {"com", vec_json(d.p_WoG_W)},
          {"plane_normal", d.plane_normal ? vec_json(*d.plane_normal) : json()},
          {"loads", loads},
          {"kinetic",
           {{"m_a_G", vec_json(d.m_a_G())},
            {"I_alpha", vec_json(d.I_alpha())},
            {"omega_cross_H", vec_json(d.w_cross_H())}}},
          {"residual",
           {{"force", vec_json(d.force_residual())}, {"moment", vec_json(d.moment_residual())}}}};
}

void print_text(const std::string& model_name, const analysis::ImpulseMomentumDiagram& d) {
  fmt::print("{}: body {} at t = {:.6g} s, m = {:.6g} kg, G at {} m\n", model_name, d.body, d.t,
             d.mass, vec_text(d.p_WoG_W));
  if (d.plane_normal) {
    fmt::print("planar: every impulse in the plane normal to {}\n", vec_text(*d.plane_normal));
  } else {
    fmt::print("three-dimensional\n");
  }
  fmt::print("momenta just before\n");
  fmt::print("  m v̄₁       = {} N·s\n", vec_text(d.linear_before()));
  fmt::print("  H_G1 = Ī ω₁ = {} N·m·s\n", vec_text(d.angular_before()));
  fmt::print("impulses on the body (world axes; N·s at points m, couples N·m·s)\n");
  for (const analysis::Load& impulse : d.impulses) {
    fmt::print("  {:<9} {}\n", analysis::load_kind_name(impulse.kind), impulse.description);
    fmt::print("            P = {} at {}", vec_text(impulse.force_W), vec_text(impulse.p_WoP_W));
    if (!impulse.couple_W.isZero(0.0)) fmt::print(", couple {}", vec_text(impulse.couple_W));
    fmt::print("\n");
  }
  fmt::print("momenta just after\n");
  fmt::print("  m v̄₂       = {} N·s\n", vec_text(d.linear_after()));
  fmt::print("  H_G2 = Ī ω₂ = {} N·m·s\n", vec_text(d.angular_after()));
  fmt::print("balance\n");
  fmt::print("  m v̄₁ + ΣP − m v̄₂    = {} N·s\n", vec_text(d.linear_residual()));
  fmt::print("  H_G1 + ΣM_G − H_G2  = {} N·m·s\n", vec_text(d.angular_residual()));
}

json diagram_json(const std::string& model_name, const analysis::ImpulseMomentumDiagram& d) {
  json impulses = json::array();
  for (const analysis::Load& impulse : d.impulses) {
    impulses.push_back({{"kind", analysis::load_kind_name(impulse.kind)},
                        {"name", impulse.name},
                        {"description", impulse.description},
                        {"point", vec_json(impulse.p_WoP_W)},
                        {"impulse", vec_json(impulse.force_W)},
                        {"couple", vec_json(impulse.couple_W)}});
  }
  return {
      {"model", model_name},
      {"body", d.body},
      {"t", d.t},
      {"mass", d.mass},
      {"com", vec_json(d.p_WoG_W)},
      {"plane_normal", d.plane_normal ? vec_json(*d.plane_normal) : json()},
      {"before",
       {{"linear", vec_json(d.linear_before())}, {"angular", vec_json(d.angular_before())}}},
      {"impulses", impulses},
      {"after", {{"linear", vec_json(d.linear_after())}, {"angular", vec_json(d.angular_after())}}},
      {"residual",
       {{"linear", vec_json(d.linear_residual())}, {"angular", vec_json(d.angular_residual())}}}};
}

// The picture and the text of the diagram the options ask for.
template <class Diagram, class Draw>
void show(const DiagramOptions& o, const io::ModelFile& file, const Diagram& d, Draw&& draw) {
  if (o.json) {
    fmt::print("{}\n", json_text(diagram_json(file.name, d), ListSpacing::spaced));
  } else {
    print_text(file.name, d);
  }
  if (o.output) {
    const std::span<const io::PartSummary> parts = file.parts_of(file.model.body_index(o.body));
    report::write_report(*o.output, draw(parts), o.force);
    if (!o.json) fmt::print("wrote {}\n", *o.output);
  }
}

void run(const DiagramOptions& o) {
  // Refused before any work: the user's file is never overwritten without --force.
  if (o.output && std::filesystem::exists(*o.output) && !o.force) {
    throw FileError(
        fmt::format("{}: the output file exists; pass --force to overwrite it", *o.output));
  }
  const io::ModelFile file = load_model(o.model);
  const integrate::State state = instant_of(file, o.instant);
  if (o.blow.given()) {
    const Blow blow = blow_of(file.model, o.blow, state);
    const std::string name = blow.contact ? "contact impulse" : "applied impulse";
    const analysis::ImpulseMomentumDiagram d = analysis::impulse_momentum_diagram(
        file.model, o.body, state.t, state.q, blow.motion, blow.on_bodies(), name);
    show(o, file, d, [&](std::span<const io::PartSummary> parts) {
      return report::impulse_momentum_svg(d, file.name, parts);
    });
    return;
  }
  // The stops and contacts the mechanism touches hold, as a run starting there holds them.
  system::MultibodySystem system(file.model);
  integrate::State at = state;
  simulate::hold_what_touches(system, at);
  const analysis::FreeBodyDiagram d = analysis::free_body_diagram(system, o.body, at.t, at.q, at.v);
  show(o, file, d, [&](std::span<const io::PartSummary> parts) {
    return report::free_body_svg(d, file.name, parts);
  });
}

}  // namespace

void add_diagram_command(CLI::App& app) {
  auto options = std::make_shared<DiagramOptions>();
  CLI::App* command = app.add_subcommand(
      "diagram",
      "A body's free-body and kinetic diagrams at one instant: every force and couple on it "
      "(gravity, joint and constraint reactions, springs, loads), m a_G and Ḣ_G, and the "
      "residuals of ΣF = m a_G and ΣM_G = Ḣ_G; with an impact's blow (as momenta impact's), its "
      "impulse–momentum diagram: momenta before + impulses = momenta after");
  add_model_argument(command, options->model);
  command->add_option("--body", options->body, "The body to isolate")->required();
  add_instant_options(command, options->instant);
  add_blow_options(command, options->blow);
  command
      ->add_option("-o,--output", options->output,
                   "Write the diagrams as SVG to this file (never overwritten without --force)")
      ->check(not_a_folder());
  command->add_flag("--force", options->force, "Overwrite the --output file if it exists");
  command->add_flag("--json", options->json, "Print JSON instead of text");
  command->footer(
      "Examples:\n"
      "  momenta diagram examples/pendulum.yaml --body bob --time 0.5 -o fbd.svg\n"
      "  momenta diagram examples/eccentric_impact.yaml --body rod --between sphere rod:0,0,-1.1 "
      "--normal 1,0,0 --restitution 0.6 -o impulse.svg\n"
      "What is drawn and the conventions: docs/diagrams.md.");
  command->callback([options] { run(*options); });
}

}  // namespace momenta::cli
