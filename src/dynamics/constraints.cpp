#include "momenta/dynamics/constraints.hpp"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "constraint_row_formulas.hpp"
#include "momenta/common/error.hpp"

namespace momenta::dynamics {
namespace {

using model::Constraint;
using model::DistanceLink;
using model::JointCoupler;
using model::KnifeEdge;
using model::LoopClosure;
using model::LoopType;
using model::RollingContact;
using model::RollingShape;

using FrameMotion = detail::FrameMotionOf<double>;

// Which accelerations a row's term w·(A_b − A_a) + ẇ·(V_b − V_a) takes: none (positions and G
// only), the velocity products (k), the whole accelerations of data's last aba or
// hybrid_dynamics (G v̇ + k), or zero (ẇ·(V_b − V_a) alone).
struct Accelerations {
  enum Kind { none, velocity_products, whole, zero } kind = none;
  Vec6 gravity_W = Vec6::Zero();  // whole: data.A_gf is shifted by −g, added back in W
  const VecX* vdot = nullptr;     // whole: data.vdot, for a coupler's row
  bool velocities() const { return kind != none; }
};

FrameMotion frame_motion(const Data& data, int body, const Transform& X_BF,
                         const Accelerations& acc) {
  FrameMotion m = detail::frame_pose_and_velocity(data, body, X_BF, acc.velocities());
  if (!acc.velocities() || body == 0) return m;
  const Transform& X_WB = data.X_WB[body];
  if (acc.kind == Accelerations::velocity_products) {
    m.A = X_WB.act_motion(data.A_bias_B[body]);
  } else if (acc.kind == Accelerations::whole) {
    m.A = X_WB.act_motion(data.A_gf[body]) + acc.gravity_W;
  }
  return m;
}

// Writes rows one at a time: φ, the wrench w and its rate ẇ (the rate only with velocities).
class RowWriter {
 public:
  RowWriter(ConstraintRows& rows, const Accelerations& acc)
      : rows_(rows), velocities_(acc.velocities()), vdot_(acc.vdot) {}

  // A row whose wrench acts on body b (and its opposite on body a).
  void wrench_row(double phi, bool holonomic, int a, int b, const Vec6& w, const Vec6& w_rate,
                  const FrameMotion& ma, const FrameMotion& mb) {
    rows_.position[i_] = holonomic ? phi : 0.0;
    rows_.wrench_W[i_] = w;
    rows_.body_a[i_] = a;
    rows_.body_b[i_] = b;
    if (velocities_) {
      rows_.bias[i_] = w_rate.dot(mb.V - ma.V) + w.dot(mb.A - ma.A);
    }
    ++i_;
  }
  // A row of G written directly (a coupler): no wrench, no velocity-product term.
  void joint_row(double phi, int v_a, double g_a, int v_b, double g_b) {
    rows_.position[i_] = phi;
    rows_.wrench_W[i_].setZero();
    rows_.body_a[i_] = rows_.body_b[i_] = 0;
    rows_.G.row(i_).setZero();
    rows_.G(i_, v_a) = g_a;
    rows_.G(i_, v_b) = g_b;
    if (velocities_) rows_.bias[i_] = vdot_ ? g_a * (*vdot_)[v_a] + g_b * (*vdot_)[v_b] : 0.0;
    ++i_;
  }

