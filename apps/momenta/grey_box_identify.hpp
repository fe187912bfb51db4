#pragma once
// `momenta identify FILE.yaml` where FILE is an identification file: the grey-box route
// (identify/grey_box.hpp) — estimates, intervals, correlations, identifiability, each channel's
// noise and residual checks, the identified model written out. Documented in
// docs/identification.md.

#include <optional>
#include <string>

namespace momenta::cli {

struct GreyBoxRequest {
  std::string file;  ///< the identification file
  bool json = false;
  std::optional<std::string> report;  ///< an HTML page
  std::optional<std::string> output;  ///< the identified model file
  bool force = false;
};

void run_grey_box(const GreyBoxRequest& request);

}  // namespace momenta::cli
