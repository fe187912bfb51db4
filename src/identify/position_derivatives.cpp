#include "momenta/identify/position_derivatives.hpp"

#include <cmath>

#include <fmt/format.h>
#include <Eigen/QR>

#include "momenta/common/error.hpp"

namespace momenta::identify {

PositionDerivatives differentiate_positions(const VecX& time, const MatX& positions, int window) {
  const Eigen::Index N = time.size();
  if (positions.rows() != N) {
    throw InvalidArgument(fmt::format("differentiate_positions: {} times for {} rows of positions",
                                      N, positions.rows()));
  }
  if (window < 5 || window % 2 == 0 || window > N) {
    throw InvalidArgument(fmt::format(
        "differentiate_positions: window {} samples: it must be odd, at least 5 (a cubic and "
        "room to smooth) and at most the {} samples logged",
        window, N));
  }
  const double h = (time[N - 1] - time[0]) / double(N - 1);
  for (Eigen::Index i = 1; i < N; ++i) {
    const double step = time[i] - time[i - 1];
    if (!(std::abs(step - h) <= 1e-6 * h)) {
      throw InvalidArgument(fmt::format(
          "differentiate_positions: the time step before row {} is {} s, the log's mean {} s: "
          "positions are differentiated only at uniform steps (give the rates and accelerations "
          "instead)",
          i, step, h));
    }
  }
  // Least-squares cubic on the window's samples at τ = (j − c) h: its coefficients are P y with
  // P the pseudo-inverse of the Vandermonde matrix; the derivatives at offset d from the centre
  // are c₁ + 2 c₂ τ_d + 3 c₃ τ_d², 2 c₂ + 6 c₃ τ_d.
  const int half = window / 2;
  MatX V(window, 4);
  for (int j = 0; j < window; ++j) {
    const double tau = (j - half) * h;
    V.row(j) << 1.0, tau, tau * tau, tau * tau * tau;
  }
  const MatX P = V.colPivHouseholderQr().solve(MatX::Identity(window, window));  // 4 × window
  PositionDerivatives out{MatX(N, positions.cols()), MatX(N, positions.cols())};
  for (Eigen::Index i = 0; i < N; ++i) {
    const Eigen::Index start = std::clamp<Eigen::Index>(i - half, 0, N - window);
    const double tau = double(i - (start + half)) * h;
    const Eigen::RowVectorXd d1 = P.row(1) + 2.0 * tau * P.row(2) + 3.0 * tau * tau * P.row(3);
    const Eigen::RowVectorXd d2 = 2.0 * P.row(2) + 6.0 * tau * P.row(3);
    out.rate.row(i) = d1 * positions.middleRows(start, window);
    out.acceleration.row(i) = d2 * positions.middleRows(start, window);
  }
  return out;
}

}  // namespace momenta::identify
