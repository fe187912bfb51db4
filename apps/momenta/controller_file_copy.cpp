#include "controller_file_copy.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "momenta/common/error.hpp"
#include "momenta/io/mjcf_file.hpp"
#include "momenta/io/urdf_file.hpp"
#include "option_checks.hpp"

namespace momenta::cli {
namespace {

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw FileError(fmt::format("{}: cannot read the model file", path));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Where a line's text starts (its indentation), or npos for a blank line.
std::size_t indentation(const std::string& line) { return line.find_first_not_of(" \t"); }

// Removes the list entry that starts on line `first` (1-based): its dash line and every line
// indented deeper than its dash (blank lines inside it too).
void remove_entry(std::vector<std::string>& lines, int first) {
  const auto begin = static_cast<std::size_t>(first - 1);
  const std::size_t dash = indentation(lines[begin]);
  std::size_t end = begin + 1;
  while (end < lines.size()) {
    const std::size_t at = indentation(lines[end]);
    if (at != std::string::npos && at <= dash) break;
    ++end;
  }
  lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(begin),
              lines.begin() + static_cast<std::ptrdiff_t>(end));
}

// A number as YAML reads it back exactly.
std::string number(double x) { return fmt::format("{}", x); }

}  // namespace

void write_controller_copy(const LoadedLinearModel& loaded, const analysis::StateSpace& plant,
                           const MatX& K, const std::string& name, const std::string& how,
                           const std::string& copy, bool force) {
  const io::ModelFile& file = loaded.file;
  const model::Model& model = file.model;
  const std::string& source = loaded.file.file;
  if (io::is_urdf_path(source) || io::is_mjcf_path(source)) {
    throw InvalidArgument(fmt::format(
        "--write: {} is not a momenta model file (YAML); the controller goes into one: `momenta "
        "export` makes one from an MJCF or URDF model",
        source));
  }
  if (model.has_controllers()) {
    throw InvalidArgument(fmt::format(
        "--write: {} has controllers already; add this one to its `controllers:` by hand", source));
  }
  if (same_file(source, copy)) {
    throw FileError(fmt::format("--write {}: that is the model file itself; name a copy", copy));
  }
  if (std::filesystem::exists(copy) && !force) {
    throw FileError(fmt::format("--write {}: the file exists; pass --force to overwrite it", copy));
  }
  // What the controller measures and drives must be coordinates and signals.
  for (const std::string& state : plant.state_names()) {
    bool coordinate = false;
    for (int i = 0; i < model.nq(); ++i) coordinate |= model.q_name(i) == state;
    for (int i = 0; i < model.nv(); ++i) coordinate |= model.v_name(i) == state;
    if (!coordinate) {
      throw InvalidArgument(fmt::format(
          "--write: state '{}' is no coordinate a controller can measure (a rotation's tangent); "
          "write the controller by hand",
          state));
    }
  }
  std::vector<std::string> lines = lines_of(source);
  std::vector<int> entries;  // the inputs' entries to take out, by line
  for (const std::string& input : plant.input_names()) {
    if (!model.find_signal(input)) {
      throw InvalidArgument(fmt::format(
          "--write: input '{}' is a prescribed coordinate; a controller drives forces and "
          "torques",
          input));
    }
    for (const io::ItemLocation& at : file.items) {
      if (at.item.kind == ModelItemRef::Kind::signal && at.item.name == input)
        entries.push_back(at.line);
    }
  }
  std::sort(entries.rbegin(), entries.rend());
  for (int line : entries) remove_entry(lines, line);

  // The controller, in the file's own vocabulary.
  const VecX x0 = [&] {
    VecX x(plant.state_names().size());
    for (std::size_t k = 0; k < plant.state_names().size(); ++k) {
      const std::string& state = plant.state_names()[k];
      double value = 0.0;
      for (int i = 0; i < model.nq(); ++i)
        if (model.q_name(i) == state) value = loaded.result.linear.point.q[i];
      for (int i = 0; i < model.nv(); ++i)
        if (model.v_name(i) == state) value = loaded.result.linear.point.v[i];
      x[static_cast<Eigen::Index>(k)] = value;
    }
    return x;
  }();
  std::vector<std::string> rows;
  for (Eigen::Index i = 0; i < K.rows(); ++i) {
    std::vector<std::string> row;
    for (Eigen::Index j = 0; j < K.cols(); ++j) row.push_back(number(K(i, j)));
    rows.push_back(fmt::format("[{}]", fmt::join(row, ", ")));
  }
  std::ostringstream out;
  for (const std::string& line : lines) out << line << '\n';
  out << '\n'
      << "# " << how << '\n'
      << "controllers:\n"
      << "  - name: " << name << '\n'
      << "    type: state_feedback\n"
      << "    measure: [" << fmt::format("{}", fmt::join(plant.state_names(), ", ")) << "]\n"
      << "    gain: [" << fmt::format("{}", fmt::join(rows, ", ")) << "]\n";
  if (!x0.isZero(0.0)) {
    std::vector<std::string> x;
    for (Eigen::Index i = 0; i < x0.size(); ++i) x.push_back(number(x0[i]));
    out << "    state_reference: [" << fmt::format("{}", fmt::join(x, ", ")) << "]\n";
  }
  if (plant.is_discrete()) out << "    sample_time: " << number(plant.sample_time()) << '\n';
  out << "    drives: [" << fmt::format("{}", fmt::join(plant.input_names(), ", ")) << "]\n";
  std::ofstream written(copy);
  written << out.str();
  if (!written) throw FileError(fmt::format("--write {}: cannot write the file", copy));
}

}  // namespace momenta::cli
