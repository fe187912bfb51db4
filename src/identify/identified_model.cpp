#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "momenta/common/number_text.hpp"
#include "momenta/identify/grey_box.hpp"
#include "momenta/io/file_template.hpp"

namespace momenta::identify {

std::string identified_model_text(const GreyBoxProblem& problem, const GreyBoxEstimate& estimate) {
  const io::ModelTemplate file(problem.model);
  std::vector<io::NumberOverride> overrides;
  std::string header = fmt::format("# Identified by momenta from {}{}:\n",
                                   problem.name.empty() ? "measured data" : problem.name,
                                   estimate.converged ? "" : " (the fit did not converge)");
  for (std::size_t i = 0; i < estimate.names.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    // A number of one experiment alone (its initial state, say) is that test's, not the model's.
    const bool shared = estimate.experiments[i].empty();
    if (shared) overrides.push_back({estimate.paths[i], estimate.value[k]});
    const std::optional<double> before = file.number_at(estimate.paths[i]);
    header += fmt::format(
        "#   {} = {} ± {} (95 %: {} … {}); {}\n", estimate.names[i],
        number_text(estimate.value[k], 6), number_text(estimate.standard_error[k], 3),
        number_text(estimate.lower95[k], 6), number_text(estimate.upper95[k], 6),
        !shared  ? fmt::format("experiment '{}' alone, not written below", estimate.experiments[i])
        : before ? fmt::format("the file had {}", number_text(*before, 6))
                 : std::string("not in the file before"));
  }
  return header + file.text_with(overrides);
}

}  // namespace momenta::identify
