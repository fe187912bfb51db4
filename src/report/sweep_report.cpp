#include <fmt/format.h>

#include "momenta/report/report.hpp"
#include "page_data.hpp"

namespace momenta::report {

std::string sweep_report_html(const SweepResults& results) {
  using detail::json;
  json data;
  data["kind"] = "sweep";
  data["title"] = results.title;
  data["source"] = results.source;
  data["parameters"] = results.parameters;
  data["metrics"] = results.metrics;
  data["parameter_units"] = results.parameter_units;
  data["metric_units"] = results.metric_units;
  data["runs"] = results.runs;
  json ok = json::array();
  for (bool b : results.ok) ok.push_back(b);
  data["ok"] = ok;
  // Exact doubles; NaN (an undefined figure) travels as NaN in the float64 bytes.
  json columns = json::array();
  for (const std::vector<double>& column : results.values)
    columns.push_back(detail::encode_f64(column));
  data["values"] = columns;
  return detail::html_page(fmt::format("{} — momenta sweep", results.title), data);
}

}  // namespace momenta::report
