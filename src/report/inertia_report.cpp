// A part's report page: the composite and its parts drawn in the part's frame, the principal
// axes and equivalent ellipsoid at the centre of mass, and the tensors.

#include <fmt/format.h>

#include "momenta/report/report.hpp"
#include "page_data.hpp"

namespace momenta::report {

namespace {

using detail::json;

json part_page_data(const io::CompositePart& part, const std::string& source,
                    const std::optional<Vec3>& about) {
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
  return data;
}

json vec2_json(const Vec2& v) { return json::array({v.x(), v.y()}); }

json grade_json(const inertia::GradeCheck& g) {
  return {{"grade", g.grade},
          {"omega", g.omega},
          {"permissible", g.permissible},
          {"plane_A", vec2_json(g.plane_A)},
          {"plane_B", vec2_json(g.plane_B)},
          {"permissible_A", g.permissible_A},
          {"permissible_B", g.permissible_B},
          {"overhung", g.overhung},
          {"pass", g.pass}};
}

json balance_json(const BalanceFindings& f) {
  const inertia::Unbalance& u = f.unbalance;
  json corrections = json::array();
  for (const auto& c : f.corrections) {
    corrections.push_back({{"z", c.z}, {"mass_radius", vec2_json(c.mass_radius)}});
  }
  json reactions = json::array();
  for (std::size_t k = 0; k < f.speeds.size(); ++k) {
    json row = {{"omega", f.speeds[k]},
                {"A", vec2_json(f.reactions[k].A)},
                {"B", vec2_json(f.reactions[k].B)}};
    if (k < f.reactions_after.size()) {
      row["A_after"] = vec2_json(f.reactions_after[k].A);
      row["B_after"] = vec2_json(f.reactions_after[k].B);
    }
    reactions.push_back(std::move(row));
  }
  json j = {{"through", detail::vec_json(f.axis.p_BoAo_B)},
            {"R_BR", detail::mat_json(u.R_BR)},
            {"mass", u.mass},
            {"axial_com", u.axial_com},
            {"eccentricity", u.eccentricity},
            {"static_unbalance", vec2_json(u.static_unbalance)},
            {"couple_unbalance", vec2_json(u.couple_unbalance)},
            {"principal_axis_tilt", u.principal_axis_tilt},
            {"corrections", std::move(corrections)},
            {"radius", f.radius ? json(*f.radius) : json(nullptr)},
            {"remove", f.remove},
            {"reactions", std::move(reactions)}};
  if (f.bearings) j["bearings"] = {(*f.bearings)[0], (*f.bearings)[1]};
  if (f.grade) j["grade"] = grade_json(*f.grade);
  if (f.grade_after) j["grade_after"] = grade_json(*f.grade_after);
  return j;
}

}  // namespace

std::string inertia_report_html(const io::CompositePart& part, const std::string& source,
                                const std::optional<Vec3>& about) {
  return detail::html_page(fmt::format("{} — momenta mass properties", part.name),
                           part_page_data(part, source, about));
}

std::string balance_report_html(const io::CompositePart& rotor, const std::string& source,
                                const BalanceFindings& findings) {
  json data = part_page_data(rotor, source, std::nullopt);
  data["balance"] = balance_json(findings);
  return detail::html_page(fmt::format("{} — momenta balancing", rotor.name), data);
}

}  // namespace momenta::report
