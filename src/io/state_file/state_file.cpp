#include "momenta/io/state_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string_view>
#include <system_error>
#include <utility>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "momenta/common/error.hpp"
#include "momenta/io/yaml_reader.hpp"

namespace momenta::io {

using json = nlohmann::ordered_json;

namespace {

// The 1-based line and column of byte `offset` (1-based, as nlohmann's parse errors count) of
// `text`.
std::pair<int, int> position_in(const std::string& text, std::size_t offset) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i + 1 < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
      ++column;  // a character, not a UTF-8 continuation byte
    }
  }
  return {line, column};
}

// What went wrong with the JSON, in momenta's words: nlohmann's message names its own exception
// ("[json.exception.parse_error.101] parse error at line 1, column 1: syntax error while parsing
// value - invalid literal; last read: 'N'"); kept is what it read last.
std::string json_problem(const std::string& text, std::size_t offset, const std::string& what) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
    return "the file is empty; expected {\"q\": [...], \"v\": [...]}";
  }
  const std::size_t at = std::min(offset > 0 ? offset - 1 : 0, text.size() - 1);
  const std::string_view rest = std::string_view(text).substr(at);
  for (const std::string_view word : {"NaN", "nan", "Infinity", "inf", "-Infinity", "-inf"}) {
    if (rest.starts_with(word) ||
        (at > 0 && std::string_view(text).substr(at - 1).starts_with(word))) {
      return "JSON has no NaN or Infinity, and a state must be finite";
    }
  }
  const auto last_read = what.find("last read: ");
  const std::string read = last_read == std::string::npos ? "" : what.substr(last_read + 11);
  if (what.find("unexpected end of input") != std::string::npos) {
    return "the JSON ends before its value does (a bracket or brace is not closed)";
  }
  if (what.find("expected end of input") != std::string::npos) {
    return "text after the JSON value: the file should end after its closing }";
  }
  return fmt::format("not valid JSON here{}", read.empty() ? "" : fmt::format(" (at {})", read));
}

}  // namespace

StateFile parse_state_file(const std::string& text, const std::string& name, int nq, int nv) {
  // A binary file: its first control character, where a JSON parser would only say where it
  // stopped.
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte < 0x20 && byte != '\n' && byte != '\r' && byte != '\t') {
      const auto [line, column] = position_in(text, i + 1);
      throw ParseError(name, line, column,
                       fmt::format("not a text file (byte 0x{:02x}); a state file is JSON text "
                                   "{{\"q\": [...], \"v\": [...]}}",
                                   byte));
    }
  }
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    const auto [line, column] = position_in(text, e.byte);
    throw ParseError(name, line, column, json_problem(text, e.byte, e.what()));
  } catch (const json::exception& e) {
    // A number beyond double precision ("t": 1e400) is the one other way parsing fails;
    // nlohmann names the number ("number overflow parsing '1e400'"), not where it is.
    const std::string what = e.what();
    const auto quote = what.find('\'');
    const std::string number =
        quote == std::string::npos ? "" : what.substr(quote + 1, what.rfind('\'') - quote - 1);
    const std::size_t at = number.empty() ? std::string::npos : text.find(number);
    const auto [line, column] =
        at == std::string::npos ? std::pair{0, 0} : position_in(text, at + 1);
    throw ParseError(name, line, column,
                     fmt::format("{} is beyond double precision (±1.8e308)",
                                 number.empty() ? std::string("a number") : number));
  }
  if (!j.is_object()) {
    throw InvalidArgument(
        fmt::format("{}: expected an object {{\"q\": [...], \"v\": [...]}}", name));
  }
  for (const auto& [key, value] : j.items()) {
    if (key != "q" && key != "v" && key != "t") {
      throw InvalidArgument(
          fmt::format("{}: unknown key '{}' (expected q, v and optionally t)", name, key));
    }
  }
  const auto vector = [&](const char* key, int size) {
    if (!j.contains(key)) {
      throw InvalidArgument(fmt::format("{}: missing '{}' ({} numbers)", name, key, size));
    }
    const json& a = j.at(key);
    if (!a.is_array() || static_cast<int>(a.size()) != size ||
        !std::all_of(a.begin(), a.end(), [](const json& x) { return x.is_number(); })) {
      throw InvalidArgument(
          fmt::format("{}: '{}' must be a list of {} numbers (the model's {}); "
                      "got {}",
                      name, key, size, key[0] == 'q' ? "nq" : "nv",
                      a.dump(-1, ' ', false, json::error_handler_t::replace).substr(0, 200)));
    }
    VecX x(size);
    for (int i = 0; i < size; ++i) {
      x[i] = a.at(static_cast<std::size_t>(i)).get<double>();
      // Bounded as a model file's numbers are (kLargestNumber): q², m v² stay finite.
      if (!(std::abs(x[i]) <= kLargestNumber)) {
        throw InvalidArgument(
            fmt::format("{}: {}[{}] = {} is beyond ±{:g}, far past anything physical", name, key, i,
                        x[i], kLargestNumber));
      }
    }
    return x;
  };
  StateFile p;
  p.q = vector("q", nq);
  p.v = vector("v", nv);
  if (j.contains("t")) {
    if (!j.at("t").is_number())
      throw InvalidArgument(fmt::format("{}: 't' must be a number", name));
    p.t = j.at("t").get<double>();
    if (!(std::abs(p.t) <= kLargestNumber)) {
      throw InvalidArgument(fmt::format("{}: t = {} is beyond ±{:g} s", name, p.t, kLargestNumber));
    }
  }
  return p;
}

StateFile read_state_file(const std::filesystem::path& path, int nq, int nv) {
  const std::string name = path.string();
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status))
    throw FileError(fmt::format("{}: state file not found", name));
  if (std::filesystem::is_directory(status)) {
    throw FileError(fmt::format("{}: is a folder, not a state file", name));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(fmt::format("{}: cannot open the state file", name));
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return parse_state_file(text, name, nq, nv);
}

}  // namespace momenta::io
