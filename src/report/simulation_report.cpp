// A simulation report: its data (simulation_data.cpp) in the page.

#include <fmt/format.h>

#include "momenta/report/report.hpp"
#include "sections.hpp"

namespace momenta::report {

std::string simulation_report_html(const SimulationRun& run, const LinearSettings& linear) {
  detail::json data = detail::simulation_data(run, linear);  // checks the run first
  return detail::html_page(fmt::format("{} — momenta report", run.file->name), data);
}

}  // namespace momenta::report
