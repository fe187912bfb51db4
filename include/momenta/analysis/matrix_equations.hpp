#pragma once
// The matrix equations of linear control design: Lyapunov's (for Gramians and quadratic costs)
// and the algebraic Riccati equations (for optimal state feedback, lqr.hpp), continuous and
// discrete. Real matrices in, real symmetric solutions out.
//
// Methods (all on Eigen, no LAPACK):
//   - Lyapunov and Stein: Bartels–Stewart on the complex Schur form of A (Bartels & Stewart,
//     CACM 15(9), 1972): A = U T Uᴴ, then one triangular solve per column.
//   - Continuous Riccati: Laub's Schur method (IEEE TAC 24(6), 1979) — the stable invariant
//     subspace [U₁; U₂] of the Hamiltonian [A −G; −Q −Aᵀ] from its complex Schur form reordered
//     by Givens swaps (as LAPACK's ztrexc), X = U₂ U₁⁻¹ — then Newton–Kleinman steps (Kleinman,
//     IEEE TAC 13(1), 1968) while they shrink the residual.
//   - Discrete Riccati: the structure-preserving doubling algorithm (Chu, Fan, Lin & Wang,
//     J. Phys. A 37, 2004; Lin & Xu, SIAM J. Matrix Anal. Appl. 28(1), 2006), quadratically
//     convergent and free of A⁻¹.
// A cross weight N (the cost's 2 xᵀ N u) is removed first: A − B R⁻¹ Nᵀ, Q − N R⁻¹ Nᵀ.

#include "momenta/math/types.hpp"

namespace momenta::analysis {

/// X with A X + X Aᵀ + Q = 0 (n×n; Q symmetric). Unique when no two eigenvalues of A sum to
/// zero; throws NumericalError when they (nearly) do, InvalidArgument on mismatched sizes.
MatX solve_continuous_lyapunov(const MatX& A, const MatX& Q);

/// X with A X Aᵀ − X + Q = 0 (the Stein equation). Unique when no product of two eigenvalues of
/// A is 1; throws NumericalError when one (nearly) is, InvalidArgument on mismatched sizes.
MatX solve_discrete_lyapunov(const MatX& A, const MatX& Q);

/// The stabilizing X = Xᵀ of Aᵀ X + X A − (X B + N) R⁻¹ (Bᵀ X + Nᵀ) + Q = 0: the one for which
/// A − B R⁻¹ (Bᵀ X + Nᵀ) has every eigenvalue in the open left half-plane. A n×n, B n×m, Q n×n
/// symmetric, R m×m symmetric positive definite, N n×m (empty for none).
/// Throws InvalidArgument on sizes, a non-finite entry, an R that is not positive definite;
/// NumericalError naming the cause when there is no stabilizing solution ((A, B) not
/// stabilizable, or a mode on the imaginary axis that Q does not see).
MatX solve_continuous_riccati(const MatX& A, const MatX& B, const MatX& Q, const MatX& R,
                              const MatX& N = MatX());

/// The stabilizing X = Xᵀ of Aᵀ X A − X − (Aᵀ X B + N)(R + Bᵀ X B)⁻¹ (Bᵀ X A + Nᵀ) + Q = 0: the
/// one for which A − B (R + Bᵀ X B)⁻¹ (Bᵀ X A + Nᵀ) has every eigenvalue inside the unit circle.
/// Sizes and errors as solve_continuous_riccati (a mode on the unit circle instead).
MatX solve_discrete_riccati(const MatX& A, const MatX& B, const MatX& Q, const MatX& R,
                            const MatX& N = MatX());

}  // namespace momenta::analysis
