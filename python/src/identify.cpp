// momenta.inertial_regressor, base_parameters, estimate_inertia: identification of a tree's
// inertial parameters from measured motion and joint efforts; momenta.identify: grey-box fits of
// an identification file (docs/identification.md) — the same numbers as `momenta identify`.

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "model_handle.hpp"
#include "momenta/common/error.hpp"
#include "momenta/identify/grey_box.hpp"
#include "momenta/identify/identification_file.hpp"
#include "momenta/identify/inertia_data.hpp"
#include "momenta/identify/inertial_regressor.hpp"

namespace momenta::python {
namespace {

py::list names_of(const model::Model& model, const std::vector<int>& indices) {
  py::list names;
  for (int k : indices) names.append(identify::parameter_name(model, k));
  return names;
}

py::dict base_dict(const model::Model& model, const identify::BaseParameters& base) {
  py::dict d;
  py::list described;
  for (int k = 0; k < base.rank(); ++k) described.append(base.describe(model, k));
  d["names"] = described;
  d["leading"] = names_of(model, base.independent);
  d["regrouping"] = to_numpy(base.regrouping);
  d["never_felt"] = names_of(model, base.no_effect);
  d["regrouped"] = names_of(model, base.regrouped());
  d["model_values"] = to_numpy(base.base_of(identify::inertial_parameters(model)));
  return d;
}

py::dict grey_box_dict(const identify::GreyBoxEstimate& e) {
  py::dict d;
  d["names"] = e.names;
  d["paths"] = e.paths;
  d["experiments"] = e.experiments;  // per parameter: the experiment it belongs to, "" if shared
  d["estimate"] = to_numpy(e.value);
  d["standard_error"] = to_numpy(e.standard_error);
  d["lower"] = to_numpy(e.lower95);
  d["upper"] = to_numpy(e.upper95);
  d["profiled"] = e.profiled;  // lower/upper from the profile likelihood, else Fisher's
  d["lower_bounded"] = e.lower_bounded;
  d["upper_bounded"] = e.upper_bounded;
  d["fisher_lower"] = to_numpy(e.fisher_lower95);
  d["fisher_upper"] = to_numpy(e.fisher_upper95);
  d["not_quadratic"] = to_numpy(e.not_quadratic);
  d["interval_notes"] = e.interval_notes;
  d["warnings"] = e.warnings;
  d["start"] = to_numpy(e.start);
  d["log_scale"] = e.positive;
  d["at_bound"] = e.at_bound;
  d["correlation"] = to_numpy(e.correlation);
  d["degrees_of_freedom"] = e.degrees_of_freedom;
  d["identifiable"] = e.identifiable;
  d["singular_values"] = to_numpy(e.singular_values);
  d["condition_number"] = e.condition_number;
  d["undetermined"] = e.undetermined;
  d["least_determined"] = e.least_determined;
  py::list channels;
  for (const identify::FittedChannel& c : e.channels) {
    py::dict channel;
    channel["experiment"] = c.experiment;
    channel["column"] = c.column;
    channel["channel"] = c.channel;
    channel["unit"] = c.unit;
    channel["abscissa"] = c.abscissa;  // "time" (s), or "frequency" (Hz) for a Bode test
    channel["time"] = to_numpy(c.time);
    channel["measured"] = to_numpy(c.measured);
    channel["fitted"] = to_numpy(c.fitted);
    channel["at_start"] = to_numpy(c.guessed);
    channel["noise"] = c.noise;
    channel["noise_given"] = c.noise_given;
    channel["residual_rms"] = c.rms;
    channel["whiteness_p"] = c.whiteness_p;
    channels.append(channel);
  }
  d["channels"] = channels;
  d["converged"] = e.converged;
  d["termination"] = e.termination;
  d["iterations"] = e.iterations;
  d["simulations"] = e.simulations;
  d["sensitivity_simulations"] = e.sensitivity_simulations;
  d["evaluations"] = e.evaluations;
  d["linearizations"] = e.linearizations;
  d["final_cost"] = e.final_cost;
  return d;
}

}  // namespace

void bind_identify(py::module_& m) {
  m.def(
      "identify",
      [](const std::string& file, std::optional<std::string> output, bool overwrite) {
        if (output && std::filesystem::exists(*output) && !overwrite) {
          throw FileError(fmt::format("{}: the file exists; pass overwrite=True", *output));
        }
        const identify::GreyBoxProblem problem = identify::read_identification_file(file);
        identify::GreyBoxEstimate e;
        {
          py::gil_scoped_release release;
          e = identify::fit_grey_box(problem);
        }
        if (output) {
          std::ofstream out(*output, std::ios::binary);
          out << identify::identified_model_text(problem, e);
          if (!out.flush()) throw FileError(fmt::format("{}: cannot be written", *output));
        }
        return grey_box_dict(e);
      },
      py::arg("file"), py::arg("output") = py::none(), py::arg("overwrite") = false,
      "Fits the numbers an identification file names to its experiments' logs, as `momenta "
      "identify FILE` does: a dict of `names`, `paths`, `estimate`, `standard_error`, `lower` "
      "and `upper` (95 %; ±inf where the data do not determine a parameter), `start`, "
      "`correlation`, the identifiability (`identifiable`, `singular_values`, "
      "`condition_number`, `undetermined` in words, `least_determined`), per measured channel "
      "its `time`, `measured`, `fitted` and `at_start` values, `noise`, `residual_rms` and "
      "`whiteness_p`, and the optimizer's `converged`, `termination`, `iterations`, runs and "
      "evaluations. With `output`, the identified model file is written there (an existing "
      "file only with overwrite=True).");

  m.def(
      "inertial_parameters",
      [](const ModelHandle& h) {
        py::list names;
        for (int k = 0; k < identify::num_inertial_parameters(h.model()); ++k)
          names.append(identify::parameter_name(h.model(), k));
        return py::make_tuple(to_numpy(identify::inertial_parameters(h.model())), names);
      },
      py::arg("model"),
      "(π, names): the model's inertial parameters, ten per body about its frame's origin in its "
      "axes — m, h_x, h_y, h_z (h = m c), I_xx, I_xy, I_xz, I_yy, I_yz, I_zz (off-diagonals minus "
      "the products of inertia) — and their names '<body>.<name>' (docs/identification.md).");
  m.def(
      "inertial_regressor",
      [](const ModelHandle& h, const py::handle& q, const py::handle& v, const py::handle& vdot) {
        const model::Model& model = h.model();
        ArgStorage sq, sv, sa;
        return to_numpy(identify::inertial_regressor(
            model, vector_arg(q, "q", model.nq(), "the model's nq", sq),
            vector_arg(v, "v", model.nv(), "the model's nv", sv),
            vector_arg(vdot, "vdot", model.nv(), "the model's nv", sa)));
      },
      py::arg("model"), py::arg("q"), py::arg("v"), py::arg("vdot"),
      "Y (nv × 10 bodies): the joint efforts are Y π + armature · vdot with π the bodies' "
      "inertial parameters (inertial_parameters), so Y @ π equals Workspace.rnea where no joint "
      "has armature.");
  m.def(
      "base_parameters",
      [](const ModelHandle& h) {
        return base_dict(h.model(), identify::base_parameters(h.model()));
      },
      py::arg("model"),
      "The base (identifiable) inertial parameters, as `momenta identify` finds them: a dict with "
      "`names` (each base parameter in words, 'upper.I_yy + 0.64·lower.m'), `leading` (the "
      "parameter each starts with), `regrouping` (β = regrouping @ π), `never_felt` and "
      "`regrouped` (the parameters joint efforts cannot tell, or tell only in the combinations), "
      "and `model_values` (β of the model's own π).");
  m.def(
      "estimate_inertia",
      [](const ModelHandle& h, const py::handle& q, const py::handle& v, const py::handle& vdot,
         const py::handle& tau) {
        const model::Model& model = h.model();
        identify::InertiaSamples s;
        s.q = matrix_arg(q, "q", -1, model.nq());
        s.v = matrix_arg(v, "v", s.q.rows(), model.nv());
        s.vdot = matrix_arg(vdot, "vdot", s.q.rows(), model.nv());
        s.tau = matrix_arg(tau, "tau", s.q.rows(), model.nv());
        const identify::BaseParameters base = identify::base_parameters(model);
        const identify::InertiaEstimate e = identify::estimate_inertia(model, s, base);
        py::dict d = base_dict(model, base);
        d["estimate"] = to_numpy(e.beta);
        d["standard_error"] = to_numpy(e.standard_error);
        d["lower"] = to_numpy(e.lower);
        d["upper"] = to_numpy(e.upper);
        d["covariance"] = to_numpy(e.covariance);
        d["correlation"] = to_numpy(e.correlation);
        d["noise"] = to_numpy(e.noise);
        d["residual_rms"] = to_numpy(e.residual_rms);
        d["fitted"] = to_numpy(e.fitted);
        d["excitation"] = to_numpy(e.excitation);
        d["condition_number"] = e.condition_number;
        d["least_determined"] = to_numpy(e.least_determined);
        d["whiteness_p"] = to_numpy(e.whiteness_p);
        d["degrees_of_freedom"] = e.degrees_of_freedom;
        d["parameters"] = to_numpy(e.parameters);
        py::dict consistency;
        for (int b = 1; b < model.num_bodies(); ++b)
          consistency[py::str(model.body(b).name)] = e.consistency[b - 1].verdict();
        d["consistency"] = consistency;
        return d;
      },
      py::arg("model"), py::arg("q"), py::arg("v"), py::arg("vdot"), py::arg("tau"),
      "The base inertial parameters estimated from N measured samples — q (N, nq), v, vdot and "
      "tau (N, nv) — by weighted least squares, as `momenta identify` does: base_parameters' "
      "dict with `estimate`, `standard_error`, `lower` and `upper` (95 %), `covariance`, "
      "`correlation`, each coordinate's `noise` and `residual_rms`, the `fitted` efforts (N, nv), "
      "the data's `excitation` (relative singular values of the scaled regressor), "
      "`condition_number` and `least_determined` combination, each effort's `whiteness_p` "
      "(Ljung–Box), "
      "`degrees_of_freedom`, a full "
      "π that gives the estimate (`parameters`) and each body's `consistency` in words.");
}

}  // namespace momenta::python
