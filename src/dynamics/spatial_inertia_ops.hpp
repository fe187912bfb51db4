#pragma once
// Articulated-inertia operations shared by aba and hybrid_dynamics (private to src/dynamics).

#include "momenta/math/spatial.hpp"

namespace momenta::dynamics::detail {

// I_P += ᴾX_B* I_B ᴮX_P for a symmetric 6×6 inertia I_B expressed in B about Bo, B at pose
// X_PB in P. With I_B = [A B; Bᵀ D] (3×3 blocks), rotate each block into P (A' = R A Rᵀ, ...)
// then move the reference point from Bo to Po with T = [1 [p]×; 0 1]: I_P = T I' Tᵀ, i.e.
//   D_P = D',  B_P = B' + [p]× D',  A_P = A' + [p]× B'ᵀ − B_P [p]×.
inline void add_transformed_inertia(const Transform& X_PB, const Mat6& I_B, Mat6& I_P) {
  const Mat3& R = X_PB.R;
  const Vec3& p = X_PB.p;
  // R times each block, then times Rᵀ (only the upper triangle of the symmetric A and D).
  double RA[3][3], RB[3][3], RD[3][3];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      RA[i][j] = R(i, 0) * I_B(0, j) + R(i, 1) * I_B(1, j) + R(i, 2) * I_B(2, j);
      RB[i][j] = R(i, 0) * I_B(0, 3 + j) + R(i, 1) * I_B(1, 3 + j) + R(i, 2) * I_B(2, 3 + j);
      RD[i][j] = R(i, 0) * I_B(3, 3 + j) + R(i, 1) * I_B(4, 3 + j) + R(i, 2) * I_B(5, 3 + j);
    }
  }
  double A[3][3], B[3][3], D[3][3];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      B[i][j] = RB[i][0] * R(j, 0) + RB[i][1] * R(j, 1) + RB[i][2] * R(j, 2);
      if (j < i) continue;
      A[i][j] = A[j][i] = RA[i][0] * R(j, 0) + RA[i][1] * R(j, 1) + RA[i][2] * R(j, 2);
      D[i][j] = D[j][i] = RD[i][0] * R(j, 0) + RD[i][1] * R(j, 1) + RD[i][2] * R(j, 2);
    }
  }
  // B_P = B' + [p]× D': column k gains p × D'_k.
  double BP[3][3];
  for (int k = 0; k < 3; ++k) {
    BP[0][k] = B[0][k] + p[1] * D[2][k] - p[2] * D[1][k];
    BP[1][k] = B[1][k] + p[2] * D[0][k] - p[0] * D[2][k];
    BP[2][k] = B[2][k] + p[0] * D[1][k] - p[1] * D[0][k];
  }
  // A_P(i, j) = A'(i, j) + (p × B'_{j,:})_i + (p × B_P{i,:})_j (upper triangle; A_P symmetric).
  const auto cross_i = [&](const double* r, int i) {
    const int a = (i + 1) % 3, b = (i + 2) % 3;
    return p[a] * r[b] - p[b] * r[a];
  };
  for (int i = 0; i < 3; ++i) {
    for (int j = i; j < 3; ++j) {
      const double value = A[i][j] + cross_i(B[j], i) + cross_i(BP[i], j);
      I_P(i, j) += value;
      if (j != i) I_P(j, i) += value;
    }
  }
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      I_P(i, 3 + k) += BP[i][k];
      I_P(3 + k, i) += BP[i][k];
      I_P(3 + i, 3 + k) += D[i][k];
    }
  }
}

// I.transformed(X_AB) for X_AB = (Rot_K(θ), p), a rotation about coordinate axis K given by
// c = cos θ, s = sin θ (a revolute joint's, JointConstants::turns_about_axis): the rotation mixes
// only rows and columns (I, J) = (K + 1, K + 2) mod 3, a third of the general products.
template <int K>
SpatialInertia transformed_about_axis(const SpatialInertia& in, double c, double s, const Vec3& p) {
  constexpr int I = (K + 1) % 3, J = (K + 2) % 3;
  const Mat3& A = in.I_O;
  Mat3 B;  // R A Rᵀ with R e_I = c e_I + s e_J, R e_J = −s e_I + c e_J, R e_K = e_K
  B(K, K) = A(K, K);
  B(K, I) = B(I, K) = c * A(K, I) - s * A(K, J);
  B(K, J) = B(J, K) = s * A(K, I) + c * A(K, J);
  // The {I, J} block r A rᵀ, r = [c −s; s c].
  const double tII = c * A(I, I) - s * A(J, I), tIJ = c * A(I, J) - s * A(J, J);
  const double tJI = s * A(I, I) + c * A(J, I), tJJ = s * A(I, J) + c * A(J, J);
  B(I, I) = c * tII - s * tIJ;
  B(J, J) = s * tJI + c * tJJ;
  B(I, J) = B(J, I) = s * tII + c * tIJ;
  Vec3 h;
  h[I] = c * in.h[I] - s * in.h[J];
  h[J] = s * in.h[I] + c * in.h[J];
  h[K] = in.h[K];
  return SpatialInertia::moved(in.mass, h, B, p);
}

// The 6×6 matrix of a rigid-body spatial inertia, written into M.
inline void set_inertia_matrix(const SpatialInertia& I, Mat6& M) {
  const Vec3& h = I.h;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      M(i, j) = I.I_O(i, j);
      M(3 + i, 3 + j) = i == j ? I.mass : 0.0;
    }
  }
  // Upper right [h]×, lower left its transpose.
  M(0, 3) = 0.0, M(0, 4) = -h[2], M(0, 5) = h[1];
  M(1, 3) = h[2], M(1, 4) = 0.0, M(1, 5) = -h[0];
  M(2, 3) = -h[1], M(2, 4) = h[0], M(2, 5) = 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) M(3 + j, i) = M(i, 3 + j);
  }
}

}  // namespace momenta::dynamics::detail
