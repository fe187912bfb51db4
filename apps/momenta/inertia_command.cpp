// `momenta inertia FILE`: mass properties of a mesh file or a composite part file.
// Parses the options, calls momenta::io and momenta::inertia, prints text or JSON. Documented in
// docs/cli.md; the part-file format in docs/inertia-format.md.

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "momenta/common/error.hpp"
#include "momenta/inertia/mass_properties.hpp"
#include "momenta/io/part_file.hpp"
#include "momenta/report/report.hpp"
#include "option_checks.hpp"
#include "output_format.hpp"
#include "part_input.hpp"

namespace momenta::cli {
namespace {

using inertia::MassProperties;
// Ordered: keys print in the order written, mass first.
using json = nlohmann::ordered_json;

struct InertiaOptions {
  PartInput part;
  std::vector<double> about;
  std::string frame = "body";
  bool json = false;
  std::optional<std::string> report;
  bool force = false;
};

void print_tensor(const Mat3& M, const char* format) {
  for (int i = 0; i < 3; ++i) {
    fmt::print("  [");
    for (int j = 0; j < 3; ++j) fmt::print(fmt::runtime(format), M(i, j));
    fmt::print(" ]\n");
  }
}

void run(const InertiaOptions& o) {
  const ReadPart r = read_part(o.part, o.report.has_value());
  const MassProperties& mp = r.total;
  const inertia::PrincipalAxes principal = mp.principal_axes();
  const Mat3& R_BP = principal.R_BP;
  // Tensors are printed in the frame asked for: B's own axes, or the principal axes P.
  const bool in_principal = o.frame == "principal";
  const auto express = [&](const Mat3& I_B) -> Mat3 {
    return in_principal ? Mat3(R_BP.transpose() * I_B * R_BP) : I_B;
  };
  // In principal axes the tensor about the centre of mass is diagonal by definition: print the
  // moments themselves rather than R_BPᵀ I R_BP with its round-off off the diagonal.
  const Mat3 I_com = in_principal ? Mat3(principal.moments.asDiagonal()) : mp.inertia_about_com();
  std::optional<Vec3> about;
  std::optional<Mat3> I_about;
  if (!o.about.empty()) {
    about = Vec3(o.about[0], o.about[1], o.about[2]);
    I_about = express(mp.inertia_about(*about));
  }

  if (o.json) {
    json j;
    j["file"] = o.part.file;
    j["name"] = r.name;
    j["frame"] = o.frame;
    j["mass"] = mp.mass();
    j["volume"] = mp.volume();
    j["com"] = vec_json(mp.center_of_mass());
    j["inertia_com"] = matrix_json(I_com);
    j["principal_moments"] = vec_json(principal.moments);
    j["principal_axes"] = matrix_json(R_BP);
    if (about) {
      j["about"] = vec_json(*about);
      j["inertia_about"] = matrix_json(*I_about);
    }
    if (r.is_mesh) {
      j["shell"] = r.shell;
      j["density"] = r.density ? json(*r.density) : json(nullptr);
      j["per_unit_density"] = r.per_unit_density;
    } else {
      json parts = json::array();
      for (const io::PartSummary& p : r.parts) {
        const MassProperties& pm = p.mass_properties;
        parts.push_back({{"name", p.name},
                         {"kind", p.kind},
                         {"hole", p.hole},
                         {"line", p.line},
                         {"mass", pm.mass()},
                         {"volume", pm.volume()},
                         {"com", vec_json(pm.center_of_mass())},
                         {"inertia_com", matrix_json(pm.inertia_about_com())}});
      }
      j["parts"] = std::move(parts);
    }
    // Every object here has keys, and a vector or a matrix row prints on one line, ", " between
    // its numbers.
    fmt::print("{}\n", json_text(j, ListSpacing::spaced));
  } else {
    fmt::print("{} ({})\n", r.name, o.part.file);
    // Lengths are shown against the body's size: its radius of gyration or its distance from Bo.
    const double length = length_scale(mp);
    if (!r.is_mesh) {
      fmt::print("\n  {:<24} {:<18} {:>12}  {}\n", "part", "kind", "mass kg", "centre of mass m");
      for (const io::PartSummary& p : r.parts) {
        const double m = p.mass_properties.mass();
        fmt::print("  {:<24} {:<18} {:>12.6g}  {}\n", p.name, p.hole ? p.kind + " (hole)" : p.kind,
                   p.hole ? -m : m, vec_text(shown(p.mass_properties.center_of_mass(), length)));
      }
      fmt::print("\n");
    }
    if (r.is_mesh && r.density) {
      fmt::print("density            {:.9g} kg/m{}{}\n", *r.density,
                 r.shell ? "² (thin shell)" : "³",
                 r.per_unit_density ? " — none given: per unit density" : "");
    }
    fmt::print("mass               {:.9g} kg\n", mp.mass());
    fmt::print("volume             {:.9g} m³{}\n", mp.volume(),
               r.shell ? " (a thin shell has none)" : "");
    fmt::print("centre of mass     {} m\n", vec_text(shown(mp.center_of_mass(), length)));
    const std::string axes = in_principal ? "principal axes" : "body axes";
    fmt::print("inertia about the centre of mass, in {} (kg·m²):\n", axes);
    print_tensor(shown(I_com), " {:>13.6e}");
    fmt::print("principal moments  {} kg·m² (ascending)\n",
               vec_text(shown(principal.moments, principal.moments.maxCoeff())));
    fmt::print("principal axes (columns, in body axes):\n");
    print_tensor(shown(R_BP), " {:>9.6f}");
    if (about) {
      fmt::print("inertia about {} m, in {} (kg·m²):\n", vec_text(*about), axes);
      print_tensor(shown(*I_about), " {:>13.6e}");
    }
  }
  note_per_unit_density(r);
  if (o.report) {
    const io::CompositePart part{r.name, r.total, r.parts};
    report::write_report(*o.report, report::inertia_report_html(part, o.part.file, about), o.force);
    fmt::print(stderr, "momenta: wrote the report {}\n", *o.report);
  }
}

}  // namespace

void add_inertia_command(CLI::App& app) {
  auto options = std::make_shared<InertiaOptions>();
  CLI::App* command = app.add_subcommand(
      "inertia",
      "Mass, centre of mass, inertia tensor and principal axes of a mesh file (.stl, .obj) or a "
      "composite part file (.yaml)");
  add_part_input_options(command, options->part,
                         "A part file (.yaml, .yml; format in docs/inertia-format.md) or a closed "
                         "triangle mesh (.stl, .obj)");
  command
      ->add_option("--about", options->about,
                   "Also the inertia tensor about the point X Y Z (m, in the file's frame)")
      ->expected(3)
      ->check(finite());
  command
      ->add_option("--frame", options->frame,
                   "Axes the inertia tensors are expressed in: 'body' (the file's own) or "
                   "'principal' (the principal axes, tensors diagonal)")
      ->check(CLI::IsMember({"body", "principal"}))
      ->capture_default_str();
  command->add_flag("--json", options->json, "Print JSON (SI units) instead of text");
  command
      ->add_option("--report", options->report,
                   "Also write an HTML page of the part: drawn with its centre of mass, principal "
                   "axes and equivalent ellipsoid, the parts and the tensors (docs/report.md)")
      ->check(not_a_folder());
  command->add_flag("--force", options->force, "Overwrite the --report file if it exists");
  command->footer(
      "Examples:\n"
      "  momenta inertia examples/parts/flanged_shaft.yaml\n"
      "  momenta inertia bracket.stl --scale 0.001 --density 2700 --about 0 0 0.05\n"
      "  momenta inertia cover.obj --shell --density 5.4 --json\n"
      "All output is SI: kg, m, m³, kg·m². Off-diagonal inertia entries are minus the products of "
      "inertia.");
  command->callback([options] { run(*options); });
}

}  // namespace momenta::cli
