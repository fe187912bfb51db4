// momenta.Workspace: the dynamics algorithms on one model with numpy state. A workspace holds
// the preallocated dynamics::Data, so a loop of calls allocates only the arrays it returns.

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "model_handle.hpp"
#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/aba_derivatives.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/data.hpp"
#include "momenta/dynamics/energy.hpp"
#include "momenta/dynamics/impulse.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/dynamics/momentum.hpp"
#include "momenta/dynamics/point_kinematics.hpp"
#include "momenta/dynamics/reactions.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta/dynamics/rnea_derivatives.hpp"

namespace momenta::python {
namespace {

using Storage = ArgStorage;

struct Workspace {
  explicit Workspace(ModelHandle h) : handle(std::move(h)), data(handle.model()) {}
  ModelHandle handle;
  dynamics::Data data;
  std::vector<Vec6> wrenches;  // external wrenches, one per body, when given

  const model::Model& model() const { return handle.model(); }

  // The state arguments as views (no copy for float64 contiguous arrays).
  Eigen::Map<const VecX> q(const py::handle& x, Storage& s) const {
    return vector_arg(x, "q", model().nq(), "the model's nq", s);
  }
  Eigen::Map<const VecX> v(const py::handle& x, const char* name, Storage& s) const {
    return vector_arg(x, name, model().nv(), "the model's nv", s);
  }

  // f_ext: None, or num_bodies × 6 wrenches [moment; force] on each body in B about Bo.
  std::span<const Vec6> external(const py::object& f_ext) {
    if (f_ext.is_none()) return {};
    const MatX f = matrix_arg(f_ext, "f_ext", model().num_bodies(), 6);
    wrenches.resize(model().num_bodies());
    for (int b = 0; b < model().num_bodies(); ++b) wrenches[b] = f.row(b).transpose();
    return wrenches;
  }

  // The body's pose after forward_kinematics: (R_WB, p_WoBo_W).
  py::tuple pose(int b) const {
    return py::make_tuple(to_numpy(data.X_WB[b].R), to_numpy(data.X_WB[b].p));
  }
};

// The state arguments of a call over a batch: each one vector of its size, or an (N, size) array
// of N rows (every 2-D argument the same N); a vector is used for every row.
class BatchArguments {
 public:
  // Adds an argument; returns its index for row().
  int add(const py::handle& object, const char* name, Eigen::Index size, const char* what) {
    auto array = as_float_array(object, name);
    const bool matrix = array.ndim() == 2;
    const py::ssize_t width = matrix ? array.shape(1) : array.ndim() == 1 ? array.shape(0) : -1;
    if (width != size || array.ndim() > 2) {
      std::vector<py::ssize_t> shape(array.shape(), array.shape() + array.ndim());
      throw py::value_error(fmt::format(
          "{}: expected a vector of {} numbers ({}) or an (N, {}) array of N of them, got shape "
          "({}{})",
          name, size, what, size, fmt::join(shape, ", "), shape.size() == 1 ? "," : ""));
    }
    if (matrix) {
      if (rows_ >= 0 && array.shape(0) != rows_) {
        throw py::value_error(
            fmt::format("{}: {} rows, where {} has {}: a batch's arguments "
                        "have one row per state",
                        name, array.shape(0), first_batched_, rows_));
      }
      if (rows_ < 0) first_batched_ = name;
      rows_ = array.shape(0);
    }
    arrays_.push_back(std::move(array));
    return static_cast<int>(arrays_.size()) - 1;
  }
  /// True when some argument has rows.
  bool batched() const { return rows_ >= 0; }
  py::ssize_t rows() const { return rows_; }
  /// Argument k at row i (the vector itself when it has no rows).
  Eigen::Map<const VecX> row(int k, py::ssize_t i) const {
    const auto& a = arrays_[static_cast<std::size_t>(k)];
    const py::ssize_t n = a.shape(a.ndim() - 1);
    return {a.data() + (a.ndim() == 2 ? i * n : 0), static_cast<Eigen::Index>(n)};
  }

