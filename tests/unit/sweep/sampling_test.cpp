// The sampled designs (sweep/sweep_spec.hpp): each distribution's samples against its exact
// moments and CDF (Kolmogorov–Smirnov), the Latin hypercube's strata, and the run-by-run
// independence of the numbers that makes a sweep's results the same however it is split.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/sweep/sweep_spec.hpp"

namespace momenta::sweep {
namespace {

constexpr long kSamples = 20000;

std::vector<double> samples_of(const Distribution& d, Design design, std::uint64_t seed = 7) {
  SweepSpec spec;
  spec.parameters.push_back({"x", "x", d});
  spec.design = design;
  spec.samples = kSamples;
  spec.seed = seed;
  const RunPlan plan(spec);
  std::vector<double> x;
  for (long k = 0; k < plan.run_count(); ++k) x.push_back(plan.values(k)[0]);
  return x;
}

// sup |F_n − F| over the sample: the Kolmogorov–Smirnov statistic.
double ks_statistic(std::vector<double> x, const Distribution& d) {
  std::sort(x.begin(), x.end());
  const auto n = static_cast<double>(x.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double F = d.cdf(x[i]);
    largest =
        std::max({largest, F - static_cast<double>(i) / n, static_cast<double>(i + 1) / n - F});
  }
  return largest;
}

double mean_of(const std::vector<double>& x) {
  double s = 0.0;
  for (double v : x) s += v;
  return s / static_cast<double>(x.size());
}

double variance_of(const std::vector<double>& x) {
  const double m = mean_of(x);
  double s = 0.0;
  for (double v : x) s += (v - m) * (v - m);
  return s / static_cast<double>(x.size() - 1);
}

struct Case {
  const char* name;
  Distribution d;
  double mean, variance;
  double fourth_central;  // μ4, for the variance's standard error; 0: not checked
};

std::vector<Case> cases() {
  using K = Distribution::Kind;
  const double inf = std::numeric_limits<double>::infinity();
  // Truncated normal N(10, 2²) on [9, 15]: α = −0.5, β = 2.5; mean μ + σ (φ(α) − φ(β)) / Z.
  const auto phi = [](double z) {
    return std::exp(-0.5 * z * z) / std::sqrt(2 * std::numbers::pi);
  };
  const auto Phi = [](double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); };
  const double Z = Phi(2.5) - Phi(-0.5);
  const double truncated_mean = 10.0 + 2.0 * (phi(-0.5) - phi(2.5)) / Z;
  const double truncated_variance = 4.0 * (1.0 + (-0.5 * phi(-0.5) - 2.5 * phi(2.5)) / Z -
                                           std::pow((phi(-0.5) - phi(2.5)) / Z, 2));
  const double s2 = 0.25 * 0.25;
  return {
      {"uniform", {K::kUniform, 2.0, 5.0, -inf, inf}, 3.5, 9.0 / 12.0, std::pow(3.0, 4) / 80.0},
      {"normal", {K::kNormal, 375.0, 20.0, -inf, inf}, 375.0, 400.0, 3.0 * 400.0 * 400.0},
      {"truncated normal",
       {K::kTruncatedNormal, 10.0, 2.0, 9.0, 15.0},
       truncated_mean,
       truncated_variance,
       0.0},
      {"log-normal",
       {K::kLogNormal, 1.0, 0.25, -inf, inf},
       std::exp(1.0 + s2 / 2),
       (std::exp(s2) - 1) * std::exp(2.0 + s2),
       0.0},
  };
}

// At a fixed seed every check is deterministic; the bounds are those a correct sampler passes
// with probability 0.999 (KS: 1.949/√n) or beyond (moments: 4 standard errors).
TEST(Sampling, MonteCarloSamplesHaveTheirDistributionsMomentsAndCdf) {
  for (const Case& c : cases()) {
    const std::vector<double> x = samples_of(c.d, Design::kMonteCarlo);
    const double n = kSamples;
    EXPECT_LT(ks_statistic(x, c.d), 1.949 / std::sqrt(n)) << c.name;
    EXPECT_NEAR(mean_of(x), c.mean, 4.0 * std::sqrt(c.variance / n)) << c.name;
    if (c.fourth_central > 0.0) {
      EXPECT_NEAR(variance_of(x), c.variance,
                  4.0 * std::sqrt((c.fourth_central - c.variance * c.variance) / n))
          << c.name;
    } else {
      EXPECT_NEAR(variance_of(x), c.variance, 0.05 * c.variance) << c.name;
    }
    for (double v : x) {
      ASSERT_GE(v, c.d.support_low()) << c.name;
      ASSERT_LE(v, c.d.support_high()) << c.name;
    }
  }
}

// Each of the n equal-probability strata holds exactly one sample, for every distribution; the
// stratified sample's mean is then far closer than Monte Carlo's (within 1/n of the strata).
TEST(Sampling, LatinHypercubeHitsEveryStratumOnce) {
  for (const Case& c : cases()) {
    const std::vector<double> x = samples_of(c.d, Design::kLatinHypercube);
    std::set<long> strata;
    for (double v : x) strata.insert(static_cast<long>(std::floor(c.d.cdf(v) * kSamples)));
    EXPECT_EQ(static_cast<long>(strata.size()), kSamples) << c.name;
    EXPECT_LT(ks_statistic(x, c.d), 1.0 / kSamples + 1e-9) << c.name;
  }
}

TEST(Sampling, ARunsNumbersDependOnTheSeedAndTheRunOnly) {
  // The same run from two plans, and in any order: the same value, to the bit.
  const Distribution d{Distribution::Kind::kNormal, 0.0, 1.0};
  const std::vector<double> a = samples_of(d, Design::kMonteCarlo, 42);
  const std::vector<double> b = samples_of(d, Design::kMonteCarlo, 42);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, samples_of(d, Design::kMonteCarlo, 43));
  // Numbers strictly inside (0, 1), at the ends of the counter too.
  for (std::uint64_t k : {0ULL, 1ULL, ~0ULL}) {
    const double u = uniform_number(0, 0, k);
    EXPECT_GT(u, 0.0);
    EXPECT_LT(u, 1.0);
  }
  // Two parameters of one run are drawn from different streams.
  SweepSpec spec;
  spec.parameters = {{"x", "x", d}, {"y", "y", d}};
  spec.design = Design::kMonteCarlo;
  spec.samples = 3;
  const RunPlan plan(spec);
  EXPECT_NE(plan.values(1)[0], plan.values(1)[1]);
}

TEST(Sampling, GridsCombineInFileOrderTheLastFastest) {
  SweepSpec spec;
  spec.parameters = {{"a", "a", std::vector<double>{1, 2}},
                     {"b", "b", std::vector<double>{10, 20, 30}}};
  const RunPlan factorial(spec);
  ASSERT_EQ(factorial.run_count(), 6);
  EXPECT_EQ(factorial.values(0), (std::vector<double>{1, 10}));
  EXPECT_EQ(factorial.values(2), (std::vector<double>{1, 30}));
  EXPECT_EQ(factorial.values(3), (std::vector<double>{2, 10}));
  spec.design = Design::kZip;
  EXPECT_THROW(RunPlan{spec}, InvalidArgument);  // lists of two lengths
  spec.parameters[1].values = std::vector<double>{10, 20};
  const RunPlan zipped(spec);
  ASSERT_EQ(zipped.run_count(), 2);
  EXPECT_EQ(zipped.values(1), (std::vector<double>{2, 20}));
  spec.design = Design::kMonteCarlo;
  spec.samples = 5;
  EXPECT_THROW(RunPlan{spec}, InvalidArgument);  // grids in a sampled design
}

}  // namespace
}  // namespace momenta::sweep
