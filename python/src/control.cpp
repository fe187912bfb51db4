// Control design from Python: c2d, LQR (continuous and discrete), controllability and
// observability, and the Lyapunov and Riccati solvers behind them. Each takes a momenta
// StateSpace, a LinearModel, or a scipy / python-control state space (state_space_arg).

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/complex.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "momenta/analysis/controllability.hpp"
#include "momenta/analysis/discretize.hpp"
#include "momenta/analysis/lqr.hpp"
#include "momenta/analysis/matrix_equations.hpp"
#include "momenta/analysis/pole_placement.hpp"
#include "momenta/analysis/root_locus.hpp"
#include "momenta/analysis/state_space.hpp"
#include "momenta/common/number_text.hpp"

namespace momenta::python {
namespace {

using namespace analysis;

// A weight argument: a matrix, or a vector / list taken as the diagonal, or a scalar times I.
MatX weight_arg(const py::object& object, const char* name, Eigen::Index size) {
  if (py::isinstance<py::float_>(object) || py::isinstance<py::int_>(object)) {
    return object.cast<double>() * MatX::Identity(size, size);
  }
  const py::array_t<double, py::array::c_style> array = as_float_array(object, name);
  if (array.ndim() == 1) {
    ArgStorage storage;
    return VecX(vector_arg(object, name, size, "one weight per state or input", storage))
        .asDiagonal();
  }
  return matrix_arg(object, name, size, size);
}

std::string poles_text(const VecXc& poles) {
  std::vector<std::string> items;
  for (const Complex& p : poles) items.push_back(complex_text(p));
  return fmt::format("{}", fmt::join(items, ", "));
}

void bind_lqr(py::module_& m) {
  py::class_<LqrDesign>(m, "LqrDesign", R"doc(
A linear-quadratic regulator: u = −K x minimizes ∫ xᵀQx + uᵀRu + 2xᵀNu dt (or the sum over
samples when the system is discrete). K (inputs × states), S (the Riccati solution: the optimal
cost from x₀ is x₀ᵀ S x₀), the closed-loop poles, and the names of K's rows and columns.)doc")
      .def_property_readonly("K", [](const LqrDesign& d) { return to_numpy(d.K); })
      .def_property_readonly("S", [](const LqrDesign& d) { return to_numpy(d.S); })
      .def_property_readonly(
          "closed_loop_poles", [](const LqrDesign& d) { return to_numpy(d.closed_loop_poles); },
          "Eigenvalues of A − B K (1/s; z-plane when dt > 0).")
      .def_readonly("state_names", &LqrDesign::state_names)
      .def_readonly("input_names", &LqrDesign::input_names)
      .def_readonly("dt", &LqrDesign::sample_time)
      .def("__iter__",
           [](const LqrDesign& d) {
             return py::iter(
                 py::make_tuple(to_numpy(d.K), to_numpy(d.S), to_numpy(d.closed_loop_poles)));
           })
      .def("__repr__", [](const LqrDesign& d) {
        return fmt::format(
            "<momenta.LqrDesign{}: u = −K x\n{}  closed-loop poles: {}>",
            d.sample_time > 0 ? fmt::format(" (discrete, dt = {} s)", number_text(d.sample_time, 6))
                              : std::string(),
            matrix_table("K", d.K, d.input_names, d.state_names), poles_text(d.closed_loop_poles));
      });
  m.def(
      "lqr",
      [](const py::object& system, const py::object& Q, const py::object& R, const py::object& N) {
        const StateSpace s = state_space_arg(system);
        const auto n = static_cast<Eigen::Index>(s.state_count());
        const auto k = static_cast<Eigen::Index>(s.input_count());
        return lqr(s, weight_arg(Q, "Q", n), weight_arg(R, "R", k),
                   N.is_none() ? MatX() : matrix_arg(N, "N", n, k));
      },
      py::arg("system"), py::arg("Q"), py::arg("R"), py::arg("N") = py::none(),
      "Linear-quadratic regulator of a continuous system (lqr) or, when system.dt > 0, of a "
      "discrete one (dlqr). Q and R: matrices, vectors (the diagonal) or numbers (times I). "
      "Returns an LqrDesign, which unpacks as K, S, poles = lqr(...), as python-control's does.");
}

void bind_pole_placement(py::module_& m) {
  py::class_<PolePlacement>(m, "PolePlacement", R"doc(
A state feedback u = −K x placing the poles of A − B K (Kautsky, Nichols & Van Dooren's method 0,
as scipy.signal.place_poles(method="KNV0")): K, the closed-loop poles as computed, and the
eigenvector matrix's condition number (how sensitive the placement is).)doc")
      .def_property_readonly("K", [](const PolePlacement& p) { return to_numpy(p.K); })
      .def_property_readonly("closed_loop_poles",
                             [](const PolePlacement& p) { return to_numpy(p.closed_loop_poles); })
      .def_readonly("eigenvector_condition", &PolePlacement::eigenvector_condition)
      .def_readonly("state_names", &PolePlacement::state_names)
      .def_readonly("input_names", &PolePlacement::input_names)
      .def("__repr__", [](const PolePlacement& p) {
        return fmt::format(
            "<momenta.PolePlacement: u = −K x\n{}  closed-loop poles: {}\n  "
            "eigenvector condition {}>",
            matrix_table("K", p.K, p.input_names, p.state_names), poles_text(p.closed_loop_poles),
            number_text(p.eigenvector_condition, 4));
      });
  m.def(
      "place_poles",
      [](const py::object& system, const std::vector<Complex>& poles) {
        return place_poles(state_space_arg(system), poles);
      },
      py::arg("system"), py::arg("poles"),
      "The state feedback u = −K x that puts the eigenvalues of A − B K at `poles` (complex ones "
      "in conjugate pairs).");
}

void bind_discretization(py::module_& m) {
  m.def(
      "c2d",
      [](const py::object& system, double dt, const std::string& method) {
        return c2d(state_space_arg(system), dt, discretization_method(method));
      },
      py::arg("system"), py::arg("dt"), py::arg("method") = "zoh",
      "The system sampled every dt seconds: method 'zoh' (zero-order hold, exact for inputs held "
      "between samples) or 'tustin' (bilinear, as scipy's cont2discrete(method='bilinear')).");
}

void bind_reachability(py::module_& m) {
  py::class_<Reachability>(m, "Reachability", R"doc(
Controllability (what the inputs move) or observability (what the outputs show): the rank, the
eigenvalues of the part left out, and the Gramian with its condition number when the system is
stable (docs/control.md).)doc")
      .def_readonly("rank", &Reachability::rank)
      .def_readonly("states", &Reachability::states)
      .def_property_readonly("complete", &Reachability::complete)
      .def_property_readonly("hidden_poles",
                             [](const Reachability& r) {
                               VecXc p(static_cast<Eigen::Index>(r.hidden_poles.size()));
                               for (std::size_t i = 0; i < r.hidden_poles.size(); ++i) {
                                 p[static_cast<Eigen::Index>(i)] = r.hidden_poles[i];
                               }
                               return to_numpy(p);
                             })
      .def_property_readonly("gramian",
                             [](const Reachability& r) -> py::object {
                               if (r.gramian.size() == 0 && r.states > 0) return py::none();
                               return to_numpy(r.gramian);
                             })
      .def_readonly("gramian_condition", &Reachability::gramian_condition)
      .def("__repr__", [](const Reachability& r) {
        std::vector<std::string> hidden;
        for (const Complex& p : r.hidden_poles) hidden.push_back(complex_text(p));
        return fmt::format(
            "<momenta.Reachability rank {} of {}{}{}>", r.rank, r.states,
            hidden.empty() ? std::string()
                           : fmt::format("; hidden modes at {}", fmt::join(hidden, ", ")),
            r.gramian_condition
                ? fmt::format("; Gramian condition {}", number_text(*r.gramian_condition, 4))
                : std::string("; unstable: no Gramian"));
      });
  m.def(
      "controllability",
      [](const py::object& system) { return controllability(state_space_arg(system)); },
      py::arg("system"), "Controllability of (A, B) by the orthogonal staircase.");
  m.def(
      "observability",
      [](const py::object& system) { return observability(state_space_arg(system)); },
      py::arg("system"), "Observability of (A, C), as controllability of (Aᵀ, Cᵀ).");
}

std::size_t channel_arg(const std::vector<std::string>& names, const py::handle& which,
                        const char* what) {
  if (py::isinstance<py::str>(which)) {
    const std::string name = which.cast<std::string>();
    const auto found = std::find(names.begin(), names.end(), name);
    if (found == names.end()) {
      throw py::value_error(fmt::format("no {} named '{}'; the {}s are: {}", what, name, what,
                                        fmt::join(names, ", ")));
    }
    return static_cast<std::size_t>(found - names.begin());
  }
  return which.cast<std::size_t>();
}

void bind_root_locus(py::module_& m) {
  py::class_<LocusPoint>(m, "LocusPoint", "A point s of the root locus and the gain k there.")
      .def_readonly("s", &LocusPoint::s, "1/s")
      .def_readonly("gain", &LocusPoint::gain)
      .def("__repr__", [](const LocusPoint& p) {
        return fmt::format("<momenta.LocusPoint s = {} at k = {}>", complex_text(p.s),
                           number_text(p.gain, 6));
      });
  py::class_<RootLocus>(m, "RootLocus", R"doc(
Where the closed-loop poles of the feedback u = r − k y go as k grows: `gains`, `poles` (gains ×
n, each column one branch), `breakaway` and `crossings` (LocusPoint: s and k, exact),
`asymptote_centroid`, `asymptote_angles_deg`, and the open-loop transfer function.)doc")
      .def_readonly("input_name", &RootLocus::input_name)
      .def_readonly("output_name", &RootLocus::output_name)
      .def_readonly("open_loop", &RootLocus::open_loop)
      .def_property_readonly("gains", [](const RootLocus& r) { return to_numpy(r.gains); })
      .def_property_readonly(
          "poles",
          [](const RootLocus& r) {
            py::array_t<std::complex<double>> out({r.poles.rows(), r.poles.cols()});
            auto view = out.mutable_unchecked<2>();
            for (Eigen::Index i = 0; i < r.poles.rows(); ++i)
              for (Eigen::Index j = 0; j < r.poles.cols(); ++j) view(i, j) = r.poles(i, j);
            return out;
          })
      .def_readonly("breakaway", &RootLocus::breakaway)
      .def_readonly("crossings", &RootLocus::crossings,
                    "where the locus crosses the stability boundary: the imaginary axis, or the "
                    "unit circle when sampled")
      .def_readonly("sample_time", &RootLocus::sample_time,
                    "s; 0 for an s-plane locus, T for a system sampled every T s (z-plane)")
      .def_readonly("asymptote_centroid", &RootLocus::asymptote_centroid)
      .def_readonly("asymptote_angles_deg", &RootLocus::asymptote_angles_deg)
      .def("__repr__", [](const RootLocus& r) {
        const auto points = [](const std::vector<LocusPoint>& list) {
          std::vector<std::string> items;
          for (const LocusPoint& p : list) {
            items.push_back(fmt::format("{} (k = {})", complex_text(p.s), number_text(p.gain, 6)));
          }
          return items.empty() ? std::string("none") : fmt::format("{}", fmt::join(items, ", "));
        };
        return fmt::format("<momenta.RootLocus {} → {}: {} gains; break-away {}; {} crossings {}>",
                           r.input_name, r.output_name, r.gains.size(), points(r.breakaway),
                           r.sample_time > 0.0 ? "unit-circle" : "axis", points(r.crossings));
      });
  m.def(
      "root_locus",
      [](const py::object& system, const py::object& input, const py::object& output,
         const py::object& gains, double k_min, double k_max, std::size_t points) {
        const StateSpace s = state_space_arg(system);
        const std::size_t i = channel_arg(s.input_names(), input, "input");
        const std::size_t o = channel_arg(s.output_names(), output, "output");
        if (!gains.is_none()) {
          ArgStorage storage;
          return root_locus(s, i, o, VecX(vector_arg(gains, "gains", -1, "", storage)));
        }
        return root_locus(s, i, o, log_gain_grid(k_min, k_max, points));
      },
      py::arg("system"), py::arg("input") = 0, py::arg("output") = 0, py::kw_only(),
      py::arg("gains") = py::none(), py::arg("k_min") = 0.01, py::arg("k_max") = 100.0,
      py::arg("points") = 200,
      "Root locus of the feedback u = r − k y on one pair, at the given gains or 0 and a log "
      "grid from k_min to k_max; with its break-away points, imaginary-axis crossings (unit-circle "
      "crossings in the z-plane of a sampled system) and asymptotes, exact.");
}

void bind_matrix_equations(py::module_& m) {
  m.def(
      "lyap",
      [](const py::object& A, const py::object& Q) {
        const MatX a = matrix_arg(A, "A", -1, -1);
        return to_numpy(solve_continuous_lyapunov(a, matrix_arg(Q, "Q", a.rows(), a.rows())));
      },
      py::arg("A"), py::arg("Q"), "X with A X + X Aᵀ + Q = 0 (Bartels–Stewart).");
  m.def(
      "dlyap",
      [](const py::object& A, const py::object& Q) {
        const MatX a = matrix_arg(A, "A", -1, -1);
        return to_numpy(solve_discrete_lyapunov(a, matrix_arg(Q, "Q", a.rows(), a.rows())));
      },
      py::arg("A"), py::arg("Q"), "X with A X Aᵀ − X + Q = 0.");
  const auto riccati = [](auto solve) {
    return [solve](const py::object& A, const py::object& B, const py::object& Q,
                   const py::object& R, const py::object& N) {
      const MatX a = matrix_arg(A, "A", -1, -1);
      const MatX b = matrix_arg(B, "B", a.rows(), -1);
      return to_numpy(solve(a, b, matrix_arg(Q, "Q", a.rows(), a.rows()),
                            matrix_arg(R, "R", b.cols(), b.cols()),
                            N.is_none() ? MatX() : matrix_arg(N, "N", a.rows(), b.cols())));
    };
  };
  m.def("care",
        riccati([](const MatX& a, const MatX& b, const MatX& q, const MatX& r, const MatX& n) {
          return solve_continuous_riccati(a, b, q, r, n);
        }),
        py::arg("A"), py::arg("B"), py::arg("Q"), py::arg("R"), py::arg("N") = py::none(),
        "The stabilizing X of Aᵀ X + X A − (X B + N) R⁻¹ (Bᵀ X + Nᵀ) + Q = 0.");
  m.def("dare",
        riccati([](const MatX& a, const MatX& b, const MatX& q, const MatX& r, const MatX& n) {
          return solve_discrete_riccati(a, b, q, r, n);
        }),
        py::arg("A"), py::arg("B"), py::arg("Q"), py::arg("R"), py::arg("N") = py::none(),
        "The stabilizing X of Aᵀ X A − X − (Aᵀ X B + N)(R + Bᵀ X B)⁻¹ (Bᵀ X A + Nᵀ) + Q = 0.");
}

}  // namespace

void bind_control(py::module_& m) {
  bind_lqr(m);
  bind_pole_placement(m);
  bind_discretization(m);
  bind_reachability(m);
  bind_root_locus(m);
  bind_matrix_equations(m);
}

}  // namespace momenta::python
