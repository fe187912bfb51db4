#include "interrupt.hpp"

#include <csignal>

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta::cli {
namespace {

std::atomic<bool> stop_requested{false};
std::atomic<bool> handlers_installed{false};

extern "C" void request_stop(int signal_number) {
  stop_requested.store(true);
  std::signal(signal_number, SIG_DFL);
}

}  // namespace

bool stops_on_request(std::string_view command) {
  return command == "simulate" || command == "report" || command == "sweep";
}

const std::atomic<bool>& stop_on_signals() {
  if (!handlers_installed.exchange(true)) {
    std::signal(SIGINT, request_stop);
    std::signal(SIGTERM, request_stop);
  }
  return stop_requested;
}

void throw_if_stop_requested(std::string_view what_was_left) {
  if (stop_requested.load()) {
    throw Interrupted(fmt::format("stopped on request before the run began; {}", what_was_left));
  }
}

}  // namespace momenta::cli
