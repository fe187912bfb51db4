#include "campbell.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta::analysis::detail {
namespace {

// The k-th whirl's frequency minus Ω, or NaN when the modes change there.
double off_the_line(const WhirlsAt& whirls_at, double speed, std::size_t k,
                    const std::string& whirl) {
  const CampbellPoint p = whirls_at(speed);
  if (k >= p.frequencies.size() || !p.stable || p.whirl[k] != whirl) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return p.frequencies[k] - speed;
}

int whirl_rank(const std::string& whirl) {
  return whirl == "backward" ? 0 : whirl == "forward" ? 1 : 2;
}

}  // namespace

void sort_whirls(CampbellPoint& point) {
  std::vector<std::pair<std::string, double>> sorted;
  for (std::size_t k = 0; k < point.frequencies.size(); ++k) {
    sorted.emplace_back(point.whirl[k], point.frequencies[k]);
  }
  std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) {
    return std::pair(whirl_rank(a.first), a.second) < std::pair(whirl_rank(b.first), b.second);
  });
  point.whirl.clear();
  point.frequencies.clear();
  for (const auto& [whirl, frequency] : sorted) {
    point.whirl.push_back(whirl);
    point.frequencies.push_back(frequency);
  }
}

}  // namespace momenta::analysis::detail

namespace momenta::analysis {

std::vector<std::string> whirl_column_names(const CampbellPoint& point) {
  std::vector<std::string> names;
  int forward = 0, backward = 0, none = 0;
  for (const std::string& w : point.whirl) {
    int& count = w == "forward" ? forward : w == "backward" ? backward : none;
    names.push_back(fmt::format("{}_{}", w, ++count));
  }
  return names;
}

}  // namespace momenta::analysis

namespace momenta::analysis::detail {

CampbellDiagram campbell_sweep(const WhirlsAt& whirls_at, double from, double to, int points) {
  if (!(from > 0.0) || !(to > from) || !std::isfinite(to) || points < 2) {
    throw InvalidArgument(fmt::format(
        "Campbell diagram: speeds from {} to {} rad/s in {} points: expected 0 < from < to and "
        "at least 2 points",
        from, to, points));
  }
  CampbellDiagram d;
  for (int k = 0; k < points; ++k) {
    d.points.push_back(whirls_at(from + (to - from) * k / (points - 1)));
  }
  // Critical speeds: a sign change of (frequency − Ω) of the same whirl between two speeds.
  for (std::size_t k = 1; k < d.points.size(); ++k) {
    const CampbellPoint &a = d.points[k - 1], &c = d.points[k];
    if (a.frequencies.size() != c.frequencies.size()) continue;
    for (std::size_t i = 0; i < a.frequencies.size(); ++i) {
      const double fa = a.frequencies[i] - a.speed, fc = c.frequencies[i] - c.speed;
      // An unbalance turns with the rotor: it drives forward whirl at 1×, so only forward whirls
      // have critical speeds here.
      if (!a.stable || !c.stable || (fa > 0.0) == (fc > 0.0) || a.whirl[i] != c.whirl[i] ||
          a.whirl[i] != "forward")
        continue;
      double lo = a.speed, hi = c.speed, flo = fa;
      while (hi - lo > 1e-12 * hi) {
        const double mid = 0.5 * (lo + hi);
        const double fm = off_the_line(whirls_at, mid, i, a.whirl[i]);
        if (std::isnan(fm)) break;
        if ((fm > 0.0) == (flo > 0.0)) {
          lo = mid;
          flo = fm;
        } else {
          hi = mid;
        }
      }
      d.critical_speeds.push_back({0.5 * (lo + hi), a.whirl[i]});
    }
  }
  return d;
}

}  // namespace momenta::analysis::detail
