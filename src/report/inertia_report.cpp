// A part's report page: the composite and its parts drawn in the part's frame, the principal
// axes and equivalent ellipsoid at the centre of mass, and the tensors.

#include <fmt/format.h>

#include "momenta/report/report.hpp"
#include "page_data.hpp"

namespace momenta::report {

std::string inertia_report_html(const io::CompositePart& part, const std::string& source,
                                const std::optional<Vec3>& about) {
  using detail::json;
  const inertia::MassProperties& total = part.total;
  const inertia::PrincipalAxes axes = total.principal_axes();
  json parts = json::array();
  for (const io::PartSummary& p : part.parts) {
    json j = detail::part_json(p);
    j["line"] = p.line;
    j["com"] = detail::vec_json(p.mass_properties.center_of_mass());
    parts.push_back(std::move(j));
  }
  json data = {{"kind", "inertia"},
               {"name", part.name},
               {"file", source},
               {"mass", total.mass()},
               {"com", detail::vec_json(total.center_of_mass())},
               {"inertia_com", detail::mat_json(total.inertia_about_com())},
               {"principal_moments", detail::vec_json(axes.moments)},
               {"principal_axes", detail::mat_json(axes.R_BP)},
               {"equivalent", detail::equivalent_ellipsoid_json(total)},
               {"parts", parts}};
  if (about) {
    data["about"] = detail::vec_json(*about);
    data["inertia_about"] = detail::mat_json(total.inertia_about(*about));
  }
  return detail::html_page(fmt::format("{} — momenta mass properties", part.name), data);
}

}  // namespace momenta::report
