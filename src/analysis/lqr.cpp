#include "momenta/analysis/lqr.hpp"

#include <fmt/format.h>
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "momenta/analysis/matrix_equations.hpp"
#include "momenta/common/error.hpp"

namespace momenta::analysis {
namespace {

void require_size(const MatX& M, Eigen::Index rows, Eigen::Index cols, const char* what,
                  const char* why) {
  if (M.rows() != rows || M.cols() != cols) {
    throw InvalidArgument(fmt::format("lqr: {} is {}×{} but must be {}×{} ({})", what, M.rows(),
                                      M.cols(), rows, cols, why));
  }
  if (!M.allFinite()) throw InvalidArgument(fmt::format("lqr: {} has a non-finite entry", what));
}

// Throws unless the symmetric M has no eigenvalue below −tolerance·max|M|.
void require_semidefinite(const MatX& M, const char* what) {
  if (M.size() == 0) return;
  const double scale = std::max(1.0, M.cwiseAbs().maxCoeff());
  if ((M - M.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale) {
    throw InvalidArgument(fmt::format("lqr: {} must be symmetric", what));
  }
  const double lowest =
      Eigen::SelfAdjointEigenSolver<MatX>(M, Eigen::EigenvaluesOnly).eigenvalues().minCoeff();
  if (lowest < -1e-12 * scale) {
    throw InvalidArgument(fmt::format(
        "lqr: {} must be positive semidefinite (a cost cannot reward a state or input); its "
        "lowest eigenvalue is {}",
        what, lowest));
  }
}

}  // namespace

LqrDesign lqr(const StateSpace& system, const MatX& Q, const MatX& R, const MatX& N) {
  const Eigen::Index n = system.A().rows();
  const Eigen::Index m = system.B().cols();
  if (m == 0) throw InvalidArgument("lqr: the system has no inputs to feed back into");
  require_size(Q, n, n, "Q", "states × states");
  require_size(R, m, m, "R", "inputs × inputs");
  if (N.size() != 0) require_size(N, n, m, "N", "states × inputs");
  require_semidefinite(Q, "Q");
  if (Eigen::LLT<MatX>(R).info() != Eigen::Success ||
      (R - R.transpose()).norm() > 1e-12 * R.norm()) {
    throw InvalidArgument(
        "lqr: R must be symmetric positive definite (every input must cost something)");
  }
  if (N.size() != 0) {
    MatX joint(n + m, n + m);
    joint << Q, N, N.transpose(), R;
    require_semidefinite(joint, "[Q N; Nᵀ R]");
  }

  const MatX& A = system.A();
  const MatX& B = system.B();
  const MatX Nt = N.size() ? MatX(N.transpose()) : MatX::Zero(m, n);
  LqrDesign design;
  if (system.is_discrete()) {
    design.S = solve_discrete_riccati(A, B, Q, R, N);
    design.K = (R + B.transpose() * design.S * B).ldlt().solve(B.transpose() * design.S * A + Nt);
  } else {
    design.S = solve_continuous_riccati(A, B, Q, R, N);
    design.K = R.llt().solve(B.transpose() * design.S + Nt);
  }
  const Modes closed = modes(MatX(A - B * design.K));
  design.closed_loop_poles.resize(static_cast<Eigen::Index>(closed.modes.size()));
  for (std::size_t i = 0; i < closed.modes.size(); ++i) {
    design.closed_loop_poles[static_cast<Eigen::Index>(i)] = closed.modes[i].eigenvalue;
  }
  design.state_names = system.state_names();
  design.input_names = system.input_names();
  design.sample_time = system.sample_time();
  return design;
}

}  // namespace momenta::analysis
