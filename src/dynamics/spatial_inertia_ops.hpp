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
  const Mat3 RA = R * I_B.topLeftCorner<3, 3>();
  const Mat3 RB = R * I_B.topRightCorner<3, 3>();
  const Mat3 RD = R * I_B.bottomRightCorner<3, 3>();
  Mat3 A, B, D;
  A.noalias() = RA * R.transpose();
  B.noalias() = RB * R.transpose();
  D.noalias() = RD * R.transpose();
  // B_P = B' + [p]× D' (column by column: p × D'_k).
  Mat3 BP;
  for (int k = 0; k < 3; ++k) BP.col(k) = B.col(k) + p.cross(D.col(k));
  // A_P = A' + [p]× B'ᵀ − B_P [p]×, column k of the last term being −B_P (p × e_k).
  Mat3 AP = A;
  for (int k = 0; k < 3; ++k) AP.col(k) += p.cross(B.row(k).transpose());
  AP.col(0) -= p.z() * BP.col(1) - p.y() * BP.col(2);
  AP.col(1) -= p.x() * BP.col(2) - p.z() * BP.col(0);
  AP.col(2) -= p.y() * BP.col(0) - p.x() * BP.col(1);
  I_P.topLeftCorner<3, 3>() += AP;
  I_P.topRightCorner<3, 3>() += BP;
  I_P.bottomLeftCorner<3, 3>() += BP.transpose();
  I_P.bottomRightCorner<3, 3>() += D;
}

// The 6×6 matrix of a rigid-body spatial inertia, written into M.
inline void set_inertia_matrix(const SpatialInertia& I, Mat6& M) {
  M.topLeftCorner<3, 3>() = I.I_O;
  const Mat3 hx = skew(I.h);
  M.topRightCorner<3, 3>() = hx;
  M.bottomLeftCorner<3, 3>() = hx.transpose();
  M.bottomRightCorner<3, 3>() = I.mass * Mat3::Identity();
}

}  // namespace momenta::dynamics::detail
