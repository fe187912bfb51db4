#include "residual_whiteness.hpp"

#include <boost/math/distributions/chi_squared.hpp>

namespace momenta::identify::detail {

double ljung_box_p(const VecX& x, int m) {
  const Eigen::Index N = x.size();
  const VecX centred = x.array() - x.mean();
  const double c0 = centred.squaredNorm();
  if (!(c0 > 0.0) || m < 1) return 1.0;
  double Q = 0.0;
  for (int k = 1; k <= m; ++k) {
    const double rho = centred.head(N - k).dot(centred.tail(N - k)) / c0;
    Q += rho * rho / double(N - k);
  }
  Q *= double(N) * double(N + 2);
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared(m), Q));
}

}  // namespace momenta::identify::detail
