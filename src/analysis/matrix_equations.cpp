#include "momenta/analysis/matrix_equations.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include <fmt/format.h>
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "momenta/common/error.hpp"

namespace momenta::analysis {
namespace {

using Complex = std::complex<double>;
using MatXc = Eigen::MatrixXcd;

constexpr double kEps = std::numeric_limits<double>::epsilon();

// ---- checks ----

void require_square(const MatX& M, Eigen::Index n, const char* function, const char* what) {
  if (M.rows() != n || M.cols() != n) {
    throw InvalidArgument(
        fmt::format("{}: {} is {}×{} but must be {}×{}", function, what, M.rows(), M.cols(), n, n));
  }
}

void require_finite(const MatX& M, const char* function, const char* what) {
  if (!M.allFinite())
    throw InvalidArgument(fmt::format("{}: {} has a non-finite entry", function, what));
}

void require_symmetric(const MatX& M, const char* function, const char* what) {
  const double scale = std::max(1.0, M.cwiseAbs().maxCoeff());
  if ((M - M.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale) {
    throw InvalidArgument(fmt::format("{}: {} must be symmetric", function, what));
  }
}

// ---- complex Schur form, reordered ----

struct Schur {
  MatXc T;  // upper triangular
  MatXc U;  // unitary, M = U T Uᴴ
};

Schur complex_schur(const MatX& M, const char* function) {
  const Eigen::ComplexSchur<MatXc> schur(M.cast<Complex>());
  if (schur.info() != Eigen::Success) {
    throw NumericalError(fmt::format("{}: the Schur iteration did not converge", function));
  }
  return {schur.matrixT(), schur.matrixU()};
}

// Applies the plane rotation [c s; −s̄ c] to the pair (x, y): x ← c x + s y, y ← c y − s̄ x.
void rotate(Complex& x, Complex& y, double c, Complex s) {
  const Complex x_new = c * x + s * y;
  y = c * y - std::conj(s) * x;
  x = x_new;
}

// Swaps the adjacent diagonal entries k and k+1 of the triangular T, keeping M = U T Uᴴ (one
// Givens rotation, as LAPACK's ztrexc).
void swap_adjacent(Schur& s, Eigen::Index k) {
  const Eigen::Index n = s.T.rows();
  const Complex t11 = s.T(k, k);
  const Complex t22 = s.T(k + 1, k + 1);
  // The rotation that takes (T(k, k+1), t22 − t11) to (r, 0).
  const Complex f = s.T(k, k + 1);
  const Complex g = t22 - t11;
  const double norm = std::hypot(std::abs(f), std::abs(g));
  if (norm == 0.0) return;  // equal eigenvalues with no coupling: nothing to swap
  double c = 0.0;
  Complex sn;
  if (std::abs(f) == 0.0) {
    sn = std::conj(g) / std::abs(g);
  } else {
    c = std::abs(f) / norm;
    sn = (f / std::abs(f)) * std::conj(g) / norm;
  }
  for (Eigen::Index j = k + 2; j < n; ++j) rotate(s.T(k, j), s.T(k + 1, j), c, sn);
  for (Eigen::Index i = 0; i < k; ++i) rotate(s.T(i, k), s.T(i, k + 1), c, std::conj(sn));
  for (Eigen::Index i = 0; i < n; ++i) rotate(s.U(i, k), s.U(i, k + 1), c, std::conj(sn));
  s.T(k, k) = t22;
  s.T(k + 1, k + 1) = t11;
  s.T(k + 1, k) = 0.0;
}

// Moves every diagonal entry for which `selected` holds to the front, in order; returns how many.
template <class Predicate>
Eigen::Index select_to_front(Schur& s, Predicate selected) {
  Eigen::Index front = 0;
  for (Eigen::Index k = 0; k < s.T.rows(); ++k) {
    if (!selected(s.T(k, k))) continue;
    for (Eigen::Index j = k; j > front; --j) swap_adjacent(s, j - 1);
    ++front;
  }
  return front;
}

// ---- Lyapunov and Stein ----

// Real symmetric X = U Y Uᴴ.
MatX real_symmetric(const MatXc& U, const MatXc& Y) {
  const MatX X = (U * Y * U.adjoint()).real();
  return 0.5 * (X + X.transpose());
}

void check_pivot(Complex pivot, double scale, const char* function, const char* why) {
  if (!(std::abs(pivot) > 1e3 * kEps * scale)) {
    throw NumericalError(fmt::format("{}: no unique solution: {}", function, why));
  }
}

// Riccati prerequisites: R's Cholesky factor and the cross-term-free A, Q and G = B R⁻¹ Bᵀ.
struct Reduced {
  MatX A, Q, G;
};

Reduced reduce(const MatX& A, const MatX& B, const MatX& Q, const MatX& R, const MatX& N,
               const char* function) {
  const Eigen::Index n = A.rows();
  const Eigen::Index m = B.cols();
  require_square(A, n, function, "A");
  if (B.rows() != n) {
    throw InvalidArgument(fmt::format("{}: B has {} rows but A has {}", function, B.rows(), n));
  }
  require_square(Q, n, function, "Q");
  require_square(R, m, function, "R");
  if (N.size() != 0 && (N.rows() != n || N.cols() != m)) {
    throw InvalidArgument(
        fmt::format("{}: N is {}×{} but must be {}×{}", function, N.rows(), N.cols(), n, m));
  }
  for (const auto& [M, what] : {std::pair{&A, "A"}, {&B, "B"}, {&Q, "Q"}, {&R, "R"}, {&N, "N"}}) {
    require_finite(*M, function, what);
  }
  require_symmetric(Q, function, "Q");
  require_symmetric(R, function, "R");
  const Eigen::LLT<MatX> r(R);
  if (m == 0 || r.info() != Eigen::Success) {
    throw InvalidArgument(
        fmt::format("{}: R must be positive definite (every input costs something){}", function,
                    m == 0 ? "; the system has no inputs" : ""));
  }
  Reduced out{A, Q, B * r.solve(B.transpose())};
  if (N.size() != 0) {
    out.A -= B * r.solve(N.transpose());
    out.Q -= N * r.solve(N.transpose());
  }
  out.G = 0.5 * (out.G + out.G.transpose());
  out.Q = 0.5 * (out.Q + out.Q.transpose());
  return out;
}

double norm1(const MatX& M) {
  return M.size() == 0 ? 0.0 : M.cwiseAbs().colwise().sum().maxCoeff();
}

// Checks A and Q of a Lyapunov equation (square, the same size, finite); returns n.
Eigen::Index lyapunov_sizes_checked(const MatX& A, const MatX& Q, const char* function) {
  const Eigen::Index n = A.rows();
  require_square(A, n, function, "A");
  require_square(Q, n, function, "Q");
  require_finite(A, function, "A");
  require_finite(Q, function, "Q");
  return n;
}

// F = −Uᴴ Q U: the right side in the Schur basis.
MatXc transformed_right_side(const Schur& s, const MatX& Q) {
  return -(s.U.adjoint() * Q.cast<Complex>() * s.U);
}

MatX continuous_residual(const Reduced& p, const MatX& X) {
  return p.A.transpose() * X + X * p.A - X * p.G * X + p.Q;
}

}  // namespace

MatX solve_continuous_lyapunov(const MatX& A, const MatX& Q) {
  constexpr const char* kFunction = "solve_continuous_lyapunov";
  const Eigen::Index n = A.rows();
  if (lyapunov_sizes_checked(A, Q, kFunction) == 0) return MatX(0, 0);
  // A = U T Uᴴ; T Y + Y Tᴴ = F with F = −Uᴴ Q U, solved column by column from the last:
  // (T + conj(T_jj) I) y_j = f_j − Σ_{k>j} conj(T_jk) y_k.
  const Schur s = complex_schur(A, kFunction);
  const MatXc F = transformed_right_side(s, Q);
  const double scale = std::max(1.0, norm1(A));
  MatXc Y(n, n);
  for (Eigen::Index j = n - 1; j >= 0; --j) {
    Eigen::VectorXcd rhs = F.col(j);
    for (Eigen::Index k = j + 1; k < n; ++k) rhs -= std::conj(s.T(j, k)) * Y.col(k);
    MatXc M = s.T;
    M.diagonal().array() += std::conj(s.T(j, j));
    for (Eigen::Index i = 0; i <= j; ++i) {
      check_pivot(M(i, i), scale, kFunction, "two eigenvalues of A sum to zero");
    }
    Y.col(j) = M.triangularView<Eigen::Upper>().solve(rhs);
  }
  return real_symmetric(s.U, Y);
}

MatX solve_discrete_lyapunov(const MatX& A, const MatX& Q) {
  constexpr const char* kFunction = "solve_discrete_lyapunov";
  const Eigen::Index n = A.rows();
  if (lyapunov_sizes_checked(A, Q, kFunction) == 0) return MatX(0, 0);
  // T Y Tᴴ − Y = F, column j: (conj(T_jj) T − I) y_j = f_j − T Σ_{k>j} conj(T_jk) y_k.
  const Schur s = complex_schur(A, kFunction);
  const MatXc F = transformed_right_side(s, Q);
  MatXc Y(n, n);
  for (Eigen::Index j = n - 1; j >= 0; --j) {
    Eigen::VectorXcd later = Eigen::VectorXcd::Zero(n);
    for (Eigen::Index k = j + 1; k < n; ++k) later += std::conj(s.T(j, k)) * Y.col(k);
    const Eigen::VectorXcd rhs = F.col(j) - s.T * later;
    MatXc M = std::conj(s.T(j, j)) * s.T;
    M.diagonal().array() -= 1.0;
    for (Eigen::Index i = 0; i <= j; ++i) {
      check_pivot(M(i, i), 1.0, kFunction, "the product of two eigenvalues of A is 1");
    }
    Y.col(j) = M.triangularView<Eigen::Upper>().solve(rhs);
  }
  return real_symmetric(s.U, Y);
}

MatX solve_continuous_riccati(const MatX& A, const MatX& B, const MatX& Q, const MatX& R,
                              const MatX& N) {
  constexpr const char* kFunction = "solve_continuous_riccati";
  const Reduced p = reduce(A, B, Q, R, N, kFunction);
  const Eigen::Index n = p.A.rows();
  if (n == 0) return MatX(0, 0);

  // The Hamiltonian and its stable invariant subspace.
  MatX H(2 * n, 2 * n);
  H << p.A, -p.G, -p.Q, -p.A.transpose();
  Schur s = complex_schur(H, kFunction);
  const double scale = std::max(1.0, norm1(H));
  for (Eigen::Index k = 0; k < 2 * n; ++k) {
    if (std::abs(s.T(k, k).real()) <= 1e-10 * scale) {
      throw NumericalError(fmt::format(
          "{}: no stabilizing solution: the Hamiltonian has an eigenvalue on the imaginary "
          "axis at s = {} 1/s: a mode of A on the axis (an integrator at 0, an undamped "
          "oscillation) that Q does not weigh — give its states a weight — or that B cannot move",
          kFunction,
          std::abs(s.T(k, k).imag()) <= 1e-10 * scale
              ? std::string("0")
              : fmt::format("±{:.6g}j", std::abs(s.T(k, k).imag()))));
    }
  }
  const Eigen::Index stable = select_to_front(s, [](Complex z) { return z.real() < 0.0; });
  if (stable != n) {
    throw NumericalError(
        fmt::format("{}: the Hamiltonian has {} stable eigenvalues, not {}", kFunction, stable, n));
  }
  const MatXc U1 = s.U.topLeftCorner(n, n);
  const MatXc U2 = s.U.bottomLeftCorner(n, n);
  const Eigen::FullPivLU<MatXc> lu(U1);
  if (lu.rcond() < 1e3 * kEps) {
    throw NumericalError(fmt::format(
        "{}: no stabilizing solution: (A, B) is not stabilizable — an unstable mode that no "
        "input moves",
        kFunction));
  }
  // X = U₂ U₁⁻¹: solve U₁ᵀ Xᵀ = U₂ᵀ.
  MatX X = Eigen::FullPivLU<MatXc>(U1.transpose()).solve(U2.transpose()).transpose().real();
  X = 0.5 * (X + X.transpose());

  // Newton–Kleinman: (A − G X)ᵀ X⁺ + X⁺ (A − G X) + Q + X G X = 0, while the residual shrinks.
  double residual = norm1(continuous_residual(p, X));
  for (int step = 0; step < 4 && residual > 0.0; ++step) {
    const MatX closed = p.A - p.G * X;
    MatX next;
    try {
      next = solve_continuous_lyapunov(closed.transpose(), p.Q + X * p.G * X);
    } catch (const NumericalError&) {
      break;
    }
    const double next_residual = norm1(continuous_residual(p, next));
    if (!(next_residual < residual)) break;
    X = next;
    residual = next_residual;
  }
  const Eigen::EigenSolver<MatX> closed(p.A - p.G * X, false);
  if (closed.info() != Eigen::Success || closed.eigenvalues().real().maxCoeff() >= 0.0) {
    throw NumericalError(
        fmt::format("{}: the solution found does not stabilize A − B K", kFunction));
  }
  return X;
}

MatX solve_discrete_riccati(const MatX& A, const MatX& B, const MatX& Q, const MatX& R,
                            const MatX& N) {
  constexpr const char* kFunction = "solve_discrete_riccati";
  const Reduced p = reduce(A, B, Q, R, N, kFunction);
  const Eigen::Index n = p.A.rows();
  if (n == 0) return MatX(0, 0);

  // Doubling: A⁺ = A W⁻¹ A, G⁺ = G + A W⁻¹ G Aᵀ, H⁺ = H + Aᵀ H W⁻¹ A, W = I + G H; H → X.
  MatX Ak = p.A, Gk = p.G, Hk = p.Q;
  const MatX I = MatX::Identity(n, n);
  bool converged = false;
  for (int iteration = 0; iteration < 100 && !converged; ++iteration) {
    const Eigen::FullPivLU<MatX> W(I + Gk * Hk);
    if (!W.isInvertible()) break;
    const MatX WA = W.solve(Ak);
    const MatX WG = W.solve(Gk);
    const MatX A_next = Ak * WA;
    MatX G_next = Gk + Ak * WG * Ak.transpose();
    MatX H_next = Hk + Ak.transpose() * Hk * WA;
    G_next = 0.5 * (G_next + G_next.transpose());
    H_next = 0.5 * (H_next + H_next.transpose());
    if (!H_next.allFinite() || !A_next.allFinite()) break;
    converged = norm1(H_next - Hk) <= 1e2 * kEps * std::max(1.0, norm1(H_next));
    Ak = A_next;
    Gk = std::move(G_next);
    Hk = std::move(H_next);
  }
  const MatX K = (R + B.transpose() * Hk * B)
                     .ldlt()
                     .solve(B.transpose() * Hk * A +
                            (N.size() ? MatX(N.transpose()) : MatX::Zero(B.cols(), n)));
  const Eigen::EigenSolver<MatX> closed(A - B * K, false);
  if (!converged || closed.info() != Eigen::Success ||
      closed.eigenvalues().cwiseAbs().maxCoeff() >= 1.0) {
    throw NumericalError(fmt::format(
        "{}: no stabilizing solution: (A, B) is not stabilizable (a mode outside the unit circle "
        "that no input moves), or a mode on the unit circle that Q does not weigh",
        kFunction));
  }
  return Hk;
}

}  // namespace momenta::analysis
