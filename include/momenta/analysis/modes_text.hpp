#pragma once
// The modes of a linear model as text: the table `momenta modes` prints and the Python reprs
// of Modes and NormalModes show, written in one place.

#include <string>
#include <vector>

#include "momenta/analysis/modes.hpp"

namespace momenta::analysis {

/// An eigenvalue below this fraction of the largest is a rigid-body (or neutral) mode's zero, and
/// prints as 0 (the modes table here, the report's panel): the linearization's central
/// differences leave A with errors near 1e-10 of its scale, and a double zero eigenvalue splits by
/// about their square root (the flexible satellite's 2.4e-9 rad/s against its 1 rad/s boom mode;
/// a rolling coin's symmetry, 5e-7 against its 15 rad/s wobble). A physical mode this slow beside
/// the fastest is not resolved by the linearization anyway; JSON keeps the computed value. A model
/// whose every eigenvalue is that small has no scale to tell round-off by, and prints them as
/// they are.
inline constexpr double kZeroEigenvalueRelative = 1e-6;

/// The modes table as cells, for a front end that lays it out itself (a notebook's HTML): the
/// header, then one row per mode of the six columns below, each figure as modes_table shows it.
struct ModesTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};
ModesTable modes_table_cells(const Modes& modes);

/// One line per mode: number, eigenvalue (1/s), ωn (rad/s and Hz), ζ (blank at λ = 0: it does
/// not exist) and the shape's three largest entries by name, under a header line. Each line
/// starts with two spaces.
std::string modes_table(const Modes& modes);

/// One line per undamped normal mode: ω² and ω (rad/s, Hz) — or, for ω² < 0, the rate at which
/// it grows — and its mass-normalized shape by coordinate.
std::string normal_modes_table(const NormalModes& modes);

}  // namespace momenta::analysis
