#include "momenta/dynamics/aba_derivatives.hpp"

#include <utility>
#include <vector>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/aba.hpp"
#include "rnea_derivatives_detail.hpp"

namespace momenta::dynamics {
namespace {

// Every joint's D⁻¹ = (Sᵀ IA S)⁻¹ from aba is finite with a positive diagonal, or M is singular.
void check_articulated_factors(const Model& model, const Data& data) {
  const auto& joints = model.joint_constants();
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const int n = joints[j].nv;
    const auto Dinv = data.Dinv[j].topLeftCorner(n, n);
    if (!Dinv.allFinite() || (n > 0 && Dinv.diagonal().minCoeff() <= 0.0)) {
      throw NumericalError(
          "aba_derivatives: the mass matrix is not positive definite (a joint that carries no "
          "mass or inertia along one of its axes)");
    }
  }
}

// Run r of a joint's subtree ranges without the joint's own n coordinates (which open run 0).
std::pair<int, int> below_joint(const std::vector<std::pair<int, int>>& ranges, std::size_t r,
                                int n) {
  const auto [first, size] = ranges[r];
  return r == 0 ? std::pair{first + n, size - n} : std::pair{first, size};
}

// The two passes' steps for a joint with one coordinate k, column by column over 6-vectors (the
// general blocks' dispatch would cost more than their arithmetic at these sizes).
using ConstVec6Map = Eigen::Map<const Vec6>;
using Mat6N = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6>;  // a joint's columns, on the stack
using Vec6Map = Eigen::Map<Vec6>;

void backward_step_1dof(Data& data, const model::JointConstants& c, int j) {
  const int k = c.v_index;
  const double d = data.Dinv[j](0, 0);
  const Vec6 S_d = data.dS_W.col(k) * d;
  const Vec6 U = data.minv_U_W.col(k);
  double* M_k = data.Minv.col(k).data();  // below the diagonal: rows of the subtree
  double* F = data.minv_F_W.data();
  const bool passes_up = c.parent != 0;
  if (passes_up) Vec6Map(F + 6 * k) = U * d;
  const auto& ranges = data.subtree_ranges[j];
  for (std::size_t r = 0; r < ranges.size(); ++r) {
    const auto [first, size] = below_joint(ranges, r, 1);
    for (int col = first; col < first + size; ++col) {
      const double m = -ConstVec6Map(F + 6 * col).dot(S_d);
      M_k[col] = m;
      if (passes_up) Vec6Map(F + 6 * col) += U * m;
    }
  }
}

void forward_step_1dof(Data& data, const model::JointConstants& c, int j, int nv) {
  const int k = c.v_index;
  const double d = data.Dinv[j](0, 0);
  const Vec6 S = data.dS_W.col(k);
  const Vec6 U_d = data.minv_U_W.col(k) * d;
  double* M_k = data.Minv.col(k).data();
  double* A = data.minv_A_W[c.child].data();
  if (c.parent == 0) {
    for (int col = k; col < nv; ++col) Vec6Map(A + 6 * col) = S * M_k[col];
    return;
  }
  const double* A_parent = data.minv_A_W[c.parent].data();
  for (int col = k; col < nv; ++col) {
    const ConstVec6Map a_parent(A_parent + 6 * col);
    const double m = M_k[col] - a_parent.dot(U_d);
    M_k[col] = m;
    Vec6Map(A + 6 * col) = a_parent + S * m;
  }
}

// M⁻¹ from the articulated-body factors U = IA S and D⁻¹ that aba left (Carpentier, "Analytical
// inverse of the joint space inertia matrix", 2018: the algorithm of Pinocchio's computeMinverse),
// in W so that no transform is needed between bodies, and written into the lower triangle (the
// columns of a joint's coordinates are contiguous there), then mirrored. With J a joint's
// coordinates, U, S and D⁻¹ its factors, F its subtree's test forces and A its parent's test
// accelerations:
//   leaves to root:  M⁻¹(J, J) = D⁻¹,  M⁻¹(k, J) = −(F_kᵀ S) D⁻¹ for k below J,
//                    F_k += U M⁻¹(k, J)ᵀ for k in J's subtree (passed up unchanged in W);
//   root to leaves:  M⁻¹(k, J) −= (A_kᵀ U) D⁻¹ for k ≥ J,  A_k ← A_k + S M⁻¹(k, J)ᵀ.
// The entries below the diagonal outside J's subtree (none in a chain) start at zero and take
// only the second pass's term. O(n d) per coordinate for a tree of depth d.
void inverse_mass_matrix(const Model& model, Data& data) {
  const auto& joints = model.joint_constants();
  const int nj = static_cast<int>(joints.size());
  const int nv = model.nv();
  MatX& Minv = data.Minv;
  if (!data.all_dofs_related) Minv.setZero();  // otherwise the first pass writes every entry
  for (int j = 0; j < nj; ++j) {
    const auto& c = joints[j];
    for (int k = 0; k < c.nv; ++k) {
      data.minv_U_W.col(c.v_index + k) = data.X_WB[c.child].act_force(data.U[j].col(k));
    }
  }

  for (int j = nj - 1; j >= 0; --j) {
    const auto& c = joints[j];
    const int n = c.nv;
    if (n == 0) continue;  // the forces pass through a body welded to its parent unchanged
    const auto S = data.dS_W.middleCols(c.v_index, n);
    const auto U = data.minv_U_W.middleCols(c.v_index, n);
    const auto Dinv = data.Dinv[j].topLeftCorner(n, n);
    Minv.block(c.v_index, c.v_index, n, n) = Dinv;
    if (n == 1) {
      backward_step_1dof(data, c, j);
      continue;
    }
    const bool passes_up = c.parent != 0;
    Mat6N minus_S_Dinv(6, n);  // the sign here: Eigen would copy a negated F or S to the heap
    minus_S_Dinv.noalias() = S * Dinv;
    minus_S_Dinv = -minus_S_Dinv;
    if (passes_up) data.minv_F_W.middleCols(c.v_index, n).noalias() = U * Dinv;
    const auto& ranges = data.subtree_ranges[j];
    for (std::size_t r = 0; r < ranges.size(); ++r) {
      const auto [start, size] = below_joint(ranges, r, n);
      auto F = data.minv_F_W.middleCols(start, size);
      auto below = Minv.block(start, c.v_index, size, n);
      below.noalias() = F.transpose() * minus_S_Dinv;
      if (!passes_up) continue;
      for (int col = 0; col < size; ++col) {  // a column at a time: Eigen would copy below
        F.col(col).noalias() += U * below.row(col).transpose();
      }
    }
  }

  for (int j = 0; j < nj; ++j) {
    const auto& c = joints[j];
    const int n = c.nv;
    const int tail = nv - c.v_index;
    const auto A_parent = data.minv_A_W[c.parent].rightCols(tail);
    auto A = data.minv_A_W[c.child].rightCols(tail);
    if (n == 0) {
      A = A_parent;
      continue;
    }
    if (n == 1) {
      forward_step_1dof(data, c, j, nv);
      continue;
    }
    const auto S = data.dS_W.middleCols(c.v_index, n);
    const auto U = data.minv_U_W.middleCols(c.v_index, n);
    const auto Dinv = data.Dinv[j].topLeftCorner(n, n);
    auto after = Minv.block(c.v_index, c.v_index, tail, n);
    if (c.parent != 0) {
      const Mat6N U_Dinv = U * Dinv;
      after.noalias() -= A_parent.transpose() * U_Dinv;
      A = A_parent;
      A.noalias() += S * after.transpose();
    } else {
      A.noalias() = S * after.transpose();
    }
  }

  for (int col = 1; col < nv; ++col) {
    Minv.col(col).head(col) = Minv.row(col).head(col).transpose();
  }
}

}  // namespace

