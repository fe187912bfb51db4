#include <cmath>

#include <boost/math/distributions/lognormal.hpp>
#include <boost/math/distributions/normal.hpp>

#include "momenta/sweep/sweep_spec.hpp"

namespace momenta::sweep {
namespace {

double normal_cdf(double x, double mean, double sd) {
  return boost::math::cdf(boost::math::normal_distribution<double>(mean, sd), x);
}

double normal_quantile(double u, double mean, double sd) {
  return boost::math::quantile(boost::math::normal_distribution<double>(mean, sd), u);
}

}  // namespace

double Distribution::quantile(double u) const {
  switch (kind) {
    case Kind::kUniform:
      return first + u * (second - first);
    case Kind::kNormal:
      return normal_quantile(u, first, second);
    case Kind::kTruncatedNormal: {
      // Inverted within [F(low), F(high)]; the value is clamped to the bounds, which round-off
      // in the far tail could otherwise step past.
      const double a = std::isinf(low) ? 0.0 : normal_cdf(low, first, second);
      const double b = std::isinf(high) ? 1.0 : normal_cdf(high, first, second);
      const double p = a + u * (b - a);
      if (p <= 0.0) return low;
      if (p >= 1.0) return high;
      return std::clamp(normal_quantile(p, first, second), low, high);
    }
    case Kind::kLogNormal:
      return boost::math::quantile(boost::math::lognormal_distribution<double>(first, second), u);
  }
  return std::nan("");
}

double Distribution::cdf(double x) const {
  switch (kind) {
    case Kind::kUniform:
      return std::clamp((x - first) / (second - first), 0.0, 1.0);
    case Kind::kNormal:
      return normal_cdf(x, first, second);
    case Kind::kTruncatedNormal: {
      if (x <= low) return 0.0;
      if (x >= high) return 1.0;
      const double a = std::isinf(low) ? 0.0 : normal_cdf(low, first, second);
      const double b = std::isinf(high) ? 1.0 : normal_cdf(high, first, second);
      return (normal_cdf(x, first, second) - a) / (b - a);
    }
    case Kind::kLogNormal:
      if (x <= 0.0) return 0.0;
      return boost::math::cdf(boost::math::lognormal_distribution<double>(first, second), x);
  }
  return std::nan("");
}

double Distribution::support_low() const {
  switch (kind) {
    case Kind::kUniform:
      return first;
    case Kind::kNormal:
      return -std::numeric_limits<double>::infinity();
    case Kind::kTruncatedNormal:
      return low;
    case Kind::kLogNormal:
      return 0.0;
  }
  return std::nan("");
}

double Distribution::support_high() const {
  switch (kind) {
    case Kind::kUniform:
      return second;
    case Kind::kTruncatedNormal:
      return high;
    case Kind::kNormal:
    case Kind::kLogNormal:
      return std::numeric_limits<double>::infinity();
  }
  return std::nan("");
}

}  // namespace momenta::sweep