 private:
  ConstraintRows& rows_;
  bool velocities_;
  const VecX* vdot_;  // the accelerations of G v̇ + k, or none (k)
  int i_ = 0;
};

// The rows of a constraint between two bodies' frames (every kind but a coupler), by the
// formulas of constraint_row_formulas.hpp.
void write_wrench_rows(const Constraint& constraint, const Data& data, const Accelerations& acc,
                       RowWriter& out) {
  const detail::JoinedFrames f = detail::joined_frames(constraint);
  const FrameMotion ma = frame_motion(data, f.a, f.X_aF, acc);
  const FrameMotion mb = frame_motion(data, f.b, f.X_bF, acc);
  detail::wrench_rows(constraint, ma, mb,
                      [&](double phi, bool holonomic, const Vec6& w, const Vec6& w_rate) {
                        out.wrench_row(phi, holonomic, f.a, f.b, w, w_rate, ma, mb);
                      });
}

void write_coupler(const JointCoupler& c, const Model& model, VecRef q, RowWriter& out) {
  const model::Joint& ja = model.joint(c.joint_a_index);
  const model::Joint& jb = model.joint(c.joint_b_index);
  out.joint_row(q[ja.q_index] - c.ratio * q[jb.q_index] - c.offset, ja.v_index, 1.0, jb.v_index,
                -c.ratio);
}

// The rows [first, end) of constraint k.
std::pair<int, int> rows_of(const ConstraintRows& rows, int k) {
  const int first = rows.first_row[k];
  const bool last = k + 1 == static_cast<int>(rows.first_row.size());
  return {first, last ? rows.count : rows.first_row[k + 1]};
}

// G's rows of the wrench rows: G_i = w_iᵀ (J_b − J_a), with J a body's Jacobian — the
// motion-subspace columns in W of the joints supporting it. A constraint's rows share their
// bodies, so they are formed together, Wᵀ (6 × rows) times the columns of each contiguous run of
// the supports (Data::support_ranges).
void assemble_jacobian(const Model& model, const Data& data, ConstraintRows& rows) {
  for (int j = 0; j < model.num_joints(); ++j) {
    const auto& c = model.joint_constants()[j];
    const Transform& X_WB = data.X_WB[c.child];
    if (c.nv == 1 && c.S_basis >= 0) {  // a column of ᵂX_B: [R e; p × R e] or [0; R e]
      auto s = rows.S_world.col(c.v_index);
      if (c.S_basis < 3) {
        const Vec3 w = X_WB.R.col(c.S_basis);
        s.head<3>() = w;
        s.tail<3>() = X_WB.p.cross(w);
      } else {
        s.head<3>().setZero();
        s.tail<3>() = X_WB.R.col(c.S_basis - 3);
      }
      continue;
    }
    for (int k = 0; k < c.nv; ++k) {
      rows.S_world.col(c.v_index + k) = X_WB.act_motion(data.S[j].col(k));
    }
  }
  for (int k = 0; k < static_cast<int>(rows.first_row.size()); ++k) {
    // Named apart, not bound: the lambda below captures them (clang before 16 cannot capture a
    // structured binding).
    const std::pair<int, int> range = rows_of(rows, k);
    const int first = range.first, end = range.second;
    const int a = rows.body_a[first], b = rows.body_b[first];
    if (a == b) continue;  // a coupler's row is written already
    const int n = end - first;
    rows.G.middleRows(first, n).setZero();
    // Column by column: the constraint's n entries of a column of G are contiguous.
    const auto add_support = [&](int body, double sign) {
      if (body == 0) return;
      for (const auto& [start, size] : data.support_ranges[body - 1]) {
        for (int col = start; col < start + size; ++col) {
          const Eigen::Map<const Vec6> s(rows.S_world.col(col).data());
          double* g = &rows.G(first, col);
          for (int r = 0; r < n; ++r) g[r] += sign * rows.wrench_W[first + r].dot(s);
        }
      }
    };
    add_support(b, 1.0);
    add_support(a, -1.0);
  }
}

void world_poses(const Model& model, Data& data) {
  for (const auto& c : model.joint_constants()) {
    data.X_WB[c.child] = data.X_WB[c.parent] * data.X_PB[c.child];
  }
}

void bias_accelerations(const Model& model, Data& data) {
  for (const auto& c : model.joint_constants()) {
    data.A_bias_B[c.child] =
        data.X_PB[c.child].act_motion_inverse(data.A_bias_B[c.parent]) + data.c_B[c.child];
  }
}

void write_rows(const Model& model, const Data& data, VecRef q, const Accelerations& acc,
                ConstraintRows& rows) {
  RowWriter out(rows, acc);
  for (const Constraint& constraint : model.constraints()) {
    if (const auto* c = std::get_if<JointCoupler>(&constraint)) {
      write_coupler(*c, model, q, out);
    } else {
      write_wrench_rows(constraint, data, acc, out);
    }
  }
  assemble_jacobian(model, data, rows);
}

}  // namespace

ConstraintRows::ConstraintRows(const Model& model)
    : count(model.num_constraint_rows()),
      position(VecX::Zero(count)),
      G(MatX::Zero(count, model.nv())),
      bias(VecX::Zero(count)),
      wrench_W(count, Vec6::Zero()),
      body_a(count, 0),
      body_b(count, 0),
      S_world(MatX::Zero(6, model.nv())) {
  for (int k = 0; k < static_cast<int>(model.constraints().size()); ++k) {
    const Constraint& c = model.constraints()[k];
    first_row.push_back(static_cast<int>(constraint.size()));
    const std::vector<std::string_view> labels = model::constraint_row_labels(c);
    const int position_rows = model::constraint_position_rows(c);
    for (int r = 0; r < static_cast<int>(labels.size()); ++r) {
      constraint.push_back(k);
      // Rolling: the height row first; a knife edge has none.
      holonomic.push_back(r < position_rows ? 1 : 0);
      enabled.push_back(model::is_unilateral(c) ? 0 : 1);
      names.push_back(fmt::format("{}.{}", model::constraint_name(c), labels[r]));
    }
  }
}

void constraint_equations(const Model& model, Data& data, VecRef q, ConstraintRows& rows,
                          RowTerms terms) {
  Accelerations acc;
  if (terms == RowTerms::with_velocity_products) {
    acc.kind = Accelerations::velocity_products;
  } else if (terms == RowTerms::with_acceleration_residual) {
    acc.kind = Accelerations::whole;
    acc.gravity_W = spatial(Vec3::Zero(), model.gravity());
    acc.vdot = &data.vdot;
  } else if (terms == RowTerms::with_wrench_rates) {
    acc.kind = Accelerations::zero;
  }
  world_poses(model, data);
  if (acc.kind == Accelerations::velocity_products) bias_accelerations(model, data);
  write_rows(model, data, q, acc, rows);
  for (int i = 0; i < rows.count; ++i) {
    if (rows.enabled[i]) continue;
    rows.position[i] = 0.0;
    rows.G.row(i).setZero();
    rows.wrench_W[i].setZero();
    if (acc.velocities()) rows.bias[i] = 0.0;
  }
}

void constraint_forces(const Model& model, const Data& data, const ConstraintRows& rows,
                       VecRef lambda, int k, std::span<double> out) {
  const Constraint& constraint = model.constraints()[k];
  const int first = rows.first_row[k];
  if (const auto* loop = std::get_if<LoopClosure>(&constraint)) {
    Vec6 w = Vec6::Zero();  // in W about Wo
    for (int i = first; i < first + model::constraint_rows(constraint); ++i)
      w += rows.wrench_W[i] * lambda[i];
    const Vec3 p = (data.X_WB[loop->b.body_index] * loop->b.X_BF).p;
    const Vec3 force = w.tail<3>();
    const Vec3 moment = w.head<3>() - p.cross(force);
    for (int j = 0; j < 3; ++j) {
      out[j] = force[j];
      out[3 + j] = moment[j];
    }
  } else if (std::holds_alternative<DistanceLink>(constraint)) {
    out[0] = -lambda[first];  // λ pushes b away from a along e; tension pulls them together
  } else if (std::holds_alternative<RollingContact>(constraint) ||
             std::holds_alternative<model::Contact>(constraint)) {
    // A contact's normal, then its friction along t₁, t₂ where it has friction.
    for (int j = 0; j < model::constraint_rows(constraint); ++j) out[j] = lambda[first + j];
  } else if (std::holds_alternative<KnifeEdge>(constraint)) {
    out[0] = lambda[first];
  } else {
    const auto& coupler = std::get<JointCoupler>(constraint);
    out[0] = lambda[first];
    out[1] = -coupler.ratio * lambda[first];
  }
}

void add_constraint_forces(const Model& model, const Data& data, const ConstraintRows& rows,
                           VecRef lambda, std::span<Vec6> f_ext, VecX& tau) {
  (void)model;
  // A constraint's rows share their bodies: one wrench, carried into each body once.
  for (int k = 0; k < static_cast<int>(rows.first_row.size()); ++k) {
    const auto [first, end] = rows_of(rows, k);
    const int a = rows.body_a[first], b = rows.body_b[first];
    if (a == b) {  // a coupler: a generalized force
      tau.noalias() += rows.G.row(first).transpose() * lambda[first];
      continue;
    }
    Vec6 f = Vec6::Zero();
    for (int i = first; i < end; ++i) f += rows.wrench_W[i] * lambda[i];
    // W about Wo → B about Bo.
    if (b != 0) f_ext[b] += data.X_WB[b].act_force_inverse(f);
    if (a != 0) f_ext[a] -= data.X_WB[a].act_force_inverse(f);
  }
}

}  // namespace momenta::dynamics
