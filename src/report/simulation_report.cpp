// A simulation report: its data (simulation_data.cpp) in the page.

#include <fmt/format.h>

#include "momenta/report/report.hpp"
#include "sections.hpp"

namespace momenta::report {

std::string simulation_report_html(const SimulationRun& run, const LinearSettings& linear) {
  detail::json data = detail::simulation_data(run, linear);  // checks the run first
  // With the engine in the page, the reader can change the model's numbers (live_section.cpp).
  const bool live = detail::engine_embedded();
  if (live) data["live"] = detail::live_json(*run.file);
  return detail::html_page(fmt::format("{} — momenta report", run.file->name), data, live);
}

}  // namespace momenta::report
