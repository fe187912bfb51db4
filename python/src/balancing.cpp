// momenta.inertia's balancing: a rigid rotor's unbalance about its axis, the bearing forces it
// causes, one- and two-plane corrections and the ISO 21940-11 grade check — the functions
// `momenta balance` prints (docs/balancing.md). Rotating vectors are 2-element numpy arrays of
// their components in the rotor-fixed axis frame R.

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <vector>

#include "bindings.hpp"
#include "momenta/inertia/balancing.hpp"

namespace momenta::python {
namespace {

using inertia::CorrectionMass;
using inertia::Unbalance;

Vec2 vec2_arg(const py::handle& object, std::string_view name) {
  ArgStorage storage;
  const auto v = vector_arg(object, name, 2, "a rotating vector's (x, y)", storage);
  return {v[0], v[1]};
}

void bind_results(py::module_& m) {
  py::class_<Unbalance>(m, "Unbalance", R"doc(
A rotor's unbalance about its axis (docs/balancing.md), in the rotor-fixed axis frame R: z along
the axis from the axis point, angles from x_R towards y_R. Rotating vectors are (x, y) arrays.)doc")
      .def_property_readonly(
          "R_BR", [](const Unbalance& u) { return to_numpy(u.R_BR); },
          "The axis frame R in the part frame B (columns x_R, y_R, z_R).")
      .def_readonly("mass", &Unbalance::mass, "kg")
      .def_readonly("axial_com", &Unbalance::axial_com, "z of the centre of mass, m")
      .def_readonly("eccentricity", &Unbalance::eccentricity, "e, m")
      .def_property_readonly(
          "static_unbalance", [](const Unbalance& u) { return to_numpy(u.static_unbalance); },
          "U_s = m (x_cm, y_cm), kg·m")
      .def_property_readonly(
          "products", [](const Unbalance& u) { return to_numpy(u.products); },
          "(P_xz, P_yz) = (∫x z dm, ∫y z dm) about the axis point, kg·m²")
      .def_property_readonly(
          "couple_unbalance", [](const Unbalance& u) { return to_numpy(u.couple_unbalance); },
          "P − z_cm U_s, kg·m²")
      .def_readonly("polar_moment", &Unbalance::polar_moment, "I_zz about the axis, kg·m²")
      .def_readonly("principal_axis_tilt", &Unbalance::principal_axis_tilt,
                    "angle between the axis and the nearest principal axis, rad")
      .def("__repr__", [](const Unbalance& u) {
        return fmt::format("Unbalance(mass={:.6g} kg, |U_s|={:.6g} kg·m, |U_c|={:.6g} kg·m²)",
                           u.mass, u.static_unbalance.norm(), u.couple_unbalance.norm());
      });

  py::class_<CorrectionMass>(m, "CorrectionMass",
                             "A correction mass: its plane z (m) and mass-radius product m·r "
                             "(kg·m) as a rotating vector; add it at that angle.")
      .def(py::init([](double z, const py::handle& mass_radius) {
             return CorrectionMass{z, vec2_arg(mass_radius, "mass_radius")};
           }),
           py::arg("z"), py::arg("mass_radius"))
      .def_readonly("z", &CorrectionMass::z)
      .def_property_readonly("mass_radius",
                             [](const CorrectionMass& c) { return to_numpy(c.mass_radius); })
      .def("mass_at", &CorrectionMass::mass_at, py::arg("radius"),
           "The mass, kg, placed at `radius` (m).")
      .def("__repr__", [](const CorrectionMass& c) {
        return fmt::format("CorrectionMass(z={:.6g} m, m·r={:.6g} kg·m at {:.4g}°)", c.z,
                           c.mass_radius.norm(), inertia::angle_of(c.mass_radius) * 180 / M_PI);
      });

  py::class_<inertia::BearingReactions>(m, "BearingReactions",
                                        "The bearings' forces on the rotor (N, in R) and the "
                                        "drive torque α I_zz (N·m).")
      .def_property_readonly("A", [](const inertia::BearingReactions& r) { return to_numpy(r.A); })
      .def_property_readonly("B", [](const inertia::BearingReactions& r) { return to_numpy(r.B); })
      .def_readonly("drive_torque", &inertia::BearingReactions::drive_torque);

  py::class_<inertia::GradeCheck>(
      m, "GradeCheck",
      "The ISO 21940-11 check: U_per = m G/ω and its allocation to "
      "the bearing planes, the residual unbalance in each, the verdict.")
      .def_readonly("grade", &inertia::GradeCheck::grade, "G, mm/s")
      .def_readonly("omega", &inertia::GradeCheck::omega, "rad/s")
      .def_readonly("permissible", &inertia::GradeCheck::permissible, "U_per, kg·m")
      .def_property_readonly("plane_A",
                             [](const inertia::GradeCheck& g) { return to_numpy(g.plane_A); })
      .def_property_readonly("plane_B",
                             [](const inertia::GradeCheck& g) { return to_numpy(g.plane_B); })
      .def_readonly("permissible_A", &inertia::GradeCheck::permissible_A)
      .def_readonly("permissible_B", &inertia::GradeCheck::permissible_B)
      .def_readonly("overhung", &inertia::GradeCheck::overhung)
      .def_readonly("passed", &inertia::GradeCheck::pass, "both planes within their share");
}

void bind_functions(py::module_& m) {
  m.def(
      "unbalance",
      [](const inertia::MassProperties& part, const py::handle& axis, const py::handle& through) {
        return inertia::unbalance(part, {vec3_arg(through, "through"), vec3_arg(axis, "axis")});
      },
      py::arg("part"), py::kw_only(), py::arg("axis") = std::vector<double>{0.0, 0.0, 1.0},
      py::arg("through") = std::vector<double>{0.0, 0.0, 0.0},
      "The unbalance of `part` (MassProperties in its frame B) about the line through `through` "
      "along `axis` (both in B).");
  m.def(
      "bearing_reactions", &inertia::bearing_reactions, py::arg("rotor"), py::arg("z_A"),
      py::arg("z_B"), py::arg("omega"), py::arg("alpha") = 0.0,
      "The bearings' forces on the rotor at speed omega (rad/s) and acceleration alpha (rad/s²).");
  m.def(
      "static_bearing_loads",
      [](const Unbalance& u, double z_A, double z_B, double g) {
        return to_numpy(inertia::static_bearing_loads(u, z_A, z_B, g));
      },
      py::arg("rotor"), py::arg("z_A"), py::arg("z_B"), py::arg("g") = 9.80665,
      "Upward gravity loads (N) on the bearings of a horizontal shaft, as (A, B).");
  m.def(
      "two_plane_correction",
      [](const Unbalance& u, double z1, double z2) {
        const auto pair = inertia::two_plane_correction(u, z1, z2);
        return std::vector<CorrectionMass>(pair.begin(), pair.end());
      },
      py::arg("rotor"), py::arg("z1"), py::arg("z2"),
      "The two masses in planes z1 ≠ z2 that cancel the static and the couple unbalance.");
  m.def("single_plane_correction", &inertia::single_plane_correction, py::arg("rotor"),
        py::arg("z"), "The mass in plane z cancelling the static unbalance.");
  m.def(
      "with_corrections",
      [](const Unbalance& u, const std::vector<CorrectionMass>& corrections) {
        return inertia::with_corrections(u, corrections);
      },
      py::arg("rotor"), py::arg("corrections"), "The rotor's unbalance with the masses added.");
  m.def("check_grade", &inertia::check_grade, py::arg("rotor"), py::arg("grade"), py::arg("omega"),
        py::arg("z_A"), py::arg("z_B"),
        "The ISO 21940-11 check of grade G (mm/s) at the maximum service speed omega (rad/s).");
}

}  // namespace

void bind_balancing(py::module_& m) {
  bind_results(m);
  bind_functions(m);
}

}  // namespace momenta::python
