#pragma once
// Planar revolute chains closed to the ground by a pin, as model-file text: the constrained
// benchmark's loops (bench/constraints_bench.cpp) and the constraint solver's tests.
//   four_bar_text   crank 0.10 m, coupler 0.30 m, rocker 0.25 m, ground 0.30 m;
//   v_loop_text(n)  n 0.1 m links hanging in a V between pins n · 0.1 · cos 30° m apart.
// Slender rods of 0.1 kg, pins about z, gravity −y; `closed` false leaves the tree.

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

namespace momenta::test {

/// Links along their x axes, pins about z, the last link's tip pinned to (d, 0, 0) when closed.
inline std::string closed_chain_text(const std::vector<double>& lengths,
                                     const std::vector<double>& q0_deg, double d, bool closed) {
  std::string text = "name: closed chain\ngravity: [0, -9.81, 0]\nbodies:\n";
  for (std::size_t i = 0; i < lengths.size(); ++i) {
    text += fmt::format(
        "  - {{name: link{}, shape: slender_rod, mass: 0.1, length: {}, position: [{}, 0, 0], "
        "euler: {{sequence: XYZ, angles_deg: [0, 90, 0]}}}}\n",
        i, lengths[i], lengths[i] / 2);
  }
  text += "joints:\n";
  for (std::size_t i = 0; i < lengths.size(); ++i) {
    text += fmt::format(
        "  - {{name: pin{}, type: revolute, parent: {}, child: link{}, axis: [0, 0, 1], "
        "in_parent: {{position: [{}, 0, 0]}}, q0_deg: {}}}\n",
        i, i == 0 ? "world" : fmt::format("link{}", i - 1), i, i == 0 ? 0.0 : lengths[i - 1],
        q0_deg[i]);
  }
  if (closed) {
    text += fmt::format(
        "constraints:\n  - {{name: ground, type: hinge, body_a: world, point_a: [{}, 0, 0], "
        "body_b: link{}, point_b: [{}, 0, 0]}}\n",
        d, lengths.size() - 1, lengths.back());
  }
  return text;
}

inline std::string four_bar_text(bool closed = true) {
  return closed_chain_text({0.10, 0.30, 0.25}, {50, -14.73, -127.4}, 0.30, closed);
}

/// The first half going down at 30°, the second coming back up (n even, n ≥ 4).
inline std::string v_loop_text(int n, bool closed = true) {
  const std::vector<double> lengths(static_cast<std::size_t>(n), 0.1);
  std::vector<double> q0(lengths.size(), 0.0);
  q0[0] = -30;
  q0[static_cast<std::size_t>(n / 2)] = 60;
  const double d = n * 0.1 * std::cos(30 * 3.141592653589793 / 180);
  return closed_chain_text(lengths, q0, d, closed);
}

}  // namespace momenta::test
