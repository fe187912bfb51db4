#pragma once
// Diagonal balancing of a square matrix (private to momenta/analysis).

#include "momenta/math/types.hpp"

namespace momenta::analysis::detail {

/// Scale factors d, powers of 2 (so the scaling is exact in floating point), such that
/// diag(d)⁻¹ A diag(d) has rows and columns of comparable 1-norms: the balancing of Parlett &
/// Reinsch, "Balancing a matrix for calculation of eigenvalues and eigenvectors", Numer. Math.
/// 13, 1969 (LAPACK dgebal without permutations). Eigenvalues and transfer functions are
/// invariant under it; their round-off scales with the norm of the balanced matrix, which can be
/// orders of magnitude smaller when states have mixed units (m and m/s, rad and N·m).
VecX balancing_scale(const MatX& A);

}  // namespace momenta::analysis::detail
