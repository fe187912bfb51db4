// A Bode test's table read (identify/frequency_response_data.hpp): a translation unit of its own,
// with io below it alone, so that the identification file's reader can be fuzzed without the
// analysis it runs (tests/fuzz/identification_file_fuzz.cpp).
#include <cmath>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/identify/frequency_response_data.hpp"

namespace momenta::identify {
namespace {

VecX column(const io::MeasuredTable& table, std::string_view name, std::string_view what) {
  const auto c = table.find(name);
  if (!c) {
    throw InvalidArgument(fmt::format("{}: no column '{}' ({}); its columns: {}", table.source,
                                      name, what, fmt::join(table.columns, ", ")));
  }
  return table.values.col(*c);
}

}  // namespace

MeasuredFrequencyResponse frequency_response_data(const io::MeasuredTable& table) {
  MeasuredFrequencyResponse data;
  data.source = table.source;
  data.lines = table.lines;
  data.frequency = column(table, "frequency", "the test frequencies, Hz");
  data.phase_deg = column(table, "phase", "the phase of the output against the input, degrees");
  const bool in_db = table.find("magnitude_db").has_value();
  const VecX magnitude = in_db ? column(table, "magnitude_db", "20 log₁₀|G|")
                               : column(table, "magnitude", "|G|, or a magnitude_db column in dB");
  data.magnitude_db.resize(magnitude.size());
  for (Eigen::Index k = 0; k < magnitude.size(); ++k) {
    const int line = table.lines.empty() ? int(k) + 2 : table.lines[std::size_t(k)];
    if (!(data.frequency[k] > 0.0)) {
      throw InvalidArgument(fmt::format("{}:{}: frequency {} Hz: a test frequency must be > 0",
                                        table.source, line, data.frequency[k]));
    }
    if (k > 0 && !(data.frequency[k] > data.frequency[k - 1])) {
      throw InvalidArgument(fmt::format("{}:{}: frequency {} Hz does not increase (after {} Hz)",
                                        table.source, line, data.frequency[k],
                                        data.frequency[k - 1]));
    }
    if (!in_db && !(magnitude[k] > 0.0)) {
      throw InvalidArgument(
          fmt::format("{}:{}: magnitude {}: |G| must be > 0 (a magnitude_db column takes dB)",
                      table.source, line, magnitude[k]));
    }
    data.magnitude_db[k] = in_db ? magnitude[k] : 20.0 * std::log10(magnitude[k]);
  }
  return data;
}

}  // namespace momenta::identify
