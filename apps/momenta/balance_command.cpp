// `momenta balance ROTOR`: how unbalanced a rigid rotor is about its axis, the bearing reactions
// it causes, the one- or two-plane correction and the ISO 21940-11 grade verdict. Parses the
// options, calls momenta::inertia's balancing functions, prints text or JSON. Documented in
// docs/balancing.md and docs/cli.md.

#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "momenta/common/error.hpp"
#include "momenta/frontend/model_loading.hpp"
#include "momenta/inertia/balancing.hpp"
#include "momenta/io/yaml_reader.hpp"
#include "momenta/model/rotor.hpp"
#include "momenta/report/report.hpp"
#include "option_checks.hpp"
#include "output_format.hpp"
#include "part_input.hpp"

namespace momenta::cli {
namespace {

using inertia::Unbalance;
using json = nlohmann::ordered_json;

constexpr double kStandardGravity = 9.80665;

struct BalanceOptions {
  PartInput part;
  std::string body;  // a model file's rotor body
  std::vector<double> axis;
  std::vector<double> through;
  std::vector<double> bearings;
  std::optional<double> speed_rpm;
  std::vector<double> speed_range;
  int points = 11;
  double alpha = 0.0;
  std::vector<double> planes;
  std::optional<double> plane;
  std::optional<double> radius;
  bool remove = false;
  std::optional<double> grade;
  // g for the static loads: --gravity, else a model file's |gravity|, else standard gravity.
  std::optional<double> gravity;
  bool json = false;
  std::optional<std::string> report;
  bool force = false;
};

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

// A rotating vector: its amplitude and angle (degrees from x_R towards y_R); an amplitude below
// `floor` (round-off of a cancelling sum) has no angle.
json rotating_json(const Vec2& v) {
  return {{"x", v.x()},
          {"y", v.y()},
          {"amplitude", v.norm()},
          {"angle_deg", degrees(inertia::angle_of(v))}};
}
std::string rotating_text(const Vec2& v, const char* unit, double floor) {
  if (v.norm() <= floor) return fmt::format("{:.6g} {}", 0.0, unit);
  return fmt::format("{:.6g} {} at {:.2f}°", v.norm(), unit, degrees(inertia::angle_of(v)));
}

// A correction mass as the user places it: added at its angle, or removed opposite.
struct Placement {
  double z;
  double mass_radius;  // kg·m
  double angle_deg;
  std::optional<double> mass;  // kg at --radius
};
Placement place(const inertia::CorrectionMass& c, const BalanceOptions& o) {
  const Vec2 v = o.remove ? Vec2(-c.mass_radius) : c.mass_radius;
  Placement p{c.z, v.norm(), degrees(inertia::angle_of(v)), std::nullopt};
  if (o.radius) p.mass = c.mass_at(*o.radius);
  return p;
}

// The speeds to tabulate, rad/s: --speed, then the --speed-range rows.
std::vector<double> speeds_of(const BalanceOptions& o) {
  std::vector<double> omega;
  if (o.speed_rpm) omega.push_back(*o.speed_rpm * kRpm);
  if (!o.speed_range.empty()) {
    const double a = o.speed_range[0] * kRpm, b = o.speed_range[1] * kRpm;
    for (int k = 0; k < o.points; ++k) {
      omega.push_back(o.points == 1 ? a : a + (b - a) * k / (o.points - 1));
    }
  }
  return omega;
}

void check_options(const BalanceOptions& o) {
  if (o.radius && !(o.planes.size() == 2 || o.plane)) {
    throw CLI::ValidationError("--radius",
                               "places correction masses: give --planes Z1 Z2 or --plane Z");
  }
  if (o.remove && !(o.planes.size() == 2 || o.plane)) {
    throw CLI::ValidationError("--remove",
                               "applies to a correction: give --planes Z1 Z2 or --plane Z");
  }
  const bool speed = o.speed_rpm || !o.speed_range.empty();
  if (speed && o.bearings.empty()) {
    throw CLI::ValidationError("--speed",
                               "the reactions need the bearing planes: give --bearings ZA ZB");
  }
  if (o.grade && (o.bearings.empty() || !o.speed_rpm)) {
    throw CLI::ValidationError(
        "--grade",
        "the grade check needs the bearings (--bearings ZA ZB) and the maximum service "
        "speed (--speed RPM)");
  }
  if (!o.speed_range.empty() && !(o.speed_range[1] > o.speed_range[0])) {
    throw CLI::ValidationError("--speed-range", "expects A < B (rev/min)");
  }
}

// The rotor to balance: a part or mesh about --axis through --through, or a model file's body on
// its revolute joint (the joint gives the axis).
struct Rotor {
  std::string name;
  inertia::MassProperties mass_properties;
  inertia::RotorAxis axis;
  std::string joint;                    // the model's joint, when from a model file
  ReadPart part;                        // the part file or mesh read, otherwise
  std::optional<double> model_gravity;  // |g| of the model file, m/s²
};

bool is_model_file(const std::string& file) {
  const std::string e = std::filesystem::path(file).extension().string();
  if (e != ".yaml" && e != ".yml") return false;
  const io::YamlNode root = io::YamlNode::load_file(file);
  return root.is_map() && root.has("bodies");
}

Rotor read_rotor(const BalanceOptions& o) {
  Rotor r;
  if (is_model_file(o.part.file)) {
    if (!o.axis.empty() || !o.through.empty()) {
      throw CLI::ValidationError(!o.axis.empty() ? "--axis" : "--through",
                                 "a model file's rotor turns about its revolute joint's axis");
    }
    const io::ModelFile file = frontend::load_model(o.part.file);
    const model::RotorOnJoint found = model::find_rotor(file.model, o.body);
    r.name = fmt::format("{}: body '{}' on joint '{}'", file.name, found.body, found.joint);
    r.mass_properties = found.rotor;
    r.axis = found.axis;
    r.joint = found.joint;
    r.model_gravity = file.model.gravity().norm();
    return r;
  }
  if (!o.body.empty()) throw CLI::ValidationError("--body", "names a body of a model file");
  r.part = read_part(o.part, o.report.has_value());  // a mesh's triangles, to draw
  r.name = r.part.name;
  r.mass_properties = r.part.total;
  if (!o.axis.empty()) r.axis.direction_B = Vec3(o.axis[0], o.axis[1], o.axis[2]);
  if (!o.through.empty()) r.axis.p_BoAo_B = Vec3(o.through[0], o.through[1], o.through[2]);
  return r;
}

// Everything computed, then printed as JSON or text.
struct Balance {
  Rotor source;
  Unbalance rotor;
  std::vector<inertia::CorrectionMass> corrections;
  std::optional<Unbalance> corrected;
  std::vector<double> speeds;  // rad/s
  std::vector<inertia::BearingReactions> reactions, reactions_after;
  double gravity = kStandardGravity;  // the g of the static loads, m/s² (0: none)
  std::optional<Vec2> static_loads;
  std::optional<inertia::GradeCheck> grade, grade_after;
};

Balance compute(const BalanceOptions& o) {
  check_options(o);
  Balance b;
  b.source = read_rotor(o);
  b.gravity = o.gravity.value_or(b.source.model_gravity.value_or(kStandardGravity));
  b.rotor = inertia::unbalance(b.source.mass_properties, b.source.axis);
  if (o.planes.size() == 2) {
    const auto pair = inertia::two_plane_correction(b.rotor, o.planes[0], o.planes[1]);
    b.corrections.assign(pair.begin(), pair.end());
  } else if (o.plane) {
    b.corrections.push_back(inertia::single_plane_correction(b.rotor, *o.plane));
  }
  if (!b.corrections.empty()) b.corrected = inertia::with_corrections(b.rotor, b.corrections);
  b.speeds = speeds_of(o);
  if (!o.bearings.empty()) {
    const double zA = o.bearings[0], zB = o.bearings[1];
    for (double w : b.speeds) {
      b.reactions.push_back(inertia::bearing_reactions(b.rotor, zA, zB, w, o.alpha));
      if (b.corrected) {
        b.reactions_after.push_back(inertia::bearing_reactions(*b.corrected, zA, zB, w, o.alpha));
      }
    }
    if (b.gravity > 0.0) b.static_loads = inertia::static_bearing_loads(b.rotor, zA, zB, b.gravity);
    if (o.grade) {
      const double w = *o.speed_rpm * kRpm;
      b.grade = inertia::check_grade(b.rotor, *o.grade, w, zA, zB);
      if (b.corrected) b.grade_after = inertia::check_grade(*b.corrected, *o.grade, w, zA, zB);
    }
  }
  return b;
}

json unbalance_json(const Unbalance& u) {
  return {{"static_unbalance", rotating_json(u.static_unbalance)},
          {"products", {{"P_xz", u.products.x()}, {"P_yz", u.products.y()}}},
          {"couple_unbalance", rotating_json(u.couple_unbalance)}};
}

json grade_json(const inertia::GradeCheck& g) {
  return {{"grade_mm_per_s", g.grade},
          {"omega", g.omega},
          {"permissible", g.permissible},
          {"plane_A", rotating_json(g.plane_A)},
          {"plane_B", rotating_json(g.plane_B)},
          {"permissible_A", g.permissible_A},
          {"permissible_B", g.permissible_B},
          {"overhung", g.overhung},
          {"pass", g.pass}};
}

void print_json(const BalanceOptions& o, const Balance& b) {
  const Unbalance& u = b.rotor;
  json j;
  j["file"] = o.part.file;
  j["name"] = b.source.name;
  if (!b.source.joint.empty()) j["joint"] = b.source.joint;
  j["axis"] = vec_json(u.R_BR.col(2));
  j["through"] = vec_json(b.source.axis.p_BoAo_B);
  j["axis_frame"] = matrix_json(u.R_BR);
  j["mass"] = u.mass;
  j["axial_com"] = u.axial_com;
  j["eccentricity"] = u.eccentricity;
  j["polar_moment"] = u.polar_moment;
  j["principal_axis_tilt"] = u.principal_axis_tilt;
  j["unbalance"] = unbalance_json(u);
  if (!o.bearings.empty()) j["bearings"] = o.bearings;
  if (!b.reactions.empty()) {
    json rows = json::array();
    for (std::size_t k = 0; k < b.reactions.size(); ++k) {
      json row = {{"omega", b.speeds[k]},
                  {"rpm", b.speeds[k] / kRpm},
                  {"A", rotating_json(b.reactions[k].A)},
                  {"B", rotating_json(b.reactions[k].B)},
                  {"drive_torque", b.reactions[k].drive_torque}};
      if (!b.reactions_after.empty()) {
        row["A_after"] = rotating_json(b.reactions_after[k].A);
        row["B_after"] = rotating_json(b.reactions_after[k].B);
      }
      rows.push_back(std::move(row));
    }
    j["alpha"] = o.alpha;
    j["reactions"] = std::move(rows);
  }
  if (b.static_loads) {
    j["static_loads"] = {{"g", b.gravity}, {"A", b.static_loads->x()}, {"B", b.static_loads->y()}};
  }
  if (!b.corrections.empty()) {
    json list = json::array();
    for (const auto& c : b.corrections) {
      const Placement p = place(c, o);
      json entry = {{"z", p.z},
                    {"mass_radius", p.mass_radius},
                    {"angle_deg", p.angle_deg},
                    {"action", o.remove ? "remove" : "add"}};
      if (p.mass) entry["mass"] = *p.mass;
      list.push_back(std::move(entry));
    }
    j["correction"] = {{"planes", b.corrections.size()},
                       {"radius", o.radius ? json(*o.radius) : json(nullptr)},
                       {"masses", std::move(list)},
                       {"after", unbalance_json(*b.corrected)}};
  }
  if (b.grade) {
    j["grade"] = grade_json(*b.grade);
    if (b.grade_after) j["grade_after_correction"] = grade_json(*b.grade_after);
  }
  fmt::print("{}\n", json_text(j, ListSpacing::spaced));
}

void print_grade(const std::string& title, const inertia::GradeCheck& g, double mass,
                 double floor) {
  fmt::print("{}: U_per = {:.6g} kg·m (e_per = G/ω = {:.6g} µm){}\n", title, g.permissible,
             g.permissible / mass * 1e6,
             g.overhung ? "; overhung rotor: U_per / 2 allowed per plane" : "");
  fmt::print("  plane A  {:<36} allowed {:.6g} kg·m  {}\n", rotating_text(g.plane_A, "kg·m", floor),
             g.permissible_A, g.plane_A.norm() <= g.permissible_A ? "ok" : "over");
  fmt::print("  plane B  {:<36} allowed {:.6g} kg·m  {}\n", rotating_text(g.plane_B, "kg·m", floor),
             g.permissible_B, g.plane_B.norm() <= g.permissible_B ? "ok" : "over");
  fmt::print("  verdict  {}\n", g.pass ? "PASS" : "FAIL");
}

void print_text(const BalanceOptions& o, const Balance& b) {
  const Unbalance& u = b.rotor;
  // Round-off floors: a unbalance below 1e-12 of m·(rotor size) is zero.
  const double size = std::sqrt(u.polar_moment / u.mass) + std::abs(u.axial_com);
  const double U_floor = 1e-12 * u.mass * size;
  const double P_floor = 1e-12 * u.mass * size * size;
  const Vec3 a = u.R_BR.col(2);
  const Vec3& through = b.source.axis.p_BoAo_B;
  fmt::print(
      "{} ({}): rotating about [{:.6g}, {:.6g}, {:.6g}] through [{:.6g}, {:.6g}, {:.6g}] m\n",
      b.source.name, o.part.file, a.x(), a.y(), a.z(), through.x(), through.y(), through.z());
  fmt::print("  angles from x_R = [{:.6g}, {:.6g}, {:.6g}] towards y_R; z along the axis\n\n",
             u.R_BR(0, 0), u.R_BR(1, 0), u.R_BR(2, 0));
  fmt::print("mass                 {:.9g} kg\n", u.mass);
  fmt::print("centre of mass       z = {:.9g} m, eccentricity e = {:.6g} m\n", u.axial_com,
             u.eccentricity);
  fmt::print("polar moment         {:.9g} kg·m²\n", u.polar_moment);
  fmt::print("static unbalance     U_s = m e = {}\n",
             rotating_text(u.static_unbalance, "kg·m", U_floor));
  fmt::print("couple unbalance     {} (products about the centre of mass's plane)\n",
             rotating_text(u.couple_unbalance, "kg·m²", P_floor));
  fmt::print("principal axis tilt  {:.6g} rad ({:.4g}°)\n", u.principal_axis_tilt,
             degrees(u.principal_axis_tilt));
  if (!b.reactions.empty()) {
    fmt::print(
        "\nbearing reactions: the bearings' forces on the rotor, turning with it (A at z = {:.6g} "
        "m, B at z = {:.6g} m{}):\n",
        o.bearings[0], o.bearings[1],
        o.alpha != 0.0 ? fmt::format(", α = {:.6g} rad/s²", o.alpha) : std::string());
    const bool after = !b.reactions_after.empty();
    fmt::print("  {:>10} {:>12}  {:<30} {:<30}{}\n", "rev/min", "ω rad/s", "A", "B",
               after ? "  |A|, |B| after correction N" : "");
    for (std::size_t k = 0; k < b.reactions.size(); ++k) {
      const double F_floor = U_floor * std::max(1.0, b.speeds[k] * b.speeds[k]);
      fmt::print("  {:>10.6g} {:>12.6g}  {:<30} {:<30}", b.speeds[k] / kRpm, b.speeds[k],
                 rotating_text(b.reactions[k].A, "N", F_floor),
                 rotating_text(b.reactions[k].B, "N", F_floor));
      if (after) {
        fmt::print("  {:.3g}, {:.3g}", b.reactions_after[k].A.norm(),
                   b.reactions_after[k].B.norm());
      }
      fmt::print("\n");
    }
    if (o.alpha != 0.0)
      fmt::print("  drive torque α I_zz = {:.6g} N·m\n", b.reactions.front().drive_torque);
  }
  if (b.static_loads) {
    fmt::print(
        "static loads (horizontal shaft, g = {:.6g} m/s²{}, upward): A {:.6g} N, B {:.6g} N\n",
        b.gravity, o.gravity || !b.source.model_gravity ? "" : ", the model's", b.static_loads->x(),
        b.static_loads->y());
  } else if (!o.bearings.empty() && b.gravity == 0.0) {
    fmt::print("static loads: none (g = 0{})\n",
               o.gravity || !b.source.model_gravity ? "" : ", the model's gravity");
  }
  if (!b.corrections.empty()) {
    fmt::print("\n{}-plane correction ({} mass):\n", b.corrections.size() == 2 ? "two" : "single",
               o.remove ? "remove" : "add");
    for (const auto& c : b.corrections) {
      const Placement p = place(c, o);
      fmt::print("  plane z = {:.6g} m: {} m·r = {:.6g} kg·m at {:.2f}°", p.z,
                 o.remove ? "remove" : "add", p.mass_radius, p.angle_deg);
      if (p.mass) fmt::print(" ({:.6g} g at r = {:.6g} m)", *p.mass * 1e3, *o.radius);
      fmt::print("\n");
    }
    fmt::print("  after it: static unbalance {}, couple unbalance {}\n",
               rotating_text(b.corrected->static_unbalance, "kg·m", U_floor),
               rotating_text(b.corrected->couple_unbalance, "kg·m²", P_floor));
  }
  if (b.grade) {
    fmt::print("\n");
    print_grade(fmt::format("grade G {:g} at {:.6g} rev/min", b.grade->grade, *o.speed_rpm),
                *b.grade, u.mass, U_floor);
    if (b.grade_after) print_grade("after the correction", *b.grade_after, u.mass, U_floor);
  }
}

// The rotor's page: its parts (a model's body as its equivalent ellipsoid) and what was found.
void write_report(const BalanceOptions& o, const Balance& b) {
  report::BalanceFindings f;
  f.axis = b.source.axis;
  f.unbalance = b.rotor;
  if (!o.bearings.empty()) f.bearings = std::array<double, 2>{o.bearings[0], o.bearings[1]};
  f.corrections = b.corrections;
  f.radius = o.radius;
  f.remove = o.remove;
  f.speeds = b.speeds;
  f.reactions = b.reactions;
  f.reactions_after = b.reactions_after;
  f.grade = b.grade;
  f.grade_after = b.grade_after;
  const io::CompositePart rotor{b.source.name, b.source.mass_properties, b.source.part.parts};
  report::write_report(*o.report, report::balance_report_html(rotor, o.part.file, f), o.force);
  fmt::print(stderr, "momenta: wrote the report {}\n", *o.report);
}

void run(const BalanceOptions& o) {
  const Balance b = compute(o);
  if (o.json) {
    print_json(o, b);
  } else {
    print_text(o, b);
  }
  note_per_unit_density(b.source.part);
  if (o.report) write_report(o, b);
}

}  // namespace

void add_balance_command(CLI::App& app) {
  auto options = std::make_shared<BalanceOptions>();
  CLI::App* command = app.add_subcommand(
      "balance",
      "Static and couple unbalance of a rigid rotor about its axis, the bearing reactions it "
      "causes, one- or two-plane correction masses and the ISO 21940-11 grade verdict");
  add_part_input_options(command, options->part,
                         "The rotor: a part file (.yaml, .yml) or a closed triangle mesh (.stl, "
                         ".obj), in its own frame B; or a model file, whose body on a revolute "
                         "joint is the rotor (with the bodies welded to it)");
  command->add_option("--body", options->body,
                      "Model file: the rotor's body (default: the one body on a revolute joint)");
  command->add_option("--axis", options->axis, "The rotation axis's direction in B (default 0 0 1)")
      ->expected(3)
      ->check(finite());
  command
      ->add_option("--through", options->through,
                   "A point of the axis in B, m (default 0 0 0); axial positions z are measured "
                   "from it")
      ->expected(3)
      ->check(finite());
  command->add_option("--bearings", options->bearings, "The bearing planes ZA ZB along the axis, m")
      ->expected(2)
      ->check(finite());
  command
      ->add_option("--speed", options->speed_rpm,
                   "The speed, rev/min (for --grade the maximum service speed)")
      ->check(positive_finite());
  command
      ->add_option("--speed-range", options->speed_range,
                   "A table of reactions from A to B rev/min")
      ->expected(2)
      ->check(finite());
  // A table a person reads (or plots): 10⁵ rows at most, not 10⁸ that exhaust the memory.
  command
      ->add_option("--points", options->points,
                   "Rows of the --speed-range table (default 11, at most 100000)")
      ->check(whole_number_from_one(100000));
  command
      ->add_option("--alpha", options->alpha,
                   "Angular acceleration while spinning up, rad/s² (default 0)")
      ->check(finite());
  command
      ->add_option("--planes", options->planes,
                   "Two correction planes Z1 Z2, m: two-plane correction")
      ->expected(2)
      ->check(finite());
  command
      ->add_option("--plane", options->plane,
                   "One correction plane Z, m: single-plane (static) correction")
      ->check(finite())
      ->excludes("--planes");
  command
      ->add_option("--radius", options->radius,
                   "Radius of the correction masses, m: masses in grams")
      ->check(positive_finite());
  command->add_flag("--remove", options->remove,
                    "Correct by removing mass (drilling) rather than adding it");
  command
      ->add_option("--grade", options->grade,
                   "Balance grade G, mm/s (ISO 21940-11: G 0.4 … G 4000)")
      ->check(positive_finite());
  command
      ->add_option("--gravity", options->gravity,
                   "g for the static bearing loads of a horizontal shaft, m/s² (0: none; "
                   "default: a model file's own gravity, else 9.80665)")
      ->check(non_negative_finite());
  command->add_flag("--json", options->json, "Print JSON (SI units, angles in degrees)");
  command
      ->add_option("--report", options->report,
                   "Also write an HTML page: the rotor drawn with its axis, bearings and "
                   "correction masses, the unbalance, the grade and the bearing forces against "
                   "speed (docs/balancing.md)")
      ->check(not_a_folder());
  command->add_flag("--force", options->force, "Overwrite the --report file if it exists");
  command->footer(
      "Examples:\n"
      "  momenta balance examples/parts/overhung_fan.yaml --bearings 0 0.3 --speed 3000\n"
      "  momenta balance rotor.yaml --bearings 0 1 --speed 3000 --planes 0.1 0.9 --radius 0.15 "
      "--grade 2.5\n"
      "Angles are measured in the rotor, from x_R towards y_R (docs/balancing.md).");
  command->callback([options] { run(*options); });
}

}  // namespace momenta::cli
