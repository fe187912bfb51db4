#pragma once
// What a sweep is (docs/sweeps.md): a model or part file, the numbers of it that vary and how,
// the job run on each variant, and the figures kept from each run. Pure description: the sweep
// file reader (io/sweep_file.hpp) fills it, the runner (sweep/runner.hpp) carries it out.

#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "momenta/model/simulation_settings.hpp"

namespace momenta::sweep {

/// A probability distribution of a Monte Carlo parameter. Sampled by inverting its CDF
/// (quantile), so that one uniform number gives one value on any machine.
struct Distribution {
  enum class Kind { kUniform, kNormal, kTruncatedNormal, kLogNormal };
  Kind kind = Kind::kUniform;
  /// uniform: low, high; normal and truncated normal: mean, standard deviation; log-normal: the
  /// mean and standard deviation of ln x (the median is e^mu).
  double first = 0.0;
  double second = 1.0;
  /// The truncated normal's bounds (either may be infinite, not both).
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();

  /// The value whose cumulative probability is u, 0 < u < 1.
  double quantile(double u) const;
  /// P(X ≤ x).
  double cdf(double x) const;
  /// The smallest and largest values it can take (infinite where unbounded).
  double support_low() const;
  double support_high() const;
};

/// One number of the file that varies.
struct Parameter {
  std::string path;  ///< dotted path in the file (io/file_template.hpp)
  std::string name;  ///< its column in the results (the path unless the file names it)
  /// The values of a grid, or the distribution of a Monte Carlo parameter.
  std::variant<std::vector<double>, Distribution> values;
  int line = 0;  ///< where the sweep file declares it (0: not from a file)
  int column = 0;
};

/// How the parameters' values combine into runs.
enum class Design {
  kFactorial,       ///< every combination of the grids; the last parameter varies fastest
  kZip,             ///< the k-th value of every grid in run k (grids of one length)
  kMonteCarlo,      ///< independent samples of every distribution
  kLatinHypercube,  ///< stratified samples: each distribution's n equal-probability strata once
};

/// The job each run does.
enum class JobKind {
  kSimulate,   ///< integrate the model (momenta simulate)
  kLinearize,  ///< linearize it and take the poles of A (momenta linearize / modes)
  kInertia,    ///< the mass properties of a part file (momenta inertia)
};

/// A figure kept from each run.
struct Metric {
  enum class Kind {
    // of a simulated output column
    kFinal,
    kInitial,
    kMax,
    kMin,
    kMaxAbs,
    kMean,
    kRms,
    kRiseTime,
    kSettlingTime,
    kOvershoot,
    kPeakTime,       // of a step: from the initial to the final
    kMaxReaction,    ///< largest |F| of a joint's reaction force, N
    kMaxAuditDrift,  ///< largest drift of an audited quantity ("energy", "|H|", "H", ...)
    // of a linearization
    kPoles,
    kNaturalFrequencies,
    kDampingRatios,
    // of a part
    kMass,
    kCentreOfMass,
    kInertia,
    kPrincipalMoments,
  };
  Kind kind = Kind::kFinal;
  std::string of;      ///< the column, joint or audited quantity it is taken of
  std::string name;    ///< its column in the results (for several columns: their prefix)
  double band = 0.02;  ///< settling time: the relative band
  int line = 0;        ///< where the sweep file declares it
  int column = 0;
};

/// The word a sweep file uses for a metric kind ("max", "settling_time", "poles"), and back.
std::string_view metric_keyword(Metric::Kind kind);
std::optional<Metric::Kind> metric_kind(std::string_view keyword);

/// A whole sweep.
struct SweepSpec {
  std::string name;             ///< the file's `name:`, or its stem
  std::string file;             ///< the sweep file's name, for messages
  std::filesystem::path model;  ///< the model file (simulate, linearize) or part file (inertia)
  JobKind job = JobKind::kSimulate;
  /// simulate: the sweep file's `simulation:`, over the model file's (as the command line's
  /// options are in momenta simulate).
  model::SimulationSettings run;
  /// linearize: the operating point ("initial" or "equilibrium"), inputs and outputs.
  std::string about = "initial";
  std::vector<std::string> inputs, outputs;
  std::vector<Parameter> parameters;
  Design design = Design::kFactorial;
  long samples = 0;        ///< Monte Carlo and Latin hypercube: the number of runs
  std::uint64_t seed = 0;  ///< Monte Carlo and Latin hypercube
  std::vector<Metric> metrics;
  /// Where each run's whole table goes, when asked: an .h5 file (a dataset per run) or a folder
  /// of CSV files; relative to the sweep file's folder.
  std::optional<std::filesystem::path> trajectories;
};

/// The values of every parameter in every run, from the spec alone: run k's values depend on
/// the seed and k, never on which process, thread or order computes them.
/// The most runs a sweep may have: 10⁸ runs of a millisecond are a day on a thousand cores.
/// RunPlan refuses more, with the count, before it allocates anything for them.
inline constexpr long kMaxRuns = 100'000'000;

class RunPlan {
 public:
  /// Checks the design against the parameters (grids for factorial and zip, distributions for
  /// the sampled designs, zipped grids of one length, samples ≥ 1) and draws the Latin
  /// hypercube's permutations. Throws InvalidArgument naming what does not fit.
  explicit RunPlan(const SweepSpec& spec);

  long run_count() const { return runs_; }
  /// The parameters' values of run `run` (0 ≤ run < run_count()), in the spec's order.
  std::vector<double> values(long run) const;

 private:
  const SweepSpec* spec_;
  long runs_ = 0;
  std::vector<std::vector<long>> strata_;  // Latin hypercube: parameter → run → stratum
};

/// The uniform number in (0, 1) of stream `stream` at `counter` under `seed`: a counter-based
/// generator (SplitMix64's mixing of the three), so any run's numbers are drawn without drawing
/// another's. 53 random bits, never 0 or 1.
double uniform_number(std::uint64_t seed, std::uint64_t stream, std::uint64_t counter);

}  // namespace momenta::sweep
