#include "momenta/dynamics/constraint_derivatives.hpp"

#include <utility>

#include <fmt/format.h>

#include "argument_checks.hpp"
#include "constraint_row_formulas.hpp"
#include "joint_stages.hpp"
#include "momenta/common/error.hpp"
#include "momenta/dynamics/rnea_derivatives.hpp"

namespace momenta::dynamics {
namespace {

using detail::Dual;
using FrameMotion = detail::FrameMotionOf<double>;
using DualMotion = detail::FrameMotionOf<Dual>;

// A frame's motion and its derivative along one direction (the same members, as rates).
struct MotionSlope {
  Mat3 R = Mat3::Zero();
  Vec3 p = Vec3::Zero();
  Vec6 V = Vec6::Zero();
  Vec6 A = Vec6::Zero();
};

template <int Rows, int Cols>
Eigen::Matrix<Dual, Rows, Cols> with_slope(const Eigen::Matrix<double, Rows, Cols>& value,
                                           const Eigen::Matrix<double, Rows, Cols>& slope) {
  Eigen::Matrix<Dual, Rows, Cols> out;
  for (int i = 0; i < Rows * Cols; ++i) out(i) = Dual(value(i), slope(i));
  return out;
}

DualMotion dual_motion(const FrameMotion& m, const MotionSlope& s) {
  return {with_slope(m.R, s.R), with_slope(m.p, s.p), with_slope(m.V, s.V), with_slope(m.A, s.A)};
}

template <int Rows>
Eigen::Matrix<double, Rows, 1> slope_of(const Eigen::Matrix<Dual, Rows, 1>& x) {
  Eigen::Matrix<double, Rows, 1> out;
  for (int i = 0; i < Rows; ++i) out(i) = x(i).slope;
  return out;
}

// Whether coordinate k moves the column of coordinate j, both supporting one body: k in an
// ancestor joint, or in j's joint at j's stage or an earlier one.
bool moves_column(const Model& model, int k, int j) {
  const model::JointConstants& c = model.joint_constants()[model.joint_of_v(j)];
  if (k < c.v_index) return true;
  if (k >= c.v_index + c.nv) return false;
  return detail::joint_stage(c.type, k - c.v_index) <= detail::joint_stage(c.type, j - c.v_index);
}

// The motions of one constraint's frames at the state of rnea_derivatives (A as whole
// accelerations), and their derivatives along each coordinate.
class ConstraintSeeds {
 public:
  ConstraintSeeds(const Model& model, const Data& data, detail::JoinedFrames frames)
      : data_(data),
        frames_(std::move(frames)),
        gravity_W_(spatial(Vec3::Zero(), model.gravity())) {
    ma_ = motion(frames_.a, frames_.X_aF);
    mb_ = motion(frames_.b, frames_.X_bF);
  }

  bool moved_by(int k) const {
    return detail::supports(data_, frames_.a, k) || detail::supports(data_, frames_.b, k);
  }

  // Along δq_k: a moved frame turns and shifts by the twist S_k, its velocity and acceleration
  // change as the header says.
  std::pair<DualMotion, DualMotion> along_configuration(int k) const {
    return {dual_motion(ma_, configuration_slope(frames_.a, ma_, k)),
            dual_motion(mb_, configuration_slope(frames_.b, mb_, k))};
  }
  // Along δv_k: poses fixed, ∂V = S_k, ∂A = S_k × V + W_k for a body coordinate k supports.
  std::pair<DualMotion, DualMotion> along_velocity(int k) const {
    return {dual_motion(ma_, velocity_slope(frames_.a, ma_, k)),
            dual_motion(mb_, velocity_slope(frames_.b, mb_, k))};
  }

 private:
  FrameMotion motion(int body, const Transform& X_BF) const {
    FrameMotion m;
    const Transform X_WF = data_.X_WB[body] * X_BF;
    m.R = X_WF.R;
    m.p = X_WF.p;
    m.V = data_.dV_W[body];
    m.A = data_.dA_W[body] + gravity_W_;  // the world's: −g + g = 0
    return m;
  }

  MotionSlope configuration_slope(int body, const FrameMotion& m, int k) const {
    MotionSlope s;
    if (!detail::supports(data_, body, k)) return s;
    const Vec6 S = data_.dS_W.col(k);
    const Vec6 delta_V = data_.dDeltaV_W.col(k);
    const Vec3 turn = S.head<3>();
    s.R = skew(turn) * m.R;
    s.p = turn.cross(m.p) + S.tail<3>();
    s.V = cross_motion(S, m.V) + delta_V;
    // x_k was formed with the shifted accelerations: S_k × A with them too.
    s.A = cross_motion(S, data_.dA_W[body]) + cross_motion(delta_V, m.V) + data_.dX_W.col(k);
    return s;
  }

  MotionSlope velocity_slope(int body, const FrameMotion& m, int k) const {
    MotionSlope s;
    if (!detail::supports(data_, body, k)) return s;
    const Vec6 S = data_.dS_W.col(k);
    s.V = S;
    s.A = cross_motion(S, m.V) + data_.dW_W.col(k);
    return s;
  }

