#include <cmath>

#include <fmt/format.h>

#include "momenta/report/report.hpp"
#include "page_data.hpp"

namespace momenta::report {

std::string identification_report_html(const IdentificationResults& r) {
  using detail::json;
  json data;
  data["kind"] = "identification";
  data["title"] = r.title;
  data["model_source"] = r.model_source;
  data["data_source"] = r.data_source;
  data["samples"] = r.samples;
  data["degrees_of_freedom"] = r.degrees_of_freedom;
  data["num_parameters"] = r.num_parameters;
  data["time"] = r.time.empty() ? json(nullptr) : json(detail::encode_f64(r.time));
  json efforts = json::array();
  for (std::size_t k = 0; k < r.efforts.size(); ++k) {
    efforts.push_back({{"name", r.efforts[k]},
                       {"unit", r.effort_units[k]},
                       {"measured", detail::encode_f64(r.measured[k])},
                       {"fitted", detail::encode_f64(r.fitted[k])},
                       {"noise", r.noise[k]},
                       {"residual_rms", r.residual_rms[k]}});
  }
  data["efforts"] = std::move(efforts);
  json estimates = json::array();
  for (const IdentificationResults::Estimate& e : r.estimates) {
    estimates.push_back({{"name", e.name},
                         {"unit", e.unit},
                         {"estimate", e.estimate},
                         {"standard_error", e.standard_error},
                         {"lower", e.lower},
                         {"upper", e.upper},
                         {"model", e.model}});
  }
  data["estimates"] = std::move(estimates);
  data["correlation"] = r.correlation;
  data["never_felt"] = r.never_felt;
  data["regrouped"] = r.regrouped;
  data["excitation"] = {{"singular_values", r.excitation},
                        {"condition_number", r.condition_number},
                        {"least_determined", r.least_determined},
                        {"poor", r.poor_excitation}};
  data["whiteness"] = {
      {"p", r.whiteness_p}, {"lags", r.whiteness_lags}, {"level", r.whiteness_level}};
  json bodies = json::array();
  for (const IdentificationResults::Body& b : r.bodies) {
    bodies.push_back({{"name", b.name}, {"verdict", b.verdict}, {"consistent", b.consistent}});
  }
  data["bodies"] = std::move(bodies);
  return detail::html_page(fmt::format("{} — momenta identify", r.title), data);
}

namespace {

// A figure that may be infinite (an undetermined standard error or bound): null in the page.
detail::json number_or_null(double x) {
  return std::isfinite(x) ? detail::json(x) : detail::json(nullptr);
}

}  // namespace

std::string grey_box_report_html(const GreyBoxResults& r) {
  using detail::json;
  json data;
  data["kind"] = "grey-box";
  data["title"] = r.title;
  data["model_source"] = r.model_source;
  data["converged"] = r.converged;
  data["termination"] = r.termination;
  data["iterations"] = r.iterations;
  data["degrees_of_freedom"] = r.degrees_of_freedom;
  data["runs"] = r.runs;
  data["evaluations"] = r.evaluations;
  data["seconds"] = r.seconds;
  data["noise_estimated"] = r.noise_estimated;
  data["linearizations"] = r.linearizations;
  json parameters = json::array();
  for (const GreyBoxResults::Parameter& p : r.parameters) {
    parameters.push_back({{"name", p.name},
                          {"path", p.path},
                          {"estimate", p.estimate},
                          {"standard_error", number_or_null(p.standard_error)},
                          {"lower", number_or_null(p.lower)},
                          {"upper", number_or_null(p.upper)},
                          {"start", p.start},
                          {"at_bound", p.at_bound},
                          {"profiled", p.profiled},
                          {"lower_bounded", p.lower_bounded},
                          {"upper_bounded", p.upper_bounded}});
  }
  data["estimates"] = std::move(parameters);
  data["interval_notes"] = r.interval_notes;
  data["warnings"] = r.warnings;
  data["correlation"] = r.correlation;
  data["identifiability"] = {{"singular_values", r.singular_values},
                             {"condition_number", number_or_null(r.condition_number)},
                             {"identifiable", r.identifiable},
                             {"undetermined", r.undetermined},
                             {"advice", r.advice},
                             {"least_determined", r.least_determined},
                             {"poor", r.poorly_determined}};
  json channels = json::array();
  for (const GreyBoxResults::Channel& c : r.channels) {
    channels.push_back({{"experiment", c.experiment},
                        {"column", c.column},
                        {"channel", c.channel},
                        {"unit", c.unit},
                        {"time", detail::encode_f64(c.time)},
                        {"measured", detail::encode_f64(c.measured)},
                        {"fitted", detail::encode_f64(c.fitted)},
                        {"at_start", detail::encode_f64(c.at_start)},
                        {"noise", c.noise},
                        {"noise_given", c.noise_given},
                        {"residual_rms", c.residual_rms},
                        {"whiteness_p", c.whiteness_p},
                        {"abscissa", c.abscissa},
                        {"abscissa_unit", c.abscissa_unit}});
  }
  data["channels"] = std::move(channels);
  data["whiteness_level"] = r.whiteness_level;
  return detail::html_page(fmt::format("{} — momenta identify", r.title), data);
}

}  // namespace momenta::report
