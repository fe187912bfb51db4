#include "momenta/dynamics/constraint_derivatives.hpp"

#include <utility>

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

using detail::Along;

template <int Rows, int Cols>
Eigen::Matrix<Dual, Rows, Cols> with_slope(const Eigen::Matrix<double, Rows, Cols>& value,
                                           const Eigen::Matrix<double, Rows, Cols>& slope) {
  Eigen::Matrix<Dual, Rows, Cols> out;
  for (int i = 0; i < Rows * Cols; ++i) out(i) = Dual(value(i), slope(i));
  return out;
}

template <int Rows>
Eigen::Matrix<double, Rows, 1> slope_of(const Eigen::Matrix<Dual, Rows, 1>& x) {
  Eigen::Matrix<double, Rows, 1> out;
  for (int i = 0; i < Rows; ++i) out(i) = x(i).slope;
  return out;
}

// The motions of one constraint's two frames at the state of rnea_derivatives (A as whole
// accelerations), and as dual numbers along one coordinate.
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

  // Both frames along coordinate k: a moved frame turns and shifts by the body's twist, its
  // velocity and acceleration change at the body's rates (detail::body_motion_rate).
  std::pair<DualMotion, DualMotion> along(int k, Along direction) const {
    return {seeded(frames_.a, ma_, k, direction), seeded(frames_.b, mb_, k, direction)};
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

  DualMotion seeded(int body, const FrameMotion& m, int k, Along direction) const {
    const detail::BodyMotionRate rate = detail::body_motion_rate(data_, body, k, direction);
    const Vec3 turn = rate.twist.head<3>();
    return {with_slope(m.R, Mat3(skew(turn) * m.R)),
            with_slope(m.p, Vec3(turn.cross(m.p) + rate.twist.tail<3>())), with_slope(m.V, rate.V),
            with_slope(m.A, rate.A)};
  }

  const Data& data_;
  detail::JoinedFrames frames_;
  Vec6 gravity_W_;
  FrameMotion ma_, mb_;
};

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

// One constraint's share of ∂(Gᵀ λ)/∂q (rows [first, first + count) on bodies a and b): each
// body's wrench F (λ-weighted, in W) reaches coordinate j as S_j · F over the coordinates
// supporting it, so ∂/∂q_k = S_j · ∂F/∂q_k + (S_k × S_j) · F where k moves S_j.
void add_force_derivative(const Model& model, const Data& data, VecRef lambda, int first, int count,
                          const detail::JoinedFrames& frames, ConstraintDerivatives& out) {
  Vec6 F = Vec6::Zero();
  Mat6X dF = Mat6X::Zero(6, model.nv());
  for (int i = first; i < first + count; ++i) {
    F += lambda[i] * out.rows.wrench_W[i];
    dF += lambda[i] * out.wrench_dq[i];
  }
  for (const auto& [body, sign] : {std::pair{frames.b, 1.0}, std::pair{frames.a, -1.0}}) {
    if (body == 0) continue;
    const auto& support = data.support_ranges[body - 1];
    for (const auto& [start, size] : support) {
      for (int j = start; j < start + size; ++j) {
        const Vec6 S_j = data.dS_W.col(j);
        out.force_dq.row(j) += sign * S_j.transpose() * dF;
        for (const auto& [k_start, k_size] : support) {
          for (int k = k_start; k < k_start + k_size; ++k) {
            if (detail::moves_column(model, k, j))
              out.force_dq(j, k) += sign * cross_motion(data.dS_W.col(k), S_j).dot(F);
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
  out.force_dq.setZero();
  for (Mat6X& w : out.wrench_dq) w.setZero();

  for (int c = 0; c < static_cast<int>(model.constraints().size()); ++c) {
    const model::Constraint& constraint = model.constraints()[c];
    if (std::holds_alternative<model::JointCoupler>(constraint)) continue;  // constant rows
    const int first = out.rows.first_row[c];
    if (!out.rows.enabled[first]) continue;  // an open contact: zero rows
    const detail::JoinedFrames frames = detail::joined_frames(constraint);
    const ConstraintSeeds seeds(model, data, frames);
    for (int k = 0; k < model.nv(); ++k) {
      if (!seeds.moved_by(k)) continue;
      for (const Along direction : {Along::configuration, Along::velocity}) {
        const auto [ma, mb] = seeds.along(k, direction);
        write_slopes(constraint, ma, mb, first, k, direction, out);
      }
    }
    add_force_derivative(model, data, lambda, first, model::constraint_rows(constraint), frames,
                         out);
  }
}

}  // namespace momenta::dynamics