  const Data& data_;
  detail::JoinedFrames frames_;
  Vec6 gravity_W_;
  FrameMotion ma_, mb_;
};

enum class Along { configuration, velocity };

// The derivative parts of one constraint's rows (from row `first`) along coordinate `column`:
// along δq its wrenches', G v's and G v̇ + k's; along δv, G v̇ + k's.
void write_slopes(const model::Constraint& constraint, const DualMotion& ma, const DualMotion& mb,
                  int first, int column, Along along, ConstraintDerivatives& out) {
  int i = first;
  detail::wrench_rows(
      constraint, ma, mb,
      [&](const Dual&, bool, const detail::Vec6Of<Dual>& w, const detail::Vec6Of<Dual>& w_rate) {
        const detail::Vec6Of<Dual> dV = mb.V - ma.V;
        const Dual residual = w_rate.dot(dV) + w.dot(mb.A - ma.A);
        if (along == Along::configuration) {
          out.wrench_dq[i].col(column) = slope_of(w);
          out.velocity_dq(i, column) = w.dot(dV).slope;
          out.residual_dq(i, column) = residual.slope;
        } else {
          out.residual_dv(i, column) = residual.slope;
        }
        ++i;
      });
}

// ∂(Gᵀ λ)/∂q: body by body, its constraint wrench F (λ-weighted, in W) reaches coordinate j
// as S_j · F over the coordinates supporting it, so ∂/∂q_k = S_j · ∂F/∂q_k + (S_k × S_j) · F
// where k moves S_j.
void constraint_force_derivative(const Model& model, const Data& data, VecRef lambda,
                                 ConstraintDerivatives& out) {
  const ConstraintRows& rows = out.rows;
  out.force_dq.setZero();
  Mat6X dF(6, model.nv());
  for (int c = 0; c < static_cast<int>(rows.first_row.size()); ++c) {
    const int first = rows.first_row[c];
    const int end =
        c + 1 < static_cast<int>(rows.first_row.size()) ? rows.first_row[c + 1] : rows.count;
    const int a = rows.body_a[first], b = rows.body_b[first];
    if (a == b) continue;  // a coupler
    Vec6 F = Vec6::Zero();
    dF.setZero();
    for (int i = first; i < end; ++i) {
      F += lambda[i] * rows.wrench_W[i];
      dF += lambda[i] * out.wrench_dq[i];
    }
    for (const auto& [body, sign] : {std::pair{b, 1.0}, std::pair{a, -1.0}}) {
      if (body == 0) continue;
      for (const auto& [start, size] : data.support_ranges[body - 1]) {
        for (int j = start; j < start + size; ++j) {
          const Vec6 S_j = data.dS_W.col(j);
          out.force_dq.row(j) += sign * S_j.transpose() * dF;
          for (const auto& [k_start, k_size] : data.support_ranges[body - 1]) {
            for (int k = k_start; k < k_start + k_size; ++k) {
              if (moves_column(model, k, j))
                out.force_dq(j, k) += sign * cross_motion(data.dS_W.col(k), S_j).dot(F);
            }
          }
        }
      }
    }
  }
}

}  // namespace

ConstraintDerivatives::ConstraintDerivatives(const Model& model)
    : velocity_dq(MatX::Zero(model.num_constraint_rows(), model.nv())),
      residual_dq(MatX::Zero(model.num_constraint_rows(), model.nv())),
      residual_dv(MatX::Zero(model.num_constraint_rows(), model.nv())),
      force_dq(MatX::Zero(model.nv(), model.nv())),
      rows(model),
      wrench_dq(static_cast<std::size_t>(model.num_constraint_rows()), Mat6X::Zero(6, model.nv())) {
}

void constraint_derivatives(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot,
                            VecRef lambda, ConstraintDerivatives& out) {
  detail::check_inverse_dynamics("constraint_derivatives", model, data, q, v, vdot, {});
  detail::check_size("constraint_derivatives", "lambda", lambda.size(), model.num_constraint_rows(),
                     "num_constraint_rows");

  // Poses, velocities, accelerations and each coordinate's terms, in W; then the rows there.
  rnea_derivatives(model, data, q, v, vdot);
  constraint_equations(model, data, q, out.rows);
  out.velocity_dq.setZero();
  out.residual_dq.setZero();
  out.residual_dv.setZero();
  for (Mat6X& w : out.wrench_dq) w.setZero();

  for (int c = 0; c < static_cast<int>(model.constraints().size()); ++c) {
    const model::Constraint& constraint = model.constraints()[c];
    if (std::holds_alternative<model::JointCoupler>(constraint)) continue;  // constant rows
    const detail::JoinedFrames frames = detail::joined_frames(constraint);
    const ConstraintSeeds seeds(model, data, frames);
    const int first = out.rows.first_row[c];
    for (int k = 0; k < model.nv(); ++k) {
      if (!seeds.moved_by(k)) continue;
      const auto [qa, qb] = seeds.along_configuration(k);
      write_slopes(constraint, qa, qb, first, k, Along::configuration, out);
      const auto [va, vb] = seeds.along_velocity(k);
      write_slopes(constraint, va, vb, first, k, Along::velocity, out);
    }
  }
  constraint_force_derivative(model, data, lambda, out);
}

}  // namespace momenta::dynamics
