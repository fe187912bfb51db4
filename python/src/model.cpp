// Models: momenta.load_model(path) for a model file, momenta.ModelBuilder for one made in code,
// and momenta.Model, what both give: the multibody tree with its outputs and simulation
// settings (a model file's `outputs:` and `simulation:` sections; empty for a built one).

#include <fmt/format.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "model_handle.hpp"
#include "momenta/frontend/model_loading.hpp"
#include "momenta/io/model_export.hpp"
#include "momenta/simulate/state_at.hpp"
#include "momenta/system/freedoms.hpp"

namespace momenta::python {
namespace {

using model::Model;

std::vector<std::string> names_of(const auto& items, auto name) {
  std::vector<std::string> out;
  for (const auto& item : items) out.push_back(name(item));
  return out;
}

py::dict info_of(const ModelHandle& h) {
  const Model& m = h.model();
  py::list bodies, joints, forces, signals;
  for (int b = 1; b < m.num_bodies(); ++b) {
    const model::Body& body = m.body(b);
    py::dict d;
    d["name"] = body.name;
    d["mass"] = body.mass_properties.mass();
    d["center_of_mass"] = to_numpy(body.mass_properties.center_of_mass());
    d["inertia_about_com"] = to_numpy(body.mass_properties.inertia_about_com());
    d["parent"] = m.body(m.parent(b)).name;
    bodies.append(d);
  }
  for (const model::Joint& joint : m.joints()) {
    py::dict d;
    d["name"] = joint.name;
    d["type"] = std::string(model::joint_type_name(joint.type));
    d["parent"] = joint.parent;
    d["child"] = joint.child;
    py::list q, v;
    for (int i = 0; i < joint.nq(); ++i) q.append(m.q_name(joint.q_index + i));
    for (int i = 0; i < joint.nv(); ++i) v.append(m.v_name(joint.v_index + i));
    d["coordinates"] = q;
    d["velocities"] = v;
    d["prescribed"] = joint.is_prescribed();
    joints.append(d);
  }
  for (const auto& element : m.force_elements()) forces.append(model::force_element_name(element));
  for (const auto& signal : m.signals()) signals.append(signal.name());
  py::dict info;
  info["name"] = h.file->name;
  info["description"] = h.file->description;
  info["nq"] = m.nq();
  info["nv"] = m.nv();
  info["total_mass"] = m.total_mass();
  info["gravity"] = to_numpy(m.gravity());
  info["bodies"] = bodies;
  info["joints"] = joints;
  info["force_elements"] = forces;
  info["signals"] = signals;
  py::list keyframes;  // an MJCF file's named states, as momenta's q and v
  for (const io::Keyframe& key : h.file->keyframes) {
    py::dict d;
    d["name"] = key.name;
    d["time"] = key.time;
    d["q"] = to_numpy(key.q);
    d["v"] = to_numpy(key.v);
    keyframes.append(d);
  }
  info["keyframes"] = keyframes;
  return info;
}

void bind_model_class(py::module_& m) {
  py::class_<ModelHandle>(m, "Model", R"doc(
A multibody model: a tree of bodies joined by joints, gravity, force elements and signals, with
the outputs and simulation settings its model file gives. Immutable. Coordinates are stacked in
joint order — the file's, depth first, as MuJoCo's qpos — q (nq, quaternions as w, x, y, z) and v
(nv); names in q_names and v_names.)doc")
      .def_property_readonly("name", [](const ModelHandle& h) { return h.file->name; })
      .def_property_readonly("description",
                             [](const ModelHandle& h) { return h.file->description; })
      .def_property_readonly(
          "file", [](const ModelHandle& h) { return h.file->file; },
          "The file it was read from ('' for a built model).")
      .def_property_readonly(
          "nq", [](const ModelHandle& h) { return h.model().nq(); }, "Size of the configuration q.")
      .def_property_readonly(
          "nv", [](const ModelHandle& h) { return h.model().nv(); },
          "Size of the velocity v (the joints' speeds, before prescribed motion and constraints "
          "take theirs: see degrees_of_freedom).")
      .def_property_readonly(
          "degrees_of_freedom",
          [](const ModelHandle& h) { return system::count_freedoms(h.model()).free(); },
          "Independent speeds left once prescribed joints and constraints take theirs: nv − "
          "prescribed − independent constraint rows (a four-bar: 1; driven by its crank: 0).")
      .def_property_readonly(
          "q_names",
          [](const ModelHandle& h) {
            std::vector<std::string> out;
            for (int i = 0; i < h.model().nq(); ++i) out.push_back(h.model().q_name(i));
            return out;
          },
          "Names of the configuration coordinates: 'hinge.angle', 'base.qw', ...")
      .def_property_readonly(
          "v_names",
          [](const ModelHandle& h) {
            std::vector<std::string> out;
            for (int i = 0; i < h.model().nv(); ++i) out.push_back(h.model().v_name(i));
            return out;
          },
          "Names of the velocity coordinates.")
      .def_property_readonly(
          "body_names",
          [](const ModelHandle& h) {
            return names_of(h.model().bodies(), [](const auto& b) { return b.name; });
          },
          "Body names, 'world' first (index 0).")
      .def_property_readonly(
          "joint_names",
          [](const ModelHandle& h) {
            return names_of(h.model().joints(), [](const auto& j) { return j.name; });
          },
          "Joint names; joint j carries body j + 1.")
      .def_property_readonly("signal_names",
                             [](const ModelHandle& h) {
                               return names_of(h.model().signals(),
                                               [](const auto& s) { return s.name(); });
                             })
      .def_property_readonly("force_element_names",
                             [](const ModelHandle& h) {
                               return names_of(h.model().force_elements(), [](const auto& e) {
                                 return model::force_element_name(e);
                               });
                             })
      .def_property_readonly(
          "output_names",
          [](const ModelHandle& h) {
            return names_of(h.file->outputs, [](const auto& o) { return o.name; });
          },
          "The model file's outputs (their column stems).")
      .def_property_readonly(
          "gravity", [](const ModelHandle& h) { return to_numpy(h.model().gravity()); },
          "Gravitational acceleration in the world frame, m/s².")
      .def_property_readonly(
          "total_mass", [](const ModelHandle& h) { return h.model().total_mass(); }, "kg.")
      .def_property_readonly(
          "initial_q", [](const ModelHandle& h) { return to_numpy(h.model().initial_q()); },
          "The initial configuration (each joint's q0).")
      .def_property_readonly(
          "initial_v", [](const ModelHandle& h) { return to_numpy(h.model().initial_v()); },
          "The initial velocity (each joint's v0).")
      .def(
          "body_index",
          [](const ModelHandle& h, const std::string& name) { return h.model().body_index(name); },
          py::arg("name"), "Index of a body; raises InvalidArgument with a did-you-mean.")
      .def(
          "joint_index",
          [](const ModelHandle& h, const std::string& name) { return h.model().joint_index(name); },
          py::arg("name"))
      .def(
          "body_mass_properties",
          [](const ModelHandle& h, const py::object& body) {
            return h.model().body(body_index_arg(h, body)).mass_properties;
          },
          py::arg("body"), "A body's mass properties in its own frame (by name or index).")
      .def(
          "neutral_q", [](const ModelHandle& h) { return to_numpy(model::neutral(h.model())); },
          "The neutral configuration: zero angles and displacements, identity quaternions.")
      .def("info", &info_of,
           "A dict describing the model: name, sizes, bodies (mass, centre of mass, inertia, "
           "parent), joints (type, parent, child, coordinate names), force elements, signals.")
      .def("__repr__", [](const ModelHandle& h) {
        return fmt::format("<momenta.Model '{}': {} bodies, {} joints, nq={}, nv={}>", h.file->name,
                           h.model().num_bodies() - 1, h.model().num_joints(), h.model().nq(),
                           h.model().nv());
      });

  m.def(
      "load_model",
      [](const std::filesystem::path& path, const std::vector<std::filesystem::path>& package_path,
         std::optional<double> link_density, std::optional<std::string> keyframe) {
        io::ModelFileOptions options;
        options.package_path = package_path;
        options.link_density = link_density;
        options.keyframe = std::move(keyframe);
        return ModelHandle{
            std::make_shared<const io::ModelFile>(frontend::load_model(path, options))};
      },
      py::arg("path"), py::kw_only(),
      py::arg("package_path") = std::vector<std::filesystem::path>{},
      py::arg("link_density") = py::none(), py::arg("keyframe") = py::none(),
      R"doc(Reads a model file — momenta's YAML (docs/model-format.md), URDF (.urdf) or MJCF
(.xml, .mjcf; docs/model-formats.md) — builds it and checks that it can be simulated, as
`momenta simulate` does. For a URDF: `package_path`, folders holding the packages its
package://NAME/... meshes name (ROS_PACKAGE_PATH is searched after), and `link_density` (kg/m³),
filling the collision (else visual) geometry of each link without <inertial> to give it mass.
For an MJCF file: `keyframe`, the name of a <keyframe><key> whose qpos and qvel become the initial
state (as `momenta --keyframe`; model.info()['keyframes'] lists them). Raises ParseError ('file:line:column: message', with .file, .line and .column) for anything wrong
in it, FileError when it cannot be read, InvalidArgument for a link_density that is not positive
and finite or a keyframe the file does not have.)doc");

  // What a format does not keep is said as a Python warning, one per load.
  const auto exported = [](const io::ExportedModel& written) {
    const py::object warn = py::module_::import("warnings").attr("warn");
    for (const std::string& lost : written.not_written) warn(fmt::format("not written: {}", lost));
    return written.text;
  };
  m.def(
      "to_mjcf",
      [exported](const ModelHandle& h) {
        return exported(io::write_mjcf(*h.file, simulate::state_at(h.model(), 0.0, {}).q));
      },
      py::arg("model"),
      R"doc(The model as MJCF text for MuJoCo, drawn in its consistent initial state, as
`momenta export --mjcf` writes it (docs/model-formats.md, "Writing models"). Loads MJCF does not
keep are warned about; raises InvalidArgument for what it cannot keep (a rolling contact).)doc");
  m.def(
      "to_urdf", [exported](const ModelHandle& h) { return exported(io::write_urdf(*h.file)); },
      py::arg("model"),
      R"doc(The model as URDF text, as `momenta export --urdf` writes it. Raises InvalidArgument
for what URDF cannot keep (a ball joint, a loop).)doc");
}

}  // namespace

int body_index_arg(const ModelHandle& h, const py::handle& body) {
  if (py::isinstance<py::str>(body)) return h.model().body_index(body.cast<std::string>());
  if (py::isinstance<py::int_>(body)) {
    const int b = body.cast<int>();
    if (b < 0 || b >= h.model().num_bodies()) {
      throw py::index_error(
          fmt::format("body index {} is out of range (the model has {} bodies, "
                      "the world 0 included)",
                      b, h.model().num_bodies()));
    }
    return b;
  }
  throw py::type_error("body: expected a body name (str) or index (int)");
}

void bind_model(py::module_& m) {
  bind_model_class(m);
  bind_model_builder(m);
}

}  // namespace momenta::python
