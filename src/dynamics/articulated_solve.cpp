#include "momenta/dynamics/articulated_solve.hpp"

#include "argument_checks.hpp"
#include "forward_pass.hpp"

namespace momenta::dynamics {
namespace {

using VecN = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;
constexpr int kGroup = Data::kSolveColumns;

// Up to kGroup columns of X go through the passes together: each body's step is a chain of
// dependent operations on its parent's (or child's) result, and a second, independent column
// fills the wait (one column alone takes twice as long per body).
struct Columns {
  double* x[kGroup];
  int count = 0;
  // articulated_row_factors only: where each column's D⁻¹ u goes, and where its row's
  // acceleration at v̇₀ (the adjoint of pass 3) is added (unused for articulated_solve).
  double* dinv_u[kGroup];
  double* rate[kGroup];
  bool x_zero[kGroup] = {};  // x is 0 (its entries are written, not read): a wrench's column
  bool rows = false;
};

// What pass 3 of aba adds to body i's acceleration before its joint's own v̇_j, with no
// acceleration of the parent: c_i, and for a root joint also ⁱX_0 of the base's −g.
Vec6 own_acceleration(const Model& model, const Data& data, const model::JointConstants& c) {
  Vec6 a = data.c_B[c.child];
  if (c.parent == 0) {
    const Vec6 a_base = spatial(Vec3::Zero(), -model.gravity());
    Vec6 carried;
    detail::to_child(c, data.X_PB[c.child], a_base.data(), carried.data());
    a += carried;
  }
  return a;
}

// Leaves to root: x_j ← u_j = x_j − S_jᵀ p_i, and the force each joint passes on to its parent,
// p_λ += ᵖX_i* (p_i + U_j D_j⁻¹ u_j). Each body's forces are zeroed once passed on (they start
// and end at zero).
//
// A 1-dof joint passes ᵖX_i* p_i + (ᵖX_i* U_j D_j⁻¹) u_j: the second factor once per joint
// (data.solve_U_parent, which pass_accelerations reads too), off the chain of dependent
// operations, so that each column's transform of p_i need not wait for u_j.
void pass_forces(const Model& model, Data& data, std::span<const char> prescribed,
                 const Columns& cols) {
  const auto& joints = model.joint_constants();
  double rate[kGroup] = {};  // rows: summed here, apart from memory the columns may share
  for (int j = static_cast<int>(joints.size()) - 1; j >= 0; --j) {
    const auto& c = joints[j];
    auto& p = data.solve_f[c.child];
    const bool held = !prescribed.empty() && prescribed[j];
    Vec6 a0;  // rows: own_acceleration
    VecN e;   // rows: D⁻¹ (u − Uᵀ a0) of aba's u
    if (cols.rows) {
      a0 = own_acceleration(model, data, c);
      const int n = c.nv;
      if (n == 1) {
        e.resize(1);
        e[0] = data.Dinv[j](0, 0) * (data.u[j][0] - data.U[j].col(0).dot(a0));
      } else {
        e.noalias() = data.Dinv[j].topLeftCorner(n, n) *
                      (data.u[j].head(n) - data.U[j].leftCols(n).transpose() * a0);
      }
    }
    if (c.nv == 1 && !held) {
      const Transform& X = data.X_PB[c.child];
      double* U_parent = data.solve_U_parent[j].data();
      const double D_inv = data.Dinv[j](0, 0);
      detail::to_parent(c, X, data.U[j].col(0).data(), U_parent);
      for (int r = 0; r < 6; ++r) U_parent[r] *= D_inv;
      for (int k = 0; k < cols.count; ++k) {
        double* x = cols.x[k] + c.v_index;
        auto p_k = p.col(k);
        const double x_j = cols.x_zero[k] ? 0.0 : x[0];
        const double u = x_j - (c.S_basis >= 0 ? p_k[c.S_basis] : data.S[j].col(0).dot(p_k));
        x[0] = u;
        if (cols.rows) {
          rate[k] += u * e[0] - p_k.dot(a0);
          cols.dinv_u[k][c.v_index] = D_inv * u;
        }
        if (c.parent == 0) continue;
        double f[6];
        detail::to_parent(c, X, p_k.data(), f);
        auto to = data.solve_f[c.parent].col(k);
        for (int r = 0; r < 6; ++r) to[r] += f[r] + U_parent[r] * u;
      }
      p.leftCols(cols.count).setZero();
      continue;
    }
    for (int k = 0; k < cols.count; ++k) {
      double* x = cols.x[k] + c.v_index;
      auto p_k = p.col(k);
      if (cols.rows) rate[k] -= p_k.dot(a0);
      if (c.nv > 0 && !held) {
        const int n = c.nv;
        auto u = Eigen::Map<VecN>(x, n);
        if (cols.x_zero[k]) u.setZero();
        u.noalias() -= data.S[j].leftCols(n).transpose() * p_k;
        const VecN Dinv_u = data.Dinv[j].topLeftCorner(n, n) * u;
        p_k.noalias() += data.U[j].leftCols(n) * Dinv_u;
        if (cols.rows) {
          rate[k] += u.dot(e);
          Eigen::Map<VecN>(cols.dinv_u[k] + c.v_index, n) = Dinv_u;
        }
      }
    }
    if (c.parent != 0) {
      auto& to = data.solve_f[c.parent];
      for (int k = 0; k < cols.count; ++k) {
        double f[6];
        detail::to_parent(c, data.X_PB[c.child], p.col(k).data(), f);
        for (int r = 0; r < 6; ++r) to(r, k) += f[r];
      }
    }
    p.leftCols(cols.count).setZero();
  }
  if (cols.rows) {
    for (int k = 0; k < cols.count; ++k) *cols.rate[k] += rate[k];
  }
}

// Root to leaves: a_i = ⁱX_λ a_λ, ẍ_j = D_j⁻¹ (u_j − U_jᵀ a_i) written over u_j, a_i += S_j ẍ_j;
// a prescribed joint's ẍ_j is 0.
//
// A 1-dof joint takes U_jᵀ a_i as (ⁱX_λᵀ U_j)ᵀ a_λ = (ᵖX_i* U_j)ᵀ a_λ, with the force U_j
// carried to the parent by pass_forces (data.solve_U_parent), so that each column's ẍ_j and
// ⁱX_λ a_λ are computed side by side from a_λ rather than one after the other.
void pass_accelerations(const Model& model, Data& data, std::span<const char> prescribed,
                        const Columns& cols) {
  const auto& joints = model.joint_constants();
  const Vec6 at_rest = Vec6::Zero();
  for (int j = 0; j < static_cast<int>(joints.size()); ++j) {
    const auto& c = joints[j];
    auto& a = data.solve_a[c.child];
    const bool held = !prescribed.empty() && prescribed[j];
    if (c.nv == 1 && !held) {
      const double D_inv = data.Dinv[j](0, 0);
      const double* U_parent = data.solve_U_parent[j].data();  // ᵖX_i* U_j D_j⁻¹
      for (int k = 0; k < cols.count; ++k) {
        const double* a_parent =
            c.parent == 0 ? at_rest.data() : data.solve_a[c.parent].col(k).data();
        auto a_k = a.col(k);
        detail::to_child(c, data.X_PB[c.child], a_parent, a_k.data());
        double Ua = 0.0;
        for (int r = 0; r < 6; ++r) Ua += U_parent[r] * a_parent[r];
        double* x = cols.x[k] + c.v_index;
        const double xdd = D_inv * x[0] - Ua;
        x[0] = xdd;
        if (c.S_basis >= 0) {
          a_k[c.S_basis] += xdd;
        } else {
          a_k.noalias() += data.S[j].col(0) * xdd;
        }
      }
      continue;
    }
    for (int k = 0; k < cols.count; ++k) {
      auto a_k = a.col(k);
      detail::to_child(c, data.X_PB[c.child],
                       c.parent == 0 ? at_rest.data() : data.solve_a[c.parent].col(k).data(),
                       a_k.data());
      double* x = cols.x[k] + c.v_index;
      if (c.nv == 0) continue;
      if (held) {
        for (int r = 0; r < c.nv; ++r) x[r] = 0.0;
      } else {
        const int n = c.nv;
        auto u = Eigen::Map<VecN>(x, n);
        const VecN xdd =
            data.Dinv[j].topLeftCorner(n, n) * (u - data.U[j].leftCols(n).transpose() * a_k);
        u = xdd;
        a_k.noalias() += data.S[j].leftCols(n) * xdd;
      }
    }
  }
}

}  // namespace

int articulated_row_factors(const Model& model, Data& data, const ConstraintRows& rows,
                            Eigen::Ref<MatX> LGt, Eigen::Ref<MatX> Dinv_LGt,
                            Eigen::Ref<VecX> acceleration, std::span<int> active) {
  const char* const name = "articulated_row_factors";
  detail::check_data(name, model, data);
  detail::check_size(name, "rows (G's columns)", static_cast<long>(rows.G.cols()), model.nv(),
                     "nv");
  const long m = rows.count;
  detail::check_size(name, "LGt (rows)", static_cast<long>(LGt.rows()), model.nv(), "nv");
  detail::check_size(name, "LGt (columns)", static_cast<long>(LGt.cols()), m,
                     "one per constraint row");
  detail::check_size(name, "Dinv_LGt (rows)", static_cast<long>(Dinv_LGt.rows()), model.nv(), "nv");
  detail::check_size(name, "Dinv_LGt (columns)", static_cast<long>(Dinv_LGt.cols()), m,
                     "one per constraint row");
  detail::check_size(name, "acceleration", static_cast<long>(acceleration.size()), m,
                     "one per constraint row");
  detail::check_size(name, "active", static_cast<long>(active.size()), m, "one per constraint row");
  const Vec6 gravity_W = spatial(Vec3::Zero(), model.gravity());
  Columns cols;
  cols.rows = true;
  int count = 0;
  const auto solve = [&] {
    pass_forces(model, data, {}, cols);
    cols.count = 0;
  };
  for (int r = 0; r < rows.count; ++r) {
    acceleration[r] = 0.0;
    if (rows.G.row(r).isZero(0.0)) continue;  // a row that exerts no force here: L 0 = 0
    active[static_cast<std::size_t>(count++)] = r;
    const int a = rows.body_a[r], b = rows.body_b[r];
    const int k = cols.count;
    cols.x_zero[k] = a != b;
    if (a == b) {  // a coupler: its generalized force, G's row
      LGt.col(r) = rows.G.row(r).transpose();
    } else {  // w on body b, −w on body a: what pass 2 makes of them is L Gᵀ
      const Vec6& w = rows.wrench_W[r];
      if (b != 0) data.solve_f[b].col(k) -= data.X_WB[b].act_force_inverse(w);
      if (a != 0) data.solve_f[a].col(k) += data.X_WB[a].act_force_inverse(w);
      // The passes carry accelerations less g (aba's base accelerates at −g); the world does not.
      acceleration[r] = w.dot(gravity_W) * ((b != 0 ? 1.0 : 0.0) - (a != 0 ? 1.0 : 0.0));
    }
    cols.x[k] = LGt.col(r).data();
    cols.dinv_u[k] = Dinv_LGt.col(r).data();
    cols.rate[k] = &acceleration[r];
    if (++cols.count == kGroup) solve();
  }
  if (cols.count > 0) solve();
  return count;
}

void articulated_solve(const Model& model, Data& data, std::span<const char> prescribed,
                       Eigen::Ref<MatX> X) {
  detail::check_data("articulated_solve", model, data);
  detail::check_size("articulated_solve", "X (rows)", static_cast<long>(X.rows()), model.nv(),
                     "nv");
  if (!prescribed.empty()) {
    detail::check_size("articulated_solve", "prescribed", static_cast<long>(prescribed.size()),
                       model.num_joints(), "one flag per joint");
  }
  Columns cols;
  const auto solve = [&] {
    pass_forces(model, data, prescribed, cols);
    pass_accelerations(model, data, prescribed, cols);
    cols.count = 0;
  };
  for (Eigen::Index k = 0; k < X.cols(); ++k) {
    if (X.col(k).isZero(0.0)) continue;  // M⁻¹ 0 = 0: a row that exerts no force here is free
    cols.x[cols.count++] = X.col(k).data();
    if (cols.count == kGroup) solve();
  }
  if (cols.count > 0) solve();
}

}  // namespace momenta::dynamics