 private:
  std::vector<py::array_t<double, py::array::c_style>> arrays_;
  py::ssize_t rows_ = -1;
  const char* first_batched_ = "";
};

// `each(i, out)` over the N rows of a batch into an (N, width) array (an (N, width, width) one
// when `square`): one row of results per row of arguments.
template <class Each>
py::array_t<double> over_rows(const BatchArguments& args, Eigen::Index width, bool square,
                              Each each) {
  const py::ssize_t n = args.rows();
  const auto w = static_cast<py::ssize_t>(width);
  py::array_t<double> out = square ? py::array_t<double>({n, w, w}) : new_float_array(n, w);
  const py::ssize_t stride = square ? w * w : w;
  for (py::ssize_t i = 0; i < n; ++i) each(i, out.mutable_data() + i * stride);
  return out;
}

// aba or rnea, `algorithm(q, v, third, f_ext)` (third: tau or vdot), on one state or on each row
// of a batch: a vector of nv, or an (N, nv) array.
template <class Algorithm>
py::array_t<double> per_state(Workspace& w, const py::handle& q, const py::handle& v,
                              const py::handle& third, const char* third_name,
                              const py::object& f_ext, Algorithm algorithm) {
  const model::Model& model = w.model();
  BatchArguments args;
  const int kq = args.add(q, "q", model.nq(), "the model's nq");
  const int kv = args.add(v, "v", model.nv(), "the model's nv");
  const int kt = args.add(third, third_name, model.nv(), "the model's nv");
  const auto f = w.external(f_ext);
  if (!args.batched())
    return to_numpy(algorithm(args.row(kq, 0), args.row(kv, 0), args.row(kt, 0), f));
  return over_rows(args, model.nv(), false, [&](py::ssize_t i, double* out) {
    Eigen::Map<VecX>(out, model.nv()) =
        algorithm(args.row(kq, i), args.row(kv, i), args.row(kt, i), f);
  });
}

py::dict point_kinematics_dict(const dynamics::PointKinematics& k) {
  py::dict d;
  d["position"] = to_numpy(k.p_WoP_W);
  d["velocity"] = to_numpy(k.v_WP_W);
  d["acceleration"] = to_numpy(k.a_WP_W);
  d["origin_acceleration"] = to_numpy(k.a_WBo_W);
  d["tangential"] = to_numpy(k.tangential);
  d["centripetal"] = to_numpy(k.centripetal);
  d["from_vdot"] = to_numpy(k.from_vdot);
  d["velocity_product"] = to_numpy(k.velocity_product);
  return d;
}

model::ReactionFrame reaction_frame(const std::string& frame) {
  if (frame == "world") return model::ReactionFrame::world;
  if (frame == "joint") return model::ReactionFrame::joint;
  if (frame == "child") return model::ReactionFrame::child;
  if (frame == "parent") return model::ReactionFrame::parent;
  throw InvalidArgument(
      fmt::format("frame '{}': expected world, joint (J'), child or parent", frame));
}

}  // namespace

void bind_dynamics(py::module_& m) {
  py::class_<Workspace>(m, "Workspace", R"doc(
The dynamics algorithms on one model (Featherstone 2008), with a preallocated workspace so a
loop of calls does not allocate beyond the arrays returned. States are numpy arrays (any real
array-like): q of size nq, v, vdot and tau of size nv; f_ext, where taken, is None or a
(num_bodies, 6) array of wrenches [moment; force] on each body, in the body frame about its
origin (row 0, the world, is ignored). Wrong sizes raise ValueError naming the argument.
Results are new arrays. Not thread-safe: one workspace per thread.)doc")
      .def(py::init<ModelHandle>(), py::arg("model"))
      .def_property_readonly("model", [](const Workspace& w) { return w.handle; })
      .def("__repr__",
           [](const Workspace& w) {
             return fmt::format(
                 "<momenta.Workspace of '{}': nq {}, nv {}, {} bodies; aba, rnea, crba, "
                 "forward_kinematics, …>",
                 w.handle.file->name, w.model().nq(), w.model().nv(),
                 w.model().bodies().size() - 1);
           })
      .def(
          "aba",
          [](Workspace& w, const py::handle& q, const py::handle& v, const py::handle& tau,
             const py::object& f_ext) {
            return per_state(w, q, v, tau, "tau", f_ext, [&w](auto&&... args) -> const VecX& {
              return dynamics::aba(w.model(), w.data, args...);
            });
          },
          py::arg("q"), py::arg("v"), py::arg("tau"), py::arg("f_ext") = py::none(),
          "Forward dynamics by the articulated-body algorithm: v̇ = M⁻¹ (τ − C v − g + Jᵀ f_ext). "
          "Every joint is driven by its τ (prescription and force elements are the simulator's). "
          "Batched: q, v, tau may be (N, n) arrays of N states (a vector is used for every row); "
          "the result is then (N, nv), one call's v̇ per row.")
      .def(
          "rnea",
          [](Workspace& w, const py::handle& q, const py::handle& v, const py::handle& vdot,
             const py::object& f_ext) {
            return per_state(w, q, v, vdot, "vdot", f_ext, [&w](auto&&... args) -> const VecX& {
              return dynamics::rnea(w.model(), w.data, args...);
            });
          },
          py::arg("q"), py::arg("v"), py::arg("vdot"), py::arg("f_ext") = py::none(),
          "Inverse dynamics by recursive Newton–Euler: τ = M v̇ + C v + g − Jᵀ f_ext. Batched as "
          "aba: (N, n) arrays give (N, nv).")
      .def(
          "aba_derivatives",
          [](Workspace& w, const py::handle& q, const py::handle& v, const py::handle& tau,
             const py::object& f_ext) {
            Storage sq, sv, st;
            dynamics::aba_derivatives(w.model(), w.data, w.q(q, sq), w.v(v, "v", sv),
                                      w.v(tau, "tau", st), w.external(f_ext));
            return py::make_tuple(to_numpy(w.data.dvdot_dq), to_numpy(w.data.dvdot_dv),
                                  to_numpy(w.data.Minv));
          },
          py::arg("q"), py::arg("v"), py::arg("tau"), py::arg("f_ext") = py::none(),
          "(∂v̇/∂q, ∂v̇/∂v, M⁻¹), each (nv, nv), of v̇ = aba(q, v, tau), analytically (Carpentier "
          "& Mansard 2018). ∂/∂q is along the configuration's tangent, one column per velocity "
          "coordinate (a ball joint's rotation vector in its child frame); f_ext is held in its "
          "bodies.")
      .def(
          "rnea_derivatives",
          [](Workspace& w, const py::handle& q, const py::handle& v, const py::handle& vdot,
             const py::object& f_ext) {
            Storage sq, sv, sa;
            dynamics::rnea_derivatives(w.model(), w.data, w.q(q, sq), w.v(v, "v", sv),
                                       w.v(vdot, "vdot", sa), w.external(f_ext));
            return py::make_tuple(to_numpy(w.data.dtau_dq), to_numpy(w.data.dtau_dv),
                                  to_numpy(w.data.M));
          },
          py::arg("q"), py::arg("v"), py::arg("vdot"), py::arg("f_ext") = py::none(),
          "(∂τ/∂q, ∂τ/∂v, M), each (nv, nv), of τ = rnea(q, v, vdot), analytically (Carpentier & "
          "Mansard 2018); ∂/∂q along the configuration's tangent, f_ext held in its bodies.")
      .def(
          "crba",
          [](Workspace& w, const py::handle& q) -> py::array_t<double> {
            const model::Model& model = w.model();
            BatchArguments args;
            const int kq = args.add(q, "q", model.nq(), "the model's nq");
            if (!args.batched()) return to_numpy(dynamics::crba(model, w.data, args.row(kq, 0)));
            using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
            return over_rows(args, model.nv(), true, [&](py::ssize_t i, double* out) {
              Eigen::Map<RowMajor>(out, model.nv(), model.nv()) =
                  dynamics::crba(model, w.data, args.row(kq, i));
            });
          },
          py::arg("q"),
          "The joint-space mass matrix M(q) (nv × nv) by the composite-rigid-body "
          "algorithm; kinetic energy ½ vᵀ M v. Batched: q an (N, nq) array gives (N, nv, nv).")
      .def(
          "nonlinear_effects",
          [](Workspace& w, const py::handle& q, const py::handle& v) {
            Storage sq, sv;
            return to_numpy(
                dynamics::nonlinear_effects(w.model(), w.data, w.q(q, sq), w.v(v, "v", sv)));
          },
          py::arg("q"), py::arg("v"), "Bias forces C(q, v) v + g(q).")
      .def(
          "generalized_gravity",
          [](Workspace& w, const py::handle& q) {
            Storage sq;
            return to_numpy(dynamics::generalized_gravity(w.model(), w.data, w.q(q, sq)));
          },
          py::arg("q"), "Generalized gravity g(q) = ∂V/∂q.")
      .def(
          "joint_reactions",
          [](Workspace& w, const py::handle& q, const py::handle& v, const py::handle& vdot,
             const std::string& frame, const py::object& f_ext) {
            Storage sq, sv, sa;
            const auto f = w.external(f_ext);
            dynamics::joint_reactions(w.model(), w.data, w.q(q, sq), w.v(v, "v", sv),
                                      w.v(vdot, "vdot", sa), f);
            const model::ReactionFrame in = reaction_frame(frame);
            const int nj = w.model().num_joints();
            MatX forces(nj, 3), moments(nj, 3);
            for (int j = 0; j < nj; ++j) {
              const dynamics::JointReaction r = dynamics::joint_reaction(w.model(), w.data, j, in);
              forces.row(j) = r.force.transpose();
              moments.row(j) = r.moment.transpose();
            }
            return py::make_tuple(to_numpy(forces), to_numpy(moments));
          },
          py::arg("q"), py::arg("v"), py::arg("vdot"), py::arg("frame") = "world",
          py::arg("f_ext") = py::none(),
          "(forces, moments), each (num_joints, 3): the wrench each joint transmits from its "
          "parent to its child for the motion (q, v, vdot), the moment about the child-side "
          "joint frame's origin, expressed in `frame` (world, joint, child or parent).")
      .def(
          "impulsive_motion",
          [](Workspace& w, const py::handle& q, const py::handle& v, const py::list& impulses) {
            Storage sq, sv;
            std::vector<dynamics::PointImpulse> hits;
            for (const py::handle& item : impulses) {
              const py::tuple t = py::reinterpret_borrow<py::object>(item).cast<py::tuple>();
              if (t.size() != 3) {
                throw py::value_error(
                    "impulses: a list of (body, point p_BoP_B, impulse in W) triples");
              }
              hits.push_back({body_index_arg(w.handle, t[0]), vec3_arg(t[1], "point"),
                              vec3_arg(t[2], "impulse")});
            }
            const dynamics::ImpulsiveMotion r =
                dynamics::impulsive_motion(w.model(), w.q(q, sq), w.v(v, "v", sv), hits);
            const int nj = w.model().num_joints();
            MatX forces(nj, 3), moments(nj, 3);
            for (int j = 0; j < nj; ++j) {
              forces.row(j) = r.joint_impulses[static_cast<std::size_t>(j)].force.transpose();
              moments.row(j) = r.joint_impulses[static_cast<std::size_t>(j)].moment.transpose();
            }
            py::dict out;
            out["v_after"] = to_numpy(r.v_after);
            out["joint_impulse_forces"] = to_numpy(forces);
            out["joint_impulse_moments"] = to_numpy(moments);
            out["constraint_impulses"] = to_numpy(r.constraint_impulses);
            out["redundant_rows"] = r.redundant_rows;
            out["drive_impulses"] = to_numpy(r.drive_impulses);
            out["kinetic_before"] = r.kinetic_before;
            out["kinetic_after"] = r.kinetic_after;
            out["impulse_work"] = r.impulse_work;
            return out;
          },
          py::arg("q"), py::arg("v"), py::arg("impulses"),
          "Impulse and momentum (docs/contacts.md): the speeds just after impulses applied at "
          "body points, impulses = [(body, p_BoP_B, P_W), ...] (N·s); returns a dict with "
          "v_after, the joints' impulses (joint_impulse_forces, joint_impulse_moments: "
          "(num_joints, 3), in W about J'o), constraint_impulses (per row), redundant_rows, "
          "drive_impulses, kinetic_before, kinetic_after and impulse_work (Kelvin's theorem: "
          "equals the energy change).")
      .def(
          "restitution_impact",
          [](Workspace& w, const py::handle& q, const py::handle& v, const py::object& body_a,
             const py::handle& point_a, const py::object& body_b, const py::handle& point_b,
             const py::handle& normal, double restitution) {
            Storage sq, sv;
            const dynamics::PointContact contact{
                body_index_arg(w.handle, body_a), vec3_arg(point_a, "point_a"),
                body_index_arg(w.handle, body_b), vec3_arg(point_b, "point_b"),
                vec3_arg(normal, "normal")};
            const dynamics::Impact impact = dynamics::restitution_impact(
                w.model(), w.q(q, sq), w.v(v, "v", sv), contact, restitution);
            py::dict out;
            out["normal_impulse"] = impact.normal_impulse;
            out["approach_speed"] = impact.approach_speed;
            out["separation_speed"] = impact.separation_speed;
            out["v_after"] = to_numpy(impact.motion.v_after);
            MatX forces(w.model().num_joints(), 3);
            for (int j = 0; j < w.model().num_joints(); ++j) {
              forces.row(j) =
                  impact.motion.joint_impulses[static_cast<std::size_t>(j)].force.transpose();
            }
            out["joint_impulse_forces"] = to_numpy(forces);
            out["kinetic_before"] = impact.motion.kinetic_before;
            out["kinetic_after"] = impact.motion.kinetic_after;
            return out;
          },
          py::arg("q"), py::arg("v"), py::arg("body_a"), py::arg("point_a"), py::arg("body_b"),
          py::arg("point_b"), py::arg("normal"), py::arg("restitution"),
          "A frictionless collision of body_a's and body_b's points (body_a may be 'world'; "
          "body_b is pushed along the unit normal) by Newton's restitution (docs/contacts.md): "
          "a dict of normal_impulse, approach_speed, separation_speed, v_after, "
          "joint_impulse_forces, kinetic_before, kinetic_after.")
      .def(
          "forward_kinematics",
          [](Workspace& w, const py::handle& q, const py::object& v, const py::object& vdot) {
            Storage sq, sv, sa;
            if (v.is_none() && !vdot.is_none()) {
              throw py::value_error("vdot: give v as well (the accelerations need velocities)");
            }
            if (v.is_none()) {
              dynamics::forward_kinematics(w.model(), w.data, w.q(q, sq));
            } else if (vdot.is_none()) {
              dynamics::forward_kinematics(w.model(), w.data, w.q(q, sq), w.v(v, "v", sv));
            } else {
              dynamics::forward_kinematics(w.model(), w.data, w.q(q, sq), w.v(v, "v", sv),
                                           w.v(vdot, "vdot", sa));
            }
          },
          py::arg("q"), py::arg("v") = py::none(), py::arg("vdot") = py::none(),
          "Poses (and velocities, accelerations) of every body; read them with body_pose, "
          "body_velocity, body_acceleration.")
      .def(
          "body_pose",
          [](const Workspace& w, const py::object& body) {
            return w.pose(body_index_arg(w.handle, body));
          },
          py::arg("body"),
          "(R_WB (3, 3), p_WoBo_W (3,)) after forward_kinematics; body by name or index.")
      .def(
          "body_velocity",
          [](const Workspace& w, const py::object& body) {
            const Vec6 V = dynamics::body_velocity_in_world(w.data, body_index_arg(w.handle, body));
            return to_numpy(V);
          },
          py::arg("body"), "[w_WB_W; v_WBo_W] (6,) after forward_kinematics with v.")
      .def(
          "body_acceleration",
          [](const Workspace& w, const py::object& body) {
            const Vec6 A =
                dynamics::body_acceleration_in_world(w.data, body_index_arg(w.handle, body));
            return to_numpy(A);
          },
          py::arg("body"),
          "[alpha_WB_W; a_WBo_W] (6,), the classical acceleration of Bo, after "
          "forward_kinematics with v and vdot.")
      .def(
          "point_kinematics",
          [](Workspace& w, const py::object& body, const py::object& point, const py::handle& q,
             const py::handle& v, const py::handle& vdot) {
            Storage sq, sv, sa;
            const int b = body_index_arg(w.handle, body);
            return point_kinematics_dict(
                dynamics::point_kinematics(w.model(), w.data, w.q(q, sq), w.v(v, "v", sv),
                                           w.v(vdot, "vdot", sa), b, vec3_arg(point, "point")));
          },
          py::arg("body"), py::arg("point"), py::arg("q"), py::arg("v"), py::arg("vdot"),
          "Motion of the point p_BoP_B fixed in `body`, in W: a dict of position, velocity, "
          "acceleration, and the acceleration's terms (origin_acceleration + tangential + "
          "centripetal, or from_vdot + velocity_product).")
      .def(
          "frame_jacobian",
          [](Workspace& w, const py::object& body, const py::object& point, const py::handle& q) {
            Storage sq;
            const int b = body_index_arg(w.handle, body);
            dynamics::forward_kinematics(w.model(), w.data, w.q(q, sq));
            MatX J(6, w.model().nv());
            dynamics::frame_jacobian(w.model(), w.data, b, vec3_arg(point, "point"), J);
            return to_numpy(J);
          },
          py::arg("body"), py::arg("point"), py::arg("q"),
          "The 6 × nv Jacobian of `body` at the point p_BoP_B, world-aligned: "
          "[w_WB_W; v_WP_W] = J v.")
      .def(
          "kinetic_energy",
          [](Workspace& w, const py::handle& q, const py::handle& v) {
            Storage sq, sv;
            return dynamics::kinetic_energy(w.model(), w.data, w.q(q, sq), w.v(v, "v", sv));
          },
          py::arg("q"), py::arg("v"), "T = ½ vᵀ M v, J.")
      .def(
          "potential_energy",
          [](Workspace& w, const py::handle& q) {
            Storage sq;
            return dynamics::potential_energy(w.model(), w.data, w.q(q, sq));
          },
          py::arg("q"), "Gravitational potential energy −Σ m g · p_cm, J (springs excluded).")
      .def(
          "center_of_mass",
          [](Workspace& w, const py::handle& q) {
            Storage sq;
            return to_numpy(dynamics::center_of_mass(w.model(), w.data, w.q(q, sq)));
          },
          py::arg("q"), "The system's centre of mass in W, m.")
      .def(
          "momentum",
          [](Workspace& w, const py::handle& q, const py::handle& v) {
            Storage sq, sv;
            const dynamics::Momentum p =
                dynamics::momentum(w.model(), w.data, w.q(q, sq), w.v(v, "v", sv));
            py::dict d;
            d["mass"] = p.mass;
            d["center_of_mass"] = to_numpy(p.p_WoScm_W);
            d["center_of_mass_velocity"] = to_numpy(p.v_WScm_W);
            d["linear"] = to_numpy(p.linear);
            d["angular_about_com"] = to_numpy(p.angular_about_com);
            return d;
          },
          py::arg("q"), py::arg("v"),
          "A dict: mass, center_of_mass, center_of_mass_velocity, linear momentum and angular "
          "momentum about the centre of mass, in W.");
}

}  // namespace momenta::python
