#include "momenta/dynamics/crba.hpp"

#include "argument_checks.hpp"

#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "forward_pass.hpp"
#include "momenta/common/error.hpp"
#include "momenta/math/sin_cos.hpp"
#include "spatial_inertia_ops.hpp"

namespace momenta::dynamics {
namespace {

// M(start + k, col) = S_W.row(start + k) · F for k < size: dot products of F with rows of the
// nv × 6 matrix S_W, vectorized along its contiguous columns.
inline void column_entries(const MatX& S_W, int start, int size, const Vec6& F, double* out) {
  const Eigen::Index ld = S_W.rows();
  const double* s = S_W.data() + start;
  for (int k = 0; k < size; ++k) {
    out[k] = s[k] * F[0] + s[k + ld] * F[1] + s[k + 2 * ld] * F[2] + s[k + 3 * ld] * F[3] +
             s[k + 4 * ld] * F[4] + s[k + 5 * ld] * F[5];
  }
}

// Copies the upper triangle of the square matrix M into its lower triangle, in tiles so that
// the strided reads stay in cache.
void mirror_upper(MatX& M) {
  const Eigen::Index n = M.rows();
  constexpr Eigen::Index kTile = 16;
  for (Eigen::Index j0 = 0; j0 < n; j0 += kTile) {
    const Eigen::Index j1 = std::min(n, j0 + kTile);
    for (Eigen::Index i0 = j0; i0 < n; i0 += kTile) {
      const Eigen::Index i1 = std::min(n, i0 + kTile);
      // Lower entries (i, j), i > j, of this tile from the upper (j, i).
      for (Eigen::Index j = j0; j < j1; ++j) {
        for (Eigen::Index i = std::max(i0, j + 1); i < i1; ++i) M(i, j) = M(j, i);
      }
    }
  }
}

}  // namespace

// The composite-rigid-body algorithm (Featherstone 2008, §6.2): M(λ, i) = S_λᵀ (I_c,i S_i) for
// every ancestor λ of joint i, I_c,i the composite inertia of joint i's subtree. Composite
// inertias are accumulated in body frames (the joint transforms are cheap there), the products
// taken in W (as Pinocchio's crba does): each entry is then one 6-D dot product, with no
// per-ancestor transform.
const MatX& crba(const Model& model, Data& data, VecRef q) {
  detail::check_data_and_q("crba", model, data, q);
  const auto& joints = model.joint_constants();
  const int nj = static_cast<int>(joints.size());

  // The angles of the joints turning about an axis, all first: independent of one another, their
  // computations overlap.
  for (int j = 0; j < nj; ++j) {
    if (!joints[j].turns_about_axis) continue;
    const auto [s, c] = math::sin_cos(q[joints[j].q_index]);
    data.axis_sin[j] = s;
    data.axis_cos[j] = c;
  }

  // Poses, world poses and motion subspaces in W; composite inertias start as each body's own.
  for (int j = 0; j < nj; ++j) {
    const auto& c = joints[j];
    const int i = c.child;
    const Transform& X_WP = data.X_WB[c.parent];
    Transform& X_WB = data.X_WB[i];
    if (c.turns_about_axis) {
      // X_PB = (Rot_k(q), p_PJ) and R_WB = R_WP Rot_k(q): two columns of R_WP mix; S in W is
      // [R_WB e_k; p_WB × R_WB e_k]. k a compile-time index: no general 3 × 3 products.
      const double sq = data.axis_sin[j], cq = data.axis_cos[j];
      detail::with_axis(c.S_basis, [&](auto axis) {
        constexpr int k = decltype(axis)::value;
        detail::set_axis_rotation<k>(cq, sq, c.X_PJ.p, data.X_PB[i]);
        detail::mix_columns<k>(X_WP.R, cq, sq, X_WB.R);
      });
      X_WB.p = X_WP.p + X_WP.R * c.X_PJ.p;
      const Vec3 w = X_WB.R.col(c.S_basis);
      const Vec3 p_cross_w = X_WB.p.cross(w);
      for (int r = 0; r < 3; ++r) {
        data.S_W(c.v_index, r) = w[r];
        data.S_W(c.v_index, 3 + r) = p_cross_w[r];
      }
    } else {
      detail::position_step(c, j, q.data(), data);
      X_WB = X_WP * data.X_PB[i];
      for (int k = 0; k < c.nv; ++k) {
        data.S_W.row(c.v_index + k) = X_WB.act_motion(data.S[j].col(k)).transpose();
      }
    }
    data.I_composite[i] = model.spatial_inertia(i);
  }

  // Leaves to root: the composite inertia of each subtree in its own body frame (passed to the
  // parent by the joint's transform, half cost for a joint turning about an axis); its force
  // F = I_c S carried to W, and the upper triangle of column i, M(λ, i) = S_λᵀ F, as dot
  // products with the rows of S_W of the joint and its ancestors. Joints that are not ancestors
  // of one another have M = 0 there.
  if (!data.all_dofs_related) data.M.setZero();
  for (int j = nj - 1; j >= 0; --j) {
    const auto& c = joints[j];
    const int i = c.child;
    const SpatialInertia& Ic = data.I_composite[i];
    const Transform& X_WB = data.X_WB[i];
    for (int k = 0; k < c.nv; ++k) {
      const int col = c.v_index + k;
      double F_B[6];
      Vec6 F;
      if (c.S_basis >= 0) {
        kernel::inertia_column(Ic.mass, Ic.h, Ic.I_O, c.S_basis, F_B);
      } else {
        kernel::inertia_times(Ic.mass, Ic.h, Ic.I_O, data.S[j].col(k).data(), F_B);
      }
      kernel::force(X_WB.R, X_WB.p, F_B, F.data());
      for (const auto& [start, size] : data.support_ranges[j]) {
        // Only rows up to this column (the joint's own later columns come with them).
        const int rows = std::min(size, col + 1 - start);
        if (rows > 0) column_entries(data.S_W, start, rows, F, &data.M(start, col));
      }
      data.M(col, col) += c.armature;  // the rotor's reflected inertia (Joint::armature)
    }
    if (c.parent == 0) continue;
    const Transform& X = data.X_PB[i];
    SpatialInertia& I_parent = data.I_composite[c.parent];
    if (c.turns_about_axis) {
      detail::with_axis_rotation(c.S_basis, X.R, [&](auto k, double cq, double sq) {
        I_parent += detail::transformed_about_axis<decltype(k)::value>(Ic, cq, sq, X.p);
      });
    } else {
      I_parent += Ic.transformed(X);
    }
  }
  mirror_upper(data.M);
  return data.M;
}

MatX mass_matrix(const Model& model, VecRef q) {
  Data data(model);
  return crba(model, data, q);
}

void check_mass_matrix(const Model& model, VecRef q) {
  // The coordinates whose acceleration forward dynamics solves for: prescribed joints' motion
  // is given, so their bodies may carry no inertia.
  std::vector<int> free;
  for (int i = 0; i < model.nv(); ++i) {
    if (!model.joint(model.joint_of_v(i)).is_prescribed()) free.push_back(i);
  }
  const MatX M_full = mass_matrix(model, q);
  const int n = static_cast<int>(free.size());
  MatX M(n, n);
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) M(r, c) = M_full(free[r], free[c]);
  }
  // Cholesky without pivoting, in coordinate order, so the first vanishing pivot names the
  // first coordinate whose motion nothing before it or itself resists. A pivot vanishes when it
  // is round-off of its own diagonal entry (a coordinate doing what earlier ones already do), or
  // of the matrix as a whole (a body turned about its own zero-inertia axis, whose entry is
  // m L² cos²(π/2) ≈ 1e-33 rather than exactly 0).
  const double scale = n > 0 ? M.diagonal().cwiseAbs().maxCoeff() : 0.0;
  MatX L = MatX::Zero(n, n);
  for (int j = 0; j < n; ++j) {
    const double pivot = M(j, j) - L.row(j).head(j).squaredNorm();
    if (!(pivot > 1e-12 * M(j, j)) || !(pivot > 1e-14 * scale)) {
      const model::Joint& joint = model.joint(model.joint_of_v(free[j]));
      InvalidArgument error(fmt::format(
          "joint '{}': the mass matrix is singular along its coordinate '{}' (pivot {:.3g} of "
          "M_ii = {:.3g}): no inertia resists that motion. A body with zero inertia about an "
          "axis its joint lets it turn about (a slender rod or point mass spinning about "
          "itself), or a massless body carrying degrees of freedom, has no defined "
          "acceleration. Give the body inertia about that axis (a cylinder rather than a slender "
          "rod) or remove the freedom (a revolute or fixed joint)",
          joint.name, model.v_name(free[j]), pivot, M(j, j)));
      error.about(ModelItemRef::Kind::joint, joint.name);
      throw error;
    }
    L(j, j) = std::sqrt(pivot);
    for (int i = j + 1; i < n; ++i) {
      L(i, j) = (M(i, j) - L.row(i).head(j).dot(L.row(j).head(j))) / L(j, j);
    }
  }
}

}  // namespace momenta::dynamics
