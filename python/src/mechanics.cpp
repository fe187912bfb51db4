// The textbook's method from Python: free-body and impulse–momentum diagrams (`momenta
// diagram`), rotating-frame
// kinematics (`momenta kinematics`) and equations of motion in symbols (`momenta equations`),
// each returning what the command prints, as Python values.

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <map>

#include "bindings.hpp"
#include "model_handle.hpp"
#include "momenta/analysis/free_body.hpp"
#include "momenta/analysis/impulse_momentum.hpp"
#include "momenta/dynamics/impulse.hpp"
#include "momenta/dynamics/momentum.hpp"
#include "momenta/dynamics/relative_kinematics.hpp"
#include "momenta/model/euler_coordinates.hpp"
#include "momenta/report/free_body_svg.hpp"
#include "momenta/report/impulse_momentum_svg.hpp"
#include "momenta/simulate/run_request.hpp"
#include "momenta/simulate/state_at.hpp"
#include "momenta/simulate/unilaterals.hpp"
#if MOMENTA_WITH_SYMBOLIC
#include "momenta/symbolic/equations.hpp"
#include "momenta/symbolic/linear_equations.hpp"
#endif
#include "momenta/system/multibody_system.hpp"

namespace momenta::python {

namespace {

// The state (t, q, v) a call looks at: as `--time t` on the command line, the model run from
// its initial state (made consistent with its constraints) to t with its file's simulation
// settings, unless q or v is given (the other then the initial one).
struct Instant {
  double t;
  VecX q, v;
};

Instant instant_of(const ModelHandle& h, const py::object& q, const py::object& v, double t) {
  if (q.is_none() && v.is_none()) {
    const simulate::ResolvedRun run = simulate::resolve_run({}, h.file->simulation);
    const integrate::State s = simulate::state_at(h.model(), t, run.options);
    return {s.t, s.q, s.v};
  }
  Instant s{t, h.model().initial_q(), h.model().initial_v()};
  ArgStorage storage;
  if (!q.is_none()) s.q = vector_arg(q, "q", h.model().nq(), "the model's nq", storage);
  if (!v.is_none()) s.v = vector_arg(v, "v", h.model().nv(), "the model's nv", storage);
  return s;
}

// What every diagram's dict begins with: the body, the instant, its mass, G and the plane.
py::dict diagram_body_dict(const analysis::DiagramBody& d) {
  py::dict out;
  out["body"] = d.body;
  out["t"] = d.t;
  out["mass"] = d.mass;
  out["com"] = to_numpy(d.p_WoG_W);
  out["plane_normal"] =
      d.plane_normal ? py::object(to_numpy(*d.plane_normal)) : py::object(py::none());
  return out;
}

py::dict load_dict(const model::Model& model, const analysis::Load& load) {
  py::dict d;
  d["kind"] = analysis::load_kind_name(load.kind);
  d["name"] = load.name;
  d["description"] = load.description;
  d["point"] = to_numpy(load.p_WoP_W);
  d["force"] = to_numpy(load.force_W);
  d["couple"] = to_numpy(load.couple_W);
  d["joint"] = load.joint_index >= 0 ? py::object(py::str(model.joint(load.joint_index).name))
                                     : py::object(py::none());
  return d;
}

#if MOMENTA_WITH_SYMBOLIC
symbolic::Format format_arg(const std::string& format) {
  if (format == "text") return symbolic::Format::text;
  if (format == "latex") return symbolic::Format::latex;
  throw InvalidArgument(fmt::format("format '{}': expected 'text' or 'latex'", format));
}

// The options, with the names the model file gives its symbols (its `symbols:` section) and
// those given here over them.
symbolic::EquationOptions equation_options(const ModelHandle& h, std::vector<std::string> symbols,
                                           bool all_symbols, bool newton_euler,
                                           bool principal_axes = false,
                                           const std::map<std::string, std::string>& names = {}) {
  symbolic::EquationOptions o;
  o.names = h.file->given_symbol_names();
  for (const auto& [name, given] : names) o.names[name] = given;
  o.symbols = std::move(symbols);
  o.all_symbols = all_symbols;
  o.newton_euler = newton_euler;
  o.principal_axes = principal_axes;
  return o;
}
#endif  // MOMENTA_WITH_SYMBOLIC

}  // namespace

void bind_mechanics(py::module_& m) {
  m.def(
      "free_body_diagram",
      [](const ModelHandle& h, const py::handle& body, const py::object& q, const py::object& v,
         double t) {
        const Instant s = instant_of(h, q, v, t);
        system::MultibodySystem system(h.model());
        const int b = body_index_arg(h, body);
        // The stops and contacts it touches hold, as momenta diagram holds them.
        integrate::State at{s.t, s.q, s.v};
        simulate::hold_what_touches(system, at);
        const analysis::FreeBodyDiagram d =
            analysis::free_body_diagram(system, h.model().body(b).name, at.t, at.q, at.v);
        py::list loads;
        for (const analysis::Load& load : d.loads) loads.append(load_dict(h.model(), load));
        py::dict out = diagram_body_dict(d);
        out["loads"] = loads;
        out["m_a_G"] = to_numpy(d.m_a_G());
        out["I_alpha"] = to_numpy(d.I_alpha());
        out["omega_cross_H"] = to_numpy(d.w_cross_H());
        out["force_residual"] = to_numpy(d.force_residual());
        out["moment_residual"] = to_numpy(d.moment_residual());
        out["svg"] = report::free_body_svg(d, h.file->name);
        return out;
      },
      py::arg("model"), py::arg("body"), py::kw_only(), py::arg("q") = py::none(),
      py::arg("v") = py::none(), py::arg("t") = 0.0,
      R"doc(The body's free-body and kinetic diagrams at (t, q, v) — without q and v, the state
the model's own run reaches at t (its initial state at t = 0) — as `momenta diagram` computes
them: a dict with `loads` (each a dict: kind, name,
description, point, force, couple in the world's axes, and the joint it acts through), the kinetic
terms m_a_G, I_alpha, omega_cross_H, the residuals of ΣF = m a_G and ΣM_G = Ḣ_G, the plane normal
when the diagram is planar, and `svg`, the picture (docs/diagrams.md). The contacts and stops the
mechanism touches hold as a run starting there holds them: a contact the body rests on is one load at
its point, its normal force and friction.)doc");

  m.def(
      "impulse_momentum_diagram",
      [](const ModelHandle& h, const py::handle& body, const py::list& impulses,
         const py::object& q, const py::object& v, double t) {
        const Instant s = instant_of(h, q, v, t);
        std::vector<dynamics::PointImpulse> blow;
        for (const py::handle& item : impulses) {
          const py::tuple hit = py::reinterpret_borrow<py::object>(item).cast<py::tuple>();
          if (hit.size() != 3) {
            throw py::value_error(
                "impulses: a list of (body, point p_BoP_B, impulse in W) triples");
          }
          blow.push_back(
              {body_index_arg(h, hit[0]), vec3_arg(hit[1], "point"), vec3_arg(hit[2], "impulse")});
        }
        const dynamics::ImpulsiveMotion motion =
            dynamics::impulsive_motion(h.model(), s.q, s.v, blow);
        const int b = body_index_arg(h, body);
        const analysis::ImpulseMomentumDiagram d = analysis::impulse_momentum_diagram(
            h.model(), h.model().body(b).name, s.t, s.q, motion, blow, "applied impulse");
        py::list listed;
        for (const analysis::Load& impulse : d.impulses) {
          py::dict item = load_dict(h.model(), impulse);
          item["impulse"] = item["force"];
          item.attr("pop")("force");
          listed.append(item);
        }
        py::dict out = diagram_body_dict(d);
        out["linear_before"] = to_numpy(d.linear_before());
        out["angular_before"] = to_numpy(d.angular_before());
        out["impulses"] = listed;
        out["linear_after"] = to_numpy(d.linear_after());
        out["angular_after"] = to_numpy(d.angular_after());
        out["linear_residual"] = to_numpy(d.linear_residual());
        out["angular_residual"] = to_numpy(d.angular_residual());
        out["svg"] = report::impulse_momentum_svg(d, h.file->name);
        return out;
      },
      py::arg("model"), py::arg("body"), py::arg("impulses"), py::kw_only(),
      py::arg("q") = py::none(), py::arg("v") = py::none(), py::arg("t") = 0.0,
      R"doc(The body's impulse–momentum diagram for impulses applied at (t, q, v) — impulses =
[(body, p_BoP_B, P_W), ...] (N·s), as `momenta diagram --at … --impulse …` draws it: a dict
with the momenta linear_before (m v̄₁), angular_before (H_G1), linear_after, angular_after, the
`impulses` on the body (each a dict: kind, name, description, point, impulse, couple in the
world's axes, and the joint it acts through — the blow and the joints' and constraints'
impulsive reactions), the residuals of m v̄₁ + ΣP = m v̄₂ and H_G1 + ΣM_G = H_G2, the plane
normal when planar, and `svg`, the picture (docs/diagrams.md).)doc");

  m.def(
      "relative_kinematics",
      [](const ModelHandle& h, const py::handle& body, const py::object& point,
         const py::handle& frame, const py::object& q, const py::object& v, double t) {
        const Instant s = instant_of(h, q, v, t);
        system::MultibodySystem system(h.model());
        system.evaluate(s.t, s.q, s.v);
        const int b = body_index_arg(h, body), f = body_index_arg(h, frame);
        const Vec3 p = point.is_none() ? Vec3::Zero() : vec3_arg(point, "point");
        const dynamics::RelativeKinematics k =
            dynamics::relative_kinematics(h.model(), system.data(), b, p, f);
        py::dict out;
        out["omega"] = to_numpy(k.w_WF_F);
        out["omega_dot"] = to_numpy(k.alpha_WF_F);
        out["position"] = to_numpy(k.p_FoP_F);
        out["v_relative"] = to_numpy(k.v_relative);
        out["v_frame_origin"] = to_numpy(k.v_WFo_F);
        out["v_rotation"] = to_numpy(k.v_rotation);
        out["v_absolute"] = to_numpy(k.v_WP_F);
        out["a_relative"] = to_numpy(k.a_relative);
        out["a_frame_origin"] = to_numpy(k.a_WFo_F);
        out["a_euler"] = to_numpy(k.a_euler);
        out["a_centripetal"] = to_numpy(k.a_centripetal);
        out["a_coriolis"] = to_numpy(k.a_coriolis);
        out["a_transport"] = to_numpy(k.a_transport());
        out["a_absolute"] = to_numpy(k.a_WP_F);
        return out;
      },
      py::arg("model"), py::arg("body"), py::kw_only(), py::arg("point") = py::none(),
      py::arg("frame") = "world", py::arg("q") = py::none(), py::arg("v") = py::none(),
      py::arg("t") = 0.0,
      R"doc(The motion of the point `point` (m, in the body's frame; its origin by default) of
`body` seen from the frame of body `frame` at (t, q, v) (without q and v, the state its run
reaches at t), split into relative, frame-origin, Euler, centripetal
and Coriolis terms, every vector in the frame's axes, as `momenta kinematics` gives them
(docs/kinematics.md).)doc");

#if MOMENTA_WITH_SYMBOLIC
  m.def(
      "equations",
      [](const ModelHandle& h, std::vector<std::string> symbols, bool all_symbols,
         const std::string& form, const std::string& format, bool principal_axes, bool greek,
         const std::map<std::string, std::string>& names,
         const std::string& coordinates) -> py::object {
        const bool code = format == "cpp" || format == "python";
        const symbolic::Format f = code ? symbolic::Format::text : format_arg(format);
        if (coordinates != "quaternion" && !coordinates.starts_with("euler:")) {
          throw InvalidArgument(
              fmt::format("coordinates '{}': expected 'quaternion' or 'euler:SEQUENCE' (euler:ZXZ)",
                          coordinates));
        }
        if (form != "lagrange" && form != "newton-euler" && form != "matrix") {
          throw InvalidArgument(
              fmt::format("form '{}': expected 'lagrange', 'matrix' or 'newton-euler'", form));
        }
        symbolic::EquationOptions options = equation_options(
            h, std::move(symbols), all_symbols, form == "newton-euler", principal_axes, names);
        options.greek = greek;
        // Ball and free joints as Euler angles, as `momenta equations --coordinates` writes them.
        const symbolic::Equations e = symbolic::derive_equations(
            coordinates == "quaternion"
                ? h.model()
                : model::with_euler_coordinates(h.model(), coordinates.substr(6)),
            options);
        // The code forms: a C++ header or a Python module computing M and b, as --cpp/--python.
        if (code) {
          return py::str(e.generate_code(
              format == "cpp" ? symbolic::Format::cpp : symbolic::Format::python, h.file->name));
        }
        std::vector<std::string> lines;
        const int free = static_cast<int>(e.free_speeds().size());
        if (form == "matrix") {
          // M(q) v̇ + C(q, v) v + g(q) = Q(q, v, u), entry by entry as --form matrix prints it.
          for (int r = 0; r < free; ++r) {
            for (int c = 0; c < free; ++c)
              lines.push_back(fmt::format("M[{},{}] = {}", r, c, e.mass_matrix_entry(r, c, f)));
          }
          for (int r = 0; r < free; ++r)
            lines.push_back(fmt::format("(C v)[{}] = {}", r, e.velocity_product(r, f)));
          for (int r = 0; r < free; ++r)
            lines.push_back(fmt::format("g[{}] = {}", r, e.gravity(r, f)));
          for (int r = 0; r < free; ++r)
            lines.push_back(fmt::format("Q[{}] = {}", r, e.generalized_force(r, f)));
        } else if (form == "lagrange") {
          for (int r = 0; r < free; ++r) lines.push_back(e.equation(r, f));
        } else {
          for (int r = 0; r < e.newton_euler_rows(); ++r)
            lines.push_back(e.newton_euler_group(r) + ": " + e.newton_euler_equation(r, f));
        }
        if (form != "newton-euler") {
          for (int r = 0; r < e.constraint_rows(); ++r)
            lines.push_back(e.constraint_row_name(r) + ": " + e.constraint_equation(r, f));
        }
        return py::cast(lines);
      },
      py::arg("model"), py::kw_only(), py::arg("symbols") = std::vector<std::string>{},
      py::arg("all_symbols") = false, py::arg("form") = "lagrange", py::arg("format") = "text",
      py::arg("principal_axes") = false, py::arg("greek") = false,
      py::arg("names") = std::map<std::string, std::string>{},
      py::arg("coordinates") = "quaternion",
      R"doc(The model's equations of motion in symbols, one string per equation, as
`momenta equations` prints them: 'lagrange' (one per free speed, each with its constraint forces
G^T lambda, then each constraint row as '<row>: phi = 0' or '<row>: G v = 0'), 'matrix' (the
entries of M(q) v̇ + C(q, v) v + g(q) = Q(q, v, u): 'M[0,0] = …', '(C v)[0] = …', 'g[0] = …',
'Q[0] = …', then the constraint rows, as --form matrix) or 'newton-euler'
(each body's ΣF = m a_G and ΣM_G = Ī α + ω × Ī ω with the joint reactions and constraint
multipliers, prefixed with the body; `principal_axes` writes a body with products of inertia in
its principal axes); 'text' or 'latex' — or 'cpp' / 'python': one string, a C++ header or a
Python module computing M and b from q, v and u (as --cpp / --python). `symbols` names the parameters to keep as symbols
(docs/equations.md); `names` renames parameters and coordinates ({'m_bob': 'm', 'L_bob': 'L'}),
over the model file's `symbols:` section; `greek` writes the revolute joints' angles θ (θ₁, θ₂, …);
coordinates='euler:ZXZ' writes ball and free joints as three Euler angles phi, theta, psi (as
`momenta equations --coordinates`), the default 'quaternion' as the engine integrates them.)doc");

  m.def(
      "_equation_parts",
      [](const ModelHandle& h, std::vector<std::string> symbols, bool all_symbols,
         const std::map<std::string, std::string>& names, const std::string& coordinates) {
        const symbolic::EquationOptions options =
            equation_options(h, std::move(symbols), all_symbols, false, false, names);
        const symbolic::Equations e = symbolic::derive_equations(
            coordinates == "quaternion"
                ? h.model()
                : model::with_euler_coordinates(h.model(), coordinates.substr(6)),
            options);
        constexpr symbolic::Format text = symbolic::Format::text;
        const int free = static_cast<int>(e.free_speeds().size());
        std::vector<std::vector<std::string>> M(static_cast<std::size_t>(free));
        std::vector<std::string> velocity_product, gravity, force, equations;
        for (int r = 0; r < free; ++r) {
          for (int c = 0; c < free; ++c)
            M[static_cast<std::size_t>(r)].push_back(e.mass_matrix_entry(r, c, text));
          velocity_product.push_back(e.velocity_product(r, text));
          gravity.push_back(e.gravity(r, text));
          force.push_back(e.generalized_force(r, text));
          equations.push_back(e.equation(r, text));
        }
        py::list parameters;
        for (const symbolic::Parameter& p : e.parameters()) {
          parameters.append(py::make_tuple(p.name, p.value, p.unit));
        }
        py::dict out;
        out["configuration_names"] = e.configuration_names();
        out["speed_names"] = e.speed_names();
        out["acceleration_names"] = e.acceleration_names();
        out["free_speeds"] = e.free_speeds();
        out["input_names"] = e.input_names();
        out["parameters"] = parameters;
        out["M"] = M;
        out["velocity_product"] = velocity_product;
        out["gravity"] = gravity;
        out["generalized_force"] = force;
        out["equations"] = equations;
        out["constraint_rows"] = e.constraint_rows();
        return out;
      },
      py::arg("model"), py::kw_only(), py::arg("symbols") = std::vector<std::string>{},
      py::arg("all_symbols") = false, py::arg("names") = std::map<std::string, std::string>{},
      py::arg("coordinates") = "quaternion",
      "The matrix form's entries and the equations as text, for equations(format='sympy').");

  m.def(
      "symbolic_transfer_function",
      [](const ModelHandle& h, const std::string& input, const std::string& coordinate, bool rate,
         std::vector<std::string> symbols, bool all_symbols, const py::object& q,
         const py::object& v, double t, const std::string& format) {
        const Instant s = instant_of(h, q, v, t);
        const symbolic::Equations e = symbolic::derive_equations(
            h.model(), equation_options(h, std::move(symbols), all_symbols, false));
        const symbolic::LinearEquations l =
            symbolic::linearize_equations(e, h.model(), s.t, s.q, s.v);
        const auto& inputs = l.input_names();
        const auto& names = l.coordinate_names();
        const auto i = std::find(inputs.begin(), inputs.end(), input);
        const auto k = std::find(names.begin(), names.end(), coordinate);
        if (i == inputs.end() || k == names.end()) {
          throw InvalidArgument(fmt::format(
              "symbolic_transfer_function: input '{}' (the inputs are {}), coordinate '{}' (the "
              "coordinates are {})",
              input, fmt::join(inputs, ", "), coordinate, fmt::join(names, ", ")));
        }
        return l.transfer_function(static_cast<int>(i - inputs.begin()),
                                   static_cast<int>(k - names.begin()), rate, format_arg(format));
      },
      py::arg("model"), py::arg("input"), py::arg("coordinate"), py::kw_only(),
      py::arg("rate") = false, py::arg("symbols") = std::vector<std::string>{},
      py::arg("all_symbols") = false, py::arg("q") = py::none(), py::arg("v") = py::none(),
      py::arg("t") = 0.0, py::arg("format") = "text",
      R"doc(The transfer function in s from a signal to a free coordinate (or its rate) of the
equations linearized in symbols about (t, q, v) (without q and v, the state the model's run
reaches at t), as `momenta equations --transfer` prints it:
'1/(m_car*s+c_road)' for the cruise control's u to road rate (docs/equations.md).)doc");
#endif  // MOMENTA_WITH_SYMBOLIC
}

}  // namespace momenta::python
