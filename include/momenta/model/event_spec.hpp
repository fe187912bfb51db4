#pragma once
// An event: a condition on one quantity of a run (a column of `momenta simulate`'s table — a
// coordinate, a speed, an energy, an output) that the run watches between steps. It happens when
// the condition becomes true: "tension < 0" when the wire's tension falls through zero,
// "bob.z > 0.5" when the bob rises through 0.5 m, "pivot.angle = 0" when the angle crosses zero
// either way. A description only; simulate/event_monitor.hpp resolves and watches it.

#include <optional>
#include <string>
#include <string_view>

namespace momenta::model {

/// Which way the quantity crosses the value.
enum class EventDirection {
  falling,  ///< "<": from ≥ value to < value
  rising,   ///< ">": from ≤ value to > value
  either,   ///< "=": a sign change of quantity − value either way
};

/// What the run does when the event happens: write a row at its time (always) and go on, or end
/// the run there.
enum class EventAction { record, stop };

struct EventSpec {
  std::string name;      ///< how the summary names it: the file's `name`, else the condition
  std::string quantity;  ///< a column name of the run's table: "tension", "pivot.angle"
  EventDirection direction = EventDirection::falling;
  double value = 0.0;  ///< in the quantity's SI unit
  EventAction action = EventAction::record;
};

/// Reads a condition "QUANTITY < VALUE", "QUANTITY > VALUE" or "QUANTITY = VALUE" (spaces
/// optional; the value a finite number in SI units) into an EventSpec named by the condition
/// itself, with `action`. Throws InvalidArgument saying what is wrong and the form expected: no
/// operator, two of them, an empty quantity, a value that is not a finite number.
EventSpec parse_event_condition(std::string_view condition,
                                EventAction action = EventAction::record);

/// The condition as the summary prints it: "tension < 0".
std::string event_condition_text(const EventSpec& event);

/// "record" or "stop".
std::string_view event_action_name(EventAction action);

/// The action of that name (event_action_name's inverse), or nothing.
std::optional<EventAction> find_event_action(std::string_view name);

}  // namespace momenta::model
