// Model files, `inputs:`: the signals u(t) that drive loads and prescribed joints.

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "csv/csv_fields.hpp"
#include "model_file/model_file_internal.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/io/files_read.hpp"

namespace momenta::io::detail {
namespace {

using model::Signal;

// Each signal type and the keys it takes (besides `name` and `type`).
const std::vector<EntryType>& signal_types() {
  static const std::vector<EntryType> types = {
      {"constant", {"value"}},
      {"step", {"start", "initial", "final", "rise_time"}},
      {"ramp", {"start", "slope", "offset", "stop"}},
      {"pulse", {"start", "width", "amplitude", "offset", "period"}},
      {"sine", {"amplitude", "frequency", "phase", "phase_deg", "offset", "start"}},
      {"chirp", {"amplitude", "f0", "f1", "start", "duration"}},
      {"table", {"times", "values", "csv"}},
  };
  return types;
}

using csv::parse_number;
using csv::trim;

// A two-column CSV file `time,value`: one optional header line, blank lines and `#` comments
// skipped. Errors name the CSV file and its line; a missing file is reported at `ref`.
model::TableSignal read_csv_table(const YamlNode& ref, const std::filesystem::path& base_dir) {
  std::filesystem::path path = ref.as_string();
  if (path.is_relative()) path = base_dir / path;
  std::ifstream in(path);
  if (!std::filesystem::is_regular_file(path) || !in) {
    throw FileError(ref.error(fmt::format("cannot read the CSV file '{}' (not found or unreadable)",
                                          path.string()))
                        .what());
  }
  note_file_read(path);
  model::TableSignal table;
  std::string line;
  int number = 0;
  bool header_allowed = true;
  while (std::getline(in, line)) {
    ++number;
    const std::string text = trim(line);
    if (text.empty() || text.front() == '#') continue;
    const auto comma = text.find(',');
    double t = 0.0, u = 0.0;
    const bool ok = comma != std::string::npos && text.find(',', comma + 1) == std::string::npos &&
                    parse_number(trim(text.substr(0, comma)), t) &&
                    parse_number(trim(text.substr(comma + 1)), u);
    if (!ok && header_allowed) {
      header_allowed = false;  // a header such as `time,value`
      continue;
    }
    header_allowed = false;
    if (!ok) {
      throw ParseError(path.string(), number, 0,
                       fmt::format("expected two finite numbers 'time,value', got '{}'", text));
    }
    if (!table.times.empty() && !(t > table.times.back())) {
      throw ParseError(
          path.string(), number, 0,
          fmt::format("times must increase: {} does not come after {}", t, table.times.back()));
    }
    table.times.push_back(t);
    table.values.push_back(u);
  }
  if (table.times.size() < 2) {
    throw ParseError(
        path.string(), 0, 0,
        fmt::format("a table needs at least two rows 'time,value', found {}", table.times.size()));
  }
  return table;
}

// `times:` and `values:` written in the file.
model::TableSignal read_inline_table(const YamlNode& entry) {
  const YamlNode times_node = entry.at("times");
  const YamlNode values_node = entry.at("values");
  const std::vector<YamlNode> times = times_node.elements();
  const std::vector<YamlNode> values = values_node.elements();
  if (times.size() < 2) times_node.fail("a table needs at least two times");
  if (values.size() != times.size()) {
    values_node.fail(fmt::format("{} values for {} times: give one value per time", values.size(),
                                 times.size()));
  }
  model::TableSignal table;
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double t = times[i].as_double();
    if (i > 0 && !(t > table.times.back())) {
      times[i].fail(
          fmt::format("times must increase: {} does not come after {}", t, table.times.back()));
    }
    table.times.push_back(t);
    table.values.push_back(values[i].as_double());
  }
  return table;
}

Signal::Shape read_shape(const YamlNode& e, std::string_view type, const Context& ctx) {
  const auto num = [&](std::string_view key, double fallback, Bound bound = Bound::kFinite) {
    return e.find_number(key, bound).value_or(fallback);
  };
  if (type == "constant") return model::ConstantSignal{e.number("value")};
  if (type == "step") {
    return model::StepSignal{num("start", 0.0), num("initial", 0.0), e.number("final"),
                             num("rise_time", 0.0, Bound::kNonNegative)};
  }
  if (type == "ramp") {
    model::RampSignal r;
    r.start = num("start", 0.0);
    r.slope = e.number("slope");
    r.offset = num("offset", 0.0);
    if (const auto stop = e.find("stop")) {
      r.stop = stop->as_double();
      if (!(r.stop > r.start)) {
        stop->fail(fmt::format("stop {} s must come after start {} s", r.stop, r.start));
      }
    }
    return r;
  }
  if (type == "pulse") {
    return model::PulseSignal{num("start", 0.0), e.number("width", Bound::kPositive),
                              e.number("amplitude"), num("offset", 0.0),
                              num("period", 0.0, Bound::kNonNegative)};
  }
  if (type == "sine") {
    return model::SineSignal{e.number("amplitude"), e.number("frequency", Bound::kNonNegative),
                             e.find_angle("phase").value_or(0.0), num("offset", 0.0),
                             num("start", 0.0)};
  }
  if (type == "chirp") {
    return model::ChirpSignal{e.number("amplitude"), e.number("f0", Bound::kNonNegative),
                              e.number("f1", Bound::kNonNegative), num("start", 0.0),
                              e.number("duration", Bound::kPositive)};
  }
  // A table: inline, or from a CSV file.
  if (e.has("csv")) {
    for (const std::string_view key : {"times", "values"}) {
      if (e.has(key)) e.at(key).fail("give either 'csv' or 'times' and 'values', not both");
    }
    return read_csv_table(e.at("csv"), ctx.base_dir);
  }
  if (!e.has("times") && !e.has("values")) {
    e.fail("a table needs 'times' and 'values' lists, or a 'csv' file of rows 'time,value'");
  }
  return read_inline_table(e);
}

}  // namespace

void read_signals(const YamlNode& root, Context& ctx, model::ModelBuilder& builder) {
  for (const YamlNode& e : list_section(root, "inputs")) {
    e.expect_map("a signal: a map with 'name' and 'type'");
    const YamlNode name = name_node(e);
    const std::string_view type = entry_type(e, signal_types(), "signal").name;
    ctx.signals.add(name.as_string(), e, name);
    Signal::Shape shape = read_shape(e, type, ctx);
    try {
      builder.add_signal(Signal(name.as_string(), std::move(shape)));
    } catch (const InvalidArgument& error) {
      e.fail(one_line(error.what()));
    }
  }
}

}  // namespace momenta::io::detail