// Up to this size the two products go coefficient by coefficient: Eigen's blocked product spends
// more packing its operands than multiplying them (7 coordinates: 4.06 → 3.7 µs a call; at 32 the
// blocked product is the faster, 26.6 against 32.8 µs).
constexpr int kLazyProductMaxNv = 16;

void aba_derivatives(const Model& model, Data& data, VecRef q, VecRef v, VecRef tau,
                     std::span<const Vec6> f_ext) {
  // v̇ and the articulated-body factors first (aba checks the arguments), then ∂τ/∂(q, v) at that
  // v̇ (with the bodies' poses and the coordinates' columns in W), then M⁻¹ from the factors.
  aba(model, data, q, v, tau, f_ext);
  check_articulated_factors(model, data);
  detail::rnea_derivatives_at_current_positions(model, data, q, v, data.vdot, f_ext);
  inverse_mass_matrix(model, data);
  if (model.nv() <= kLazyProductMaxNv) {
    data.dvdot_dq.noalias() = -data.Minv.lazyProduct(data.dtau_dq);
    data.dvdot_dv.noalias() = -data.Minv.lazyProduct(data.dtau_dv);
  } else {
    data.dvdot_dq.noalias() = -data.Minv * data.dtau_dq;
    data.dvdot_dv.noalias() = -data.Minv * data.dtau_dv;
  }
}

}  // namespace momenta::dynamics
