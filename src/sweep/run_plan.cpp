#include <algorithm>
#include <numeric>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/sweep/sweep_spec.hpp"

namespace momenta::sweep {
namespace {

// SplitMix64's output function (Steele, Lea & Flood 2014): a bijection of 64-bit words whose
// every output bit depends on every input bit.
std::uint64_t mix(std::uint64_t z) {
  z += 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// Streams of the plan's numbers: parameter p's value in run k is drawn from stream p at counter
// k; the Latin hypercube's shuffles from stream kShuffle + p.
constexpr std::uint64_t kShuffle = 1ULL << 32;

const std::vector<double>& grid_of(const Parameter& p) {
  return std::get<std::vector<double>>(p.values);
}

const Distribution& distribution_of(const Parameter& p) { return std::get<Distribution>(p.values); }

void check_parameters(const SweepSpec& spec) {
  const bool sampled = spec.design == Design::kMonteCarlo || spec.design == Design::kLatinHypercube;
  for (const Parameter& p : spec.parameters) {
    const bool is_grid = std::holds_alternative<std::vector<double>>(p.values);
    if (sampled && is_grid) {
      throw InvalidArgument(fmt::format(
          "parameter '{}' has a grid of values, but the design samples distributions; give it a "
          "distribution, or use design: factorial or zip",
          p.name));
    }
    if (!sampled && !is_grid) {
      throw InvalidArgument(fmt::format(
          "parameter '{}' has a distribution, but the design is a grid; use design: monte_carlo "
          "or latin_hypercube with samples and a seed",
          p.name));
    }
    if (is_grid && grid_of(p).empty()) {
      throw InvalidArgument(fmt::format("parameter '{}' has no values", p.name));
    }
  }
}

long count_runs(const SweepSpec& spec) {
  switch (spec.design) {
    case Design::kFactorial: {
      long runs = 1;
      for (const Parameter& p : spec.parameters) {
        const auto n = static_cast<long>(grid_of(p).size());
        if (runs > (1LL << 40) / n) {
          throw InvalidArgument("the factorial design has more than 2^40 runs");
        }
        runs *= n;
      }
      return runs;
    }
    case Design::kZip: {
      const std::size_t n = spec.parameters.empty() ? 1 : grid_of(spec.parameters[0]).size();
      for (const Parameter& p : spec.parameters) {
        if (grid_of(p).size() != n) {
          throw InvalidArgument(fmt::format(
              "zipped parameters need lists of one length: '{}' has {} values, '{}' has {}",
              spec.parameters[0].name, n, p.name, grid_of(p).size()));
        }
      }
      return static_cast<long>(n);
    }
    case Design::kMonteCarlo:
    case Design::kLatinHypercube:
      if (spec.samples < 1) throw InvalidArgument("a sampled design needs samples ≥ 1");
      return spec.samples;
  }
  return 0;
}

// A uniformly random permutation of 0..n−1 (Fisher–Yates), from stream `stream` under `seed`.
std::vector<long> shuffled(long n, std::uint64_t seed, std::uint64_t stream) {
  std::vector<long> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0L);
  for (long i = n - 1; i > 0; --i) {
    const double u = uniform_number(seed, stream, static_cast<std::uint64_t>(i));
    const auto j = std::min(i, static_cast<long>(u * static_cast<double>(i + 1)));
    std::swap(order[static_cast<std::size_t>(i)], order[static_cast<std::size_t>(j)]);
  }
  return order;
}

}  // namespace

double uniform_number(std::uint64_t seed, std::uint64_t stream, std::uint64_t counter) {
  const std::uint64_t bits = mix(mix(mix(seed) ^ stream) ^ counter) >> 11;  // 53 bits
  return (static_cast<double>(bits) + 0.5) * 0x1.0p-53;
}

RunPlan::RunPlan(const SweepSpec& spec) : spec_(&spec) {
  check_parameters(spec);
  runs_ = count_runs(spec);
  if (runs_ > kMaxRuns) {
    throw InvalidArgument(fmt::format(
        "this sweep has {:.3g} runs, more than the {:.0e} a sweep may have (at a millisecond a "
        "run, {:.3g} days on one core): fewer samples or grid values",
        static_cast<double>(runs_), static_cast<double>(kMaxRuns),
        static_cast<double>(runs_) * 1e-3 / 86400.0));
  }
  if (spec.design == Design::kLatinHypercube) {
    for (std::size_t p = 0; p < spec.parameters.size(); ++p) {
      strata_.push_back(shuffled(runs_, spec.seed, kShuffle + p));
    }
  }
}

std::vector<double> RunPlan::values(long run) const {
  const std::vector<Parameter>& parameters = spec_->parameters;
  std::vector<double> values(parameters.size());
  switch (spec_->design) {
    case Design::kFactorial: {
      long rest = run;
      for (std::size_t p = parameters.size(); p-- > 0;) {
        const std::vector<double>& grid = grid_of(parameters[p]);
        const auto n = static_cast<long>(grid.size());
        values[p] = grid[static_cast<std::size_t>(rest % n)];
        rest /= n;
      }
      break;
    }
    case Design::kZip:
      for (std::size_t p = 0; p < parameters.size(); ++p) {
        values[p] = grid_of(parameters[p])[static_cast<std::size_t>(run)];
      }
      break;
    case Design::kMonteCarlo:
      for (std::size_t p = 0; p < parameters.size(); ++p) {
        const double u = uniform_number(spec_->seed, p, static_cast<std::uint64_t>(run));
        values[p] = distribution_of(parameters[p]).quantile(u);
      }
      break;
    case Design::kLatinHypercube:
      for (std::size_t p = 0; p < parameters.size(); ++p) {
        const double jitter = uniform_number(spec_->seed, p, static_cast<std::uint64_t>(run));
        const auto stratum = static_cast<double>(strata_[p][static_cast<std::size_t>(run)]);
        values[p] = distribution_of(parameters[p])
                        .quantile((stratum + jitter) / static_cast<double>(runs_));
      }
      break;
  }
  return values;
}

}  // namespace momenta::sweep
