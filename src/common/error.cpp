#include "momenta/common/error.hpp"

#include <fmt/format.h>

namespace momenta {
namespace {

std::string locate(const std::string& file, int line, int column, const std::string& message) {
  if (line <= 0) return fmt::format("{}: {}", file, message);
  if (column <= 0) return fmt::format("{}:{}: {}", file, line, message);
  return fmt::format("{}:{}:{}: {}", file, line, column, message);
}

}  // namespace

namespace {

constexpr std::string_view kOpen = "‹", kClose = "›";

// Calls f(name, value) for each mark of `text` and g(piece) for the text between them.
template <class Mark, class Text>
void each_mark(std::string_view text, Mark&& mark, Text&& between) {
  std::size_t at = 0;
  while (true) {
    const std::size_t open = text.find(kOpen, at);
    const std::size_t close = open == text.npos ? text.npos : text.find(kClose, open);
    if (close == text.npos) {
      between(text.substr(at));
      return;
    }
    between(text.substr(at, open - at));
    const std::string_view inside = text.substr(open + kOpen.size(), close - open - kOpen.size());
    const std::size_t equals = inside.find('=');
    mark(inside.substr(0, equals),
         equals == inside.npos ? std::string_view() : inside.substr(equals + 1));
    at = close + kClose.size();
  }
}

}  // namespace

std::string plain_spelling(std::string_view name, std::string_view value) {
  return value.empty() ? std::string(name) : std::string(name) + " " + std::string(value);
}

std::string keep_option_marks(std::string_view name, std::string_view value) {
  return std::string(kOpen) + std::string(name) + (value.empty() ? "" : "=") + std::string(value) +
         std::string(kClose);
}

std::string spell_options(std::string_view text, OptionSpelling spell) {
  std::string out;
  each_mark(
      text, [&](std::string_view name, std::string_view value) { out += spell(name, value); },
      [&](std::string_view piece) { out += piece; });
  return out;
}

Error::Error(const OptionMessage& message)
    : std::runtime_error(spell_options(message.text, plain_spelling)), option_text_(message.text) {}

std::string Error::spelled(OptionSpelling spell) const {
  return option_text_.empty() ? std::string(what()) : spell_options(option_text_, spell);
}

std::vector<std::string> Error::options() const {
  std::vector<std::string> names;
  each_mark(
      option_text_, [&](std::string_view name, std::string_view) { names.emplace_back(name); },
      [](std::string_view) {});
  return names;
}

ParseError::ParseError(std::string file, int line, int column, const std::string& message)
    : Error(locate(file, line, column, message)),
      file_(std::move(file)),
      line_(line),
      column_(column) {}

ParseError::ParseError(std::string file, int line, int column, const OptionMessage& message)
    : Error(OptionMessage{locate(file, line, column, message.text)}),
      file_(std::move(file)),
      line_(line),
      column_(column) {}

}  // namespace momenta
