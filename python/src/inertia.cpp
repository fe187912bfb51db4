// momenta.inertia: mass properties of primitives, meshes and part files, and what can be done
// with them (composition, holes, shifts, rotations, principal axes, the validity check).

#include <fmt/format.h>
#include <pybind11/operators.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <optional>

#include "bindings.hpp"
#include "momenta/inertia/mass_properties.hpp"
#include "momenta/inertia/primitives.hpp"
#include "momenta/io/part_file.hpp"

namespace momenta::python {
namespace {

using inertia::Amount;
using inertia::MassProperties;

// Exactly one of mass= (kg) or density= (its unit follows the shape's dimension).
Amount amount_of(std::string_view shape, std::optional<double> mass,
                 std::optional<double> density) {
  if (mass.has_value() == density.has_value()) {
    throw py::value_error(fmt::format("{}: give exactly one of mass= (kg) or density=", shape));
  }
  return mass ? Amount::mass(*mass) : Amount::density(*density);
}

std::string describe(const MassProperties& p) {
  const Vec3& c = p.center_of_mass();
  const Mat3& I = p.inertia_about_com();
  return fmt::format(
      "MassProperties(mass={:.6g} kg, center_of_mass=[{:.6g}, {:.6g}, {:.6g}] m, "
      "inertia_about_com=[[{:.6g}, {:.6g}, {:.6g}], [{:.6g}, {:.6g}, {:.6g}], "
      "[{:.6g}, {:.6g}, {:.6g}]] kg·m², volume={:.6g} m³)",
      p.mass(), c[0], c[1], c[2], I(0, 0), I(0, 1), I(0, 2), I(1, 0), I(1, 1), I(1, 2), I(2, 0),
      I(2, 1), I(2, 2), p.volume());
}

void bind_mass_properties(py::module_& m) {
  py::class_<MassProperties>(m, "MassProperties", R"doc(
Mass properties of a rigid body B described in its frame B: mass (kg), centre of mass
p_BoBcm_B (m), inertia I_BBcm_B about the centre of mass, expressed in B (kg·m²; off-diagonal
entries are minus the products of inertia, I_xy = −∫ x y dm), and volume (m³; 0 where it has no
meaning). Add two to compose them, subtract a hole.)doc")
      .def(py::init([](double mass, const py::object& center_of_mass,
                       const py::object& inertia_about_com, double volume) {
             return MassProperties(mass, vec3_arg(center_of_mass, "center_of_mass"),
                                   mat3_arg(inertia_about_com, "inertia_about_com"), volume);
           }),
           py::arg("mass"), py::arg("center_of_mass"), py::arg("inertia_about_com"),
           py::arg("volume") = 0.0,
           "From a mass, the centre of mass and the inertia about it. Nothing is checked: call "
           "check_physical() on values a user gave.")
      .def_static(
          "from_inertia_about",
          [](double mass, const py::object& center_of_mass, const py::object& inertia,
             const py::object& about, double volume) {
            return MassProperties::from_inertia_about(
                mass, vec3_arg(center_of_mass, "center_of_mass"), mat3_arg(inertia, "inertia"),
                vec3_arg(about, "about"), volume);
          },
          py::arg("mass"), py::arg("center_of_mass"), py::arg("inertia"), py::arg("about"),
          py::arg("volume") = 0.0,
          "From an inertia about the point `about` (p_BoQ_B) instead of about the centre of mass "
          "(a top's moment about its pivot, as textbooks give it).")
      .def_property_readonly("mass", &MassProperties::mass, "Mass, kg.")
      .def_property_readonly("volume", &MassProperties::volume, "Volume, m³ (0: not a solid).")
      .def_property_readonly(
          "center_of_mass", [](const MassProperties& p) { return to_numpy(p.center_of_mass()); },
          "Centre of mass p_BoBcm_B, m (3,).")
      .def_property_readonly(
          "inertia_about_com",
          [](const MassProperties& p) { return to_numpy(p.inertia_about_com()); },
          "Inertia about the centre of mass, in B, kg·m² (3, 3).")
      .def(
          "inertia_about",
          [](const MassProperties& p, const py::object& point) {
            return to_numpy(p.inertia_about(vec3_arg(point, "point")));
          },
          py::arg("point"),
          "Inertia about the point p_BoQ_B (m), in B, by the parallel-axis theorem (products "
          "included), kg·m² (3, 3).")
      .def(
          "transformed",
          [](const MassProperties& p, const py::object& rotation, const py::object& position) {
            return p.transformed(mat3_arg(rotation, "rotation"), vec3_arg(position, "position"));
          },
          py::arg("rotation"), py::arg("position"),
          "The same body described in a frame A in which B sits at pose (R_AB = rotation, "
          "p_AoBo_A = position).")
      .def(
          "re_expressed",
          [](const MassProperties& p, const py::object& rotation) {
            return p.re_expressed(mat3_arg(rotation, "rotation"));
          },
          py::arg("rotation"), "The inertia re-expressed in a frame A turned by R_AB about Bo.")
      .def(
          "principal_axes",
          [](const MassProperties& p) {
            const inertia::PrincipalAxes axes = p.principal_axes();
            return py::make_tuple(to_numpy(axes.moments), to_numpy(axes.R_BP));
          },
          "(moments, axes): principal moments ascending (kg·m², (3,)) and the axes as the columns "
          "of a proper rotation R_BP (3, 3). Repeated moments take axes closest to B's own.")
      .def("check_physical", &MassProperties::check_physical, py::arg("what") = "body",
           "Raises InvalidInertia, naming `what` and the numbers, unless the mass is positive "
           "and finite and the inertia symmetric, positive semi-definite and obeys A + B ≥ C "
           "(each to 1e-9 of the largest moment).")
      .def(py::self + py::self, "The composite of two bodies described in the same frame.")
      .def(py::self += py::self)
      .def(py::self - py::self,
           "Removes a hole described in the same frame; raises InvalidInertia if the remaining "
           "mass is not positive.")
      .def(py::self -= py::self)
      .def("__repr__", &describe);
}

void bind_primitives(py::module_& m) {
  const auto kw = [](const char* name) { return py::arg(name); };
  m.def("point_mass", &inertia::point_mass, py::arg("mass"),
        "A point mass (kg) at the origin: zero inertia about its centre.");
  // Every shape takes mass= (kg) or density= (kg/m, kg/m² or kg/m³ as its dimension says).
#define MOMENTA_SHAPE_1(NAME, ARG, DOC)                                         \
  m.def(                                                                        \
      #NAME,                                                                    \
      [](double a, std::optional<double> mass, std::optional<double> density) { \
        return inertia::NAME(amount_of(#NAME, mass, density), a);               \
      },                                                                        \
      kw(ARG), py::kw_only(), py::arg("mass") = py::none(), py::arg("density") = py::none(), DOC)
#define MOMENTA_SHAPE_2(NAME, ARG1, ARG2, DOC)                                            \
  m.def(                                                                                  \
      #NAME,                                                                              \
      [](double a, double b, std::optional<double> mass, std::optional<double> density) { \
        return inertia::NAME(amount_of(#NAME, mass, density), a, b);                      \
      },                                                                                  \
      kw(ARG1), kw(ARG2), py::kw_only(), py::arg("mass") = py::none(),                    \
      py::arg("density") = py::none(), DOC)
  MOMENTA_SHAPE_1(slender_rod, "length", "A slender rod along z (density in kg/m).");
  MOMENTA_SHAPE_1(thin_ring, "radius", "A thin ring in the xy-plane (density in kg/m).");
  MOMENTA_SHAPE_1(thin_disk, "radius", "A thin disk in the xy-plane (density in kg/m²).");
  MOMENTA_SHAPE_2(annulus, "inner_radius", "outer_radius",
                  "A thin annulus in the xy-plane (density in kg/m²).");
  MOMENTA_SHAPE_2(solid_cylinder, "radius", "length",
                  "A solid cylinder along z (density in kg/m³).");
  MOMENTA_SHAPE_2(cylindrical_shell, "radius", "length",
                  "A thin-walled open tube along z (density in kg/m²).");
  MOMENTA_SHAPE_1(solid_sphere, "radius", "A solid sphere (density in kg/m³).");
  MOMENTA_SHAPE_2(hollow_sphere, "inner_radius", "outer_radius",
                  "A thick spherical shell (density in kg/m³).");
  MOMENTA_SHAPE_1(spherical_shell, "radius", "A thin spherical shell (density in kg/m²).");
  MOMENTA_SHAPE_2(thin_rectangular_plate, "width", "height",
                  "A thin plate, width along x and height along y (density in kg/m²).");
  MOMENTA_SHAPE_2(solid_cone, "base_radius", "height",
                  "A solid right circular cone with its frame's origin at the APEX and the axis "
                  "along +z; centre of mass at z = 3/4 height (density in kg/m³).");
#undef MOMENTA_SHAPE_1
#undef MOMENTA_SHAPE_2
  m.def(
      "hollow_cylinder",
      [](double inner_radius, double outer_radius, double length, std::optional<double> mass,
         std::optional<double> density) {
        return inertia::hollow_cylinder(amount_of("hollow_cylinder", mass, density), inner_radius,
                                        outer_radius, length);
      },
      py::arg("inner_radius"), py::arg("outer_radius"), py::arg("length"), py::kw_only(),
      py::arg("mass") = py::none(), py::arg("density") = py::none(),
      "A thick-walled tube along z (density in kg/m³).");
  m.def(
      "box",
      [](const py::object& size, std::optional<double> mass, std::optional<double> density) {
        return inertia::box(amount_of("box", mass, density), vec3_arg(size, "size"));
      },
      py::arg("size"), py::kw_only(), py::arg("mass") = py::none(), py::arg("density") = py::none(),
      "A solid box with edge lengths size = (x, y, z), m (density in kg/m³).");
  m.def(
      "ellipsoid",
      [](const py::object& semi_axes, std::optional<double> mass, std::optional<double> density) {
        return inertia::ellipsoid(amount_of("ellipsoid", mass, density),
                                  vec3_arg(semi_axes, "semi_axes"));
      },
      py::arg("semi_axes"), py::kw_only(), py::arg("mass") = py::none(),
      py::arg("density") = py::none(),
      "A solid ellipsoid with semi-axes (a, b, c) along x, y, z, m (density in kg/m³).");
}

void bind_files(py::module_& m) {
  m.def(
      "mesh",
      [](const std::filesystem::path& path, std::optional<double> density,
         std::optional<double> mass, double scale, bool shell) {
        return io::read_mesh_mass_properties(path, amount_of("mesh", mass, density), scale, shell);
      },
      py::arg("path"), py::kw_only(), py::arg("density") = py::none(), py::arg("mass") = py::none(),
      py::arg("scale") = 1.0, py::arg("shell") = false,
      R"doc(Exact mass properties of the solid an STL or OBJ mesh bounds (divergence theorem over
its triangles), in the mesh's coordinates times `scale` (0.001 for millimetres). density in kg/m³,
or a total mass; shell=True takes the triangles as a thin sheet of density kg/m² instead (open
meshes allowed). Raises FileError, ParseError or MeshError naming the file.)doc");

  py::class_<io::PartSummary>(m, "PartSummary", "One entry of a part file's parts: list.")
      .def_readonly("name", &io::PartSummary::name)
      .def_readonly("kind", &io::PartSummary::kind,
                    "The shape ('cylinder', 'box', ...), 'mesh' or 'inertia'.")
      .def_readonly("hole", &io::PartSummary::hole, "Subtracted from the composite.")
      .def_readonly("line", &io::PartSummary::line, "1-based line in the file.")
      .def_readonly("mass_properties", &io::PartSummary::mass_properties,
                    "The part alone, placed in the file's frame (a hole's mass positive).")
      .def("__repr__", [](const io::PartSummary& p) {
        return fmt::format("PartSummary(name='{}', kind='{}', hole={}, line={})", p.name, p.kind,
                           p.hole ? "True" : "False", p.line);
      });
  py::class_<io::CompositePart>(m, "CompositePart", "A part file's composite and its parts.")
      .def_readonly("name", &io::CompositePart::name)
      .def_readonly("total", &io::CompositePart::total,
                    "The composite in the file's frame: solids added, holes removed.")
      .def_readonly("parts", &io::CompositePart::parts, "Every part, in file order.")
      .def("__repr__", [](const io::CompositePart& p) {
        return fmt::format("CompositePart(name='{}', {} parts, {})", p.name, p.parts.size(),
                           describe(p.total));
      });
  m.def(
      "part",
      [](const std::filesystem::path& path, std::optional<double> density) {
        io::PartFileOptions options;
        options.default_density = density;
        return io::read_part_file(path, options);
      },
      py::arg("path"), py::kw_only(), py::arg("density") = py::none(),
      "Reads a part file (docs/inertia-format.md) and composes its parts. density= replaces the "
      "file's default density (kg/m³). Raises FileError or ParseError (file:line:column).");
}

}  // namespace

void bind_inertia(py::module_& m) {
  bind_mass_properties(m);
  bind_primitives(m);
  bind_files(m);
}

}  // namespace momenta::python
