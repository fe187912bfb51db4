// The constraints' rows in symbols (constraint_rows.hpp), row for row as
// src/dynamics/constraints.cpp writes them in numbers.

#include "constraint_rows.hpp"

#include <cmath>

#include <fmt/format.h>

namespace momenta::symbolic::detail {
namespace {

using SourceKind = model::ParameterSource::Kind;
using model::DistanceLink;
using model::JointCoupler;
using model::KnifeEdge;
using model::LoopClosure;
using model::LoopType;
using model::RollingContact;
using model::RollingShape;

// A frame fixed in a body: its axes and origin in W.
struct WorldFrame {
  M3 R;
  V3 p;
  V3 axis(int k) const { return {{R(0, k), R(1, k), R(2, k)}}; }
};

class RowWriter {
 public:
  RowWriter(const model::Model& model, const std::vector<M3>& R_WB, const std::vector<V3>& p_WB,
            const std::vector<ex>& q, const ParameterFn& parameter)
      : model_(model), R_WB_(R_WB), p_WB_(p_WB), q_(q), parameter_(parameter) {}

  std::vector<SymbolicRow> run() {
    for (const model::Constraint& constraint : model_.constraints()) {
      ++index_;
      name_ = model::constraint_name(constraint);
      labels_ = model::constraint_row_labels(constraint);
      label_ = 0;
      if (const auto* c = std::get_if<LoopClosure>(&constraint)) loop(*c);
      if (const auto* c = std::get_if<DistanceLink>(&constraint)) distance(*c);
      if (const auto* c = std::get_if<RollingContact>(&constraint)) rolling(*c);
      if (const auto* c = std::get_if<KnifeEdge>(&constraint)) knife_edge(*c);
      if (const auto* c = std::get_if<JointCoupler>(&constraint)) coupler(*c);
      // A contact (model::Contact) is open in the equations of motion: no rows.
    }
    return std::move(rows_);
  }

 private:
  // The frame, its origin's position a parameter p_<constraint>_<which>_x … in the body.
  // `column`: which of the constraint's frames it is (0 a, or its one frame; 1 b).
  WorldFrame frame(const model::BodyFrame& f, const std::string& which, int column) {
    const auto origin = [&](int k) {
      return parameter_(fmt::format("p_{}_{}_{}", name_, which, "xyz"[k]),
                        {SourceKind::constraint_frame_origin, index_, k, column});
    };
    const V3 p_BF{{origin(0), origin(1), origin(2)}};
    const auto b = static_cast<std::size_t>(f.body_index);
    return {R_WB_[b] * to_m3(f.X_BF.R), p_WB_[b] + R_WB_[b] * p_BF};
  }

  // A force f at point p on body b (−f on a): w = [p × f; f].
  void force_row(const ex& phi, bool holonomic, int a, int b, const V3& p, const V3& f) {
    wrench_row(phi, holonomic, a, b, cross(p, f), f);
  }
  void wrench_row(const ex& phi, bool holonomic, int a, int b, const V3& moment, const V3& force) {
    SymbolicRow row;
    row.name = fmt::format("{}.{}", name_, labels_[static_cast<std::size_t>(label_++)]);
    row.holonomic = holonomic;
    row.position = holonomic ? phi : ex(0);
    row.body_a = a;
    row.body_b = b;
    row.moment = moment;
    row.force = force;
    rows_.push_back(std::move(row));
  }

  void loop(const LoopClosure& c) {
    const WorldFrame A = frame(c.a, "a", 0), B = frame(c.b, "b", 1);
    const V3 d = B.p - A.p;
    const int a = c.a.body_index, b = c.b.body_index;
    const int translations = c.type == LoopType::slider ? 2 : 3;
    for (int k = 0; k < translations; ++k) force_row(dot(A.axis(k), d), true, a, b, B.p, A.axis(k));
    // n_A · m_B = 0; a unit multiplier is the moment −(n × m) on B.
    const auto rotation_row = [&](int i, int j) {
      const V3 n = A.axis(i), m = B.axis(j);
      wrench_row(dot(n, m), true, a, b, ex(-1) * cross(n, m), V3{});
    };
    if (c.type == LoopType::hinge) {
      rotation_row(0, 2);
      rotation_row(1, 2);
    } else if (c.type != LoopType::point) {
      rotation_row(0, 1);
      rotation_row(1, 2);
      rotation_row(2, 0);
    }
  }

