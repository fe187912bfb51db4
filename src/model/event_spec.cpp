#include "momenta/model/event_spec.hpp"
#include "momenta/common/chars_to_double.hpp"

#include <charconv>
#include <cmath>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta::model {
namespace {

constexpr std::string_view kForm =
    "write it as 'QUANTITY < VALUE', 'QUANTITY > VALUE' or 'QUANTITY = VALUE' (a column of the "
    "run's table and a number in SI units: 'tension < 0', 'pivot.angle = 0')";

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == s.npos) return {};
  const auto last = s.find_last_not_of(" \t");
  return s.substr(first, last - first + 1);
}

// The whole of `text` as a number, or nothing.
std::optional<double> parse_number(std::string_view text) {
  if (text.starts_with('+')) text.remove_prefix(1);
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = chars_to_double(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end) return std::nullopt;
  return value;
}

}  // namespace

EventSpec parse_event_condition(std::string_view condition, EventAction action) {
  const auto fail = [&](std::string_view why) {
    throw InvalidArgument(fmt::format("event condition '{}': {}; {}", condition, why, kForm));
  };
  const auto op = condition.find_first_of("<>=");
  if (op == condition.npos) fail("no comparison (<, > or =)");
  if (condition.find_first_of("<>=", op + 1) != condition.npos) {
    fail("one comparison only (<= and >= mean the same as < and > for a crossing)");
  }
  EventSpec event;
  event.quantity = std::string(trim(condition.substr(0, op)));
  if (event.quantity.empty()) fail("no quantity before the comparison");
  const std::string_view value_text = trim(condition.substr(op + 1));
  const std::optional<double> value = parse_number(value_text);
  if (!value || !std::isfinite(*value)) {
    fail(fmt::format("'{}' is not a finite number", value_text));
  }
  event.value = *value;
  event.direction = condition[op] == '<'   ? EventDirection::falling
                    : condition[op] == '>' ? EventDirection::rising
                                           : EventDirection::either;
  event.name = event_condition_text(event);
  event.action = action;
  return event;
}

std::string event_condition_text(const EventSpec& event) {
  const char op = event.direction == EventDirection::falling  ? '<'
                  : event.direction == EventDirection::rising ? '>'
                                                              : '=';
  return fmt::format("{} {} {}", event.quantity, op, event.value);
}

std::string_view event_action_name(EventAction action) {
  return action == EventAction::stop ? "stop" : "record";
}

std::optional<EventAction> find_event_action(std::string_view name) {
  for (const EventAction action : {EventAction::record, EventAction::stop}) {
    if (event_action_name(action) == name) return action;
  }
  return std::nullopt;
}

}  // namespace momenta::model
