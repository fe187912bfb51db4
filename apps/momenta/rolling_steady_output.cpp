#include "rolling_steady_output.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "linear_model_options.hpp"
#include "momenta/common/number_text.hpp"
#include "output_format.hpp"

namespace momenta::cli {
namespace {

using json = nlohmann::ordered_json;

constexpr double kDegree = 180.0 / std::numbers::pi;

json vec3_json(const Vec3& x) { return {x.x(), x.y(), x.z()}; }

json complex_list(const std::vector<std::complex<double>>& values) {
  json list = json::array();
  for (const auto& z : values) list.push_back(complex_json(z));
  return list;
}

// "on a circle of radius 0.5 m (the contact's 0.534 m), its centre on the lean side".
std::string path_text(const analysis::RollingSteadyMotion& m) {
  if (std::isinf(m.radius)) return "on a straight line";
  if (m.radius == 0.0) return "(it stays put: the body turns on the spot)";
  std::string text = fmt::format("on a circle of radius {:.10g} m (the contact's {:.10g} m)",
                                 std::abs(m.radius), std::abs(m.contact_radius));
  if (m.lean != 0.0) {
    const bool inside = (m.radius > 0.0) == (m.lean > 0.0);
    text += inside ? ", leaning into the turn" : ", leaning out of the turn";
  }
  return text;
}

std::string disturbance_text(const analysis::RollingSteadyModes& modes) {
  if (!modes.stable) {
    return fmt::format("unstable: a disturbance grows at {:.6g} 1/s", modes.growth_rate);
  }
  if (modes.eigenvalues.empty()) return "stable: a disturbance neither grows nor oscillates";
  std::vector<std::string> frequencies;
  for (const auto& z : modes.eigenvalues) {
    frequencies.push_back(
        fmt::format("{:.6g} rad/s ({:.6g} Hz)", z.imag(), z.imag() / (2 * std::numbers::pi)));
  }
  return fmt::format("stable: it wobbles at {}", fmt::join(frequencies, ", "));
}

// A force component that is round-off of the normal force (1e-15 N of 9.81 N) prints as 0.
double force_text_value(double component, const Vec3& force) {
  return std::abs(component) <= 1e-12 * force.norm() ? 0.0 : component;
}

void print_motion_header(const analysis::RollingSteadyMotion& m) {
  fmt::print(
      "  precession Ω = {:.10g} rad/s, spin ω·e = {:.10g} rad/s ({:.10g} rad/s relative to "
      "the turning frame)\n",
      m.precession, m.spin, m.relative_spin);
  fmt::print("  G at {:.10g} m/s {}\n", m.speed, path_text(m));
  fmt::print(
      "  the floor's force on it: normal {:.6g} N, longitudinal {:.6g} N, lateral {:.6g} N\n",
      m.contact_force[0], force_text_value(m.contact_force[1], m.contact_force),
      force_text_value(m.contact_force[2], m.contact_force));
  if (m.contact_force[0] < 0.0) {
    fmt::print("  (the floor would have to pull it down: a real disk lifts off the floor)\n");
  }
}

}  // namespace

json rolling_motion_json(const analysis::RollingSteadyModes& modes) {
  const analysis::RollingSteadyMotion& m = modes.motion;
  json j;
  j["lean"] = m.lean;
  j["lean_deg"] = m.lean * kDegree;
  j["precession"] = m.precession;
  j["spin"] = m.spin;
  j["relative_spin"] = m.relative_spin;
  j["speed"] = m.speed;
  j["radius"] = finite_or_null(m.radius);
  j["contact_radius"] = finite_or_null(m.contact_radius);
  j["heading_W"] = vec3_json(m.heading_W);
  j["lateral_W"] = vec3_json(m.lateral_W);
  j["contact_force"] = {{"normal", m.contact_force[0]},
                        {"longitudinal", m.contact_force[1]},
                        {"lateral", m.contact_force[2]}};
  j["residual"] = m.residual;
  j["stable"] = modes.stable;
  j["growth_rate"] = modes.growth_rate;
  j["eigenvalues"] = complex_list(modes.eigenvalues);
  j["circle_shift"] = complex_list(modes.circle_shift);
  j["zero_eigenvalues"] = modes.zero_eigenvalues;
  j["state"] = {{"q", std::vector<double>(m.point.q.data(), m.point.q.data() + m.point.q.size())},
                {"v", std::vector<double>(m.point.v.data(), m.point.v.data() + m.point.v.size())},
                {"t", m.point.t}};
  return j;
}

void print_rolling_motion(const analysis::RollingSteadyModes& modes, const std::string& joint,
                          int index, int count) {
  if (count > 1) fmt::print("{} ({}):\n", index, index == 1 ? "slow" : "fast");
  const analysis::RollingSteadyMotion& m = modes.motion;
  print_motion_header(m);
  fmt::print("  {}\n", disturbance_text(modes));
  // The state as a model file writes it, for a model that starts on this motion.
  const auto list = [](const VecX& x) {
    std::vector<std::string> entries;
    for (Eigen::Index i = 0; i < x.size(); ++i) entries.push_back(fmt::format("{:.16g}", x[i]));
    return fmt::format("[{}]", fmt::join(entries, ", "));
  };
  fmt::print("  joint '{}': q0: {}\n  {:>{}}  v0: {}\n", joint, list(m.point.q), "",
             joint.size() + 8, list(m.point.v));
}

void print_rolling_steady_modes(const io::ModelFile& file,
                                const analysis::RollingSteadyModes& modes, bool as_json,
                                bool with_matrix) {
  const analysis::RollingBodyInfo info = analysis::rolling_body_info(file.model);
  const analysis::RollingSteadyMotion& motion = modes.motion;
  const analysis::StateSpace& A = modes.reduced;
  if (as_json) {
    json j;
    j["model"] = file.name;
    j["about"] = "steady";
    j["motion"] = "steady rolling";
    j["body"] = info.body;
    j["contact"] = info.contact;
    j.update(rolling_motion_json(modes));
    j["state_names"] = A.state_names();
    json rows = json::array();
    for (Eigen::Index i = 0; i < A.A().rows(); ++i) {
      json row = json::array();
      for (Eigen::Index k = 0; k < A.A().cols(); ++k) row.push_back(A.A()(i, k));
      rows.push_back(std::move(row));
    }
    j["A"] = std::move(rows);
    fmt::print("{}\n", json_text(j));
    return;
  }
  fmt::print("{}: steady rolling of '{}' on contact '{}' at lean {:.6g}° (residual {:.2g})\n",
             file.name, info.body, info.contact, motion.lean * kDegree, motion.residual);
  print_motion_header(motion);
  fmt::print("\nthe disturbed motion seen from the turning frame ({} states: {}):\n",
             A.state_names().size(), fmt::join(A.state_names(), ", "));
  if (with_matrix) {
    print_matrix("A", A.A(), A.state_names(), A.state_names());
    fmt::print("\n");
  }
  for (const auto& z : modes.eigenvalues) {
    fmt::print("  {:>28}   {:.6g} rad/s ({:.6g} Hz){}\n", complex_text(z), std::abs(z.imag()),
               std::abs(z.imag()) / (2 * std::numbers::pi), z.imag() != 0.0 ? ", a wobble" : "");
  }
  for (const auto& z : modes.circle_shift) {
    fmt::print(
        "  {:>28}   the circle's centre displaced: a neighbouring steady motion, turning at "
        "Ω as seen from this frame\n",
        complex_text(z));
  }
  fmt::print(
      "  {} zero eigenvalue{}: along the symmetry (across the floor, about the vertical, "
      "about the axis) and to neighbouring steady motions\n",
      modes.zero_eigenvalues, modes.zero_eigenvalues == 1 ? "" : "s");
  fmt::print("\n{}\n", disturbance_text(modes));
}

}  // namespace momenta::cli