  void distance(const DistanceLink& c) {
    const WorldFrame A = frame(c.a, "a", 0), B = frame(c.b, "b", 1);
    const V3 d = B.p - A.p;
    const ex length = GiNaC::sqrt(dot(d, d));
    const ex L = parameter_("L_" + name_, {SourceKind::constraint_length, index_});
    force_row(length - L, true, c.a.body_index, c.b.body_index, B.p, (1 / length) * d);
  }

  // Unit vectors as numbers: the plane's normal n, its point, a sphere's fixed tangent.
  void rolling(const RollingContact& c) {
    const WorldFrame F = frame(c.frame, "centre", 0);
    const V3 n = to_v3(c.plane_normal);
    const ex r = parameter_("r_" + name_, {SourceKind::constraint_radius, index_});
    V3 u = ex(-1) * n, forward;
    if (c.shape == RollingShape::disk) {
      const V3 axis = F.axis(2);
      const ex n_axis = dot(n, axis);
      const ex s = GiNaC::sqrt(1 - n_axis * n_axis);  // |n − (n·z) z| for a unit axis z
      u = (-1 / s) * (n - n_axis * axis);
      forward = (1 / s) * cross(axis, n);
    } else {
      const Vec3& nn = c.plane_normal;
      const Vec3 x = std::abs(nn.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
      forward = to_v3((x - nn * nn.dot(x)).normalized());
    }
    const V3 lateral = cross(n, forward);
    const V3 contact = F.p + r * u;
    const int b = c.frame.body_index;
    force_row(dot(n, contact - to_v3(c.plane_point)), true, 0, b, contact, n);
    force_row(0, false, 0, b, contact, forward);
    force_row(0, false, 0, b, contact, lateral);
  }

  void knife_edge(const KnifeEdge& c) {
    const WorldFrame F = frame(c.frame, "point", 0);
    const V3 n = to_v3(c.plane_normal), blade = F.axis(0);
    const ex n_blade = dot(n, blade);
    const V3 side = (1 / GiNaC::sqrt(1 - n_blade * n_blade)) * cross(n, blade);
    force_row(0, false, 0, c.frame.body_index, F.p, side);
  }

  void coupler(const JointCoupler& c) {
    const model::Joint& ja = model_.joint(c.joint_a_index);
    const model::Joint& jb = model_.joint(c.joint_b_index);
    const ex ratio = parameter_("n_" + name_, {SourceKind::constraint_ratio, index_});
    const ex offset = parameter_("q0_" + name_, {SourceKind::constraint_offset, index_});
    SymbolicRow row;
    row.name = fmt::format("{}.{}", name_, labels_.front());
    row.holonomic = true;
    row.position = q_[static_cast<std::size_t>(ja.q_index)] -
                   ratio * q_[static_cast<std::size_t>(jb.q_index)] - offset;
    row.joint_row = {{ja.v_index, ex(1)}, {jb.v_index, -ratio}};
    rows_.push_back(std::move(row));
  }

  const model::Model& model_;
  const std::vector<M3>& R_WB_;
  const std::vector<V3>& p_WB_;
  const std::vector<ex>& q_;
  const ParameterFn& parameter_;
  int index_ = -1;  // the constraint's index in the model's (its parameters' sources)
  std::string name_;
  std::vector<std::string_view> labels_;
  int label_ = 0;
  std::vector<SymbolicRow> rows_;
};

}  // namespace

std::vector<SymbolicRow> constraint_rows(const model::Model& model, const std::vector<M3>& R_WB,
                                         const std::vector<V3>& p_WB, const std::vector<ex>& q,
                                         const ParameterFn& parameter) {
  return RowWriter(model, R_WB, p_WB, q, parameter).run();
}

}  // namespace momenta::symbolic::detail
