#include "expression_algebra.hpp"

#include <cmath>

namespace momenta::symbolic::detail {

using GiNaC::numeric;

ex exact_number(double x) {
  if (x == 0.0) return 0;
  double scale = 1.0;
  for (int k = 0; k <= 12; ++k, scale *= 10.0) {
    const double s = x * scale;
    if (std::abs(s) >= 1e15) break;
    const double whole = std::round(s);
    if (whole == s && whole / scale == x) {
      return numeric(static_cast<long>(whole)) / numeric(static_cast<long>(scale));
    }
  }
  return numeric(x);
}

M3 M3::identity() {
  M3 m;
  for (int i = 0; i < 3; ++i) m(i, i) = 1;
  return m;
}

V3 to_v3(const Vec3& v) {
  return {{exact_number(v.x()), exact_number(v.y()), exact_number(v.z())}};
}

M3 to_m3(const Mat3& m) {
  M3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = exact_number(m(i, j));
  return r;
}

V3 operator+(const V3& a, const V3& b) { return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}}; }
V3 operator-(const V3& a, const V3& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
V3 operator*(const ex& s, const V3& a) { return {{s * a[0], s * a[1], s * a[2]}}; }

V3 operator*(const M3& m, const V3& a) {
  V3 r;
  for (int i = 0; i < 3; ++i) r[i] = m(i, 0) * a[0] + m(i, 1) * a[1] + m(i, 2) * a[2];
  return r;
}

M3 operator*(const M3& a, const M3& b) {
  M3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = a(i, 0) * b(0, j) + a(i, 1) * b(1, j) + a(i, 2) * b(2, j);
  return r;
}

M3 transpose(const M3& m) {
  M3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = m(j, i);
  return r;
}

V3 cross(const V3& a, const V3& b) {
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

ex dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

M3 axis_rotation(const V3& a, const ex& theta) {
  const ex c = GiNaC::cos(theta), s = GiNaC::sin(theta), t = 1 - c;
  M3 R;
  R(0, 0) = t * a[0] * a[0] + c;
  R(0, 1) = t * a[0] * a[1] - s * a[2];
  R(0, 2) = t * a[0] * a[2] + s * a[1];
  R(1, 0) = t * a[0] * a[1] + s * a[2];
  R(1, 1) = t * a[1] * a[1] + c;
  R(1, 2) = t * a[1] * a[2] - s * a[0];
  R(2, 0) = t * a[0] * a[2] - s * a[1];
  R(2, 1) = t * a[1] * a[2] + s * a[0];
  R(2, 2) = t * a[2] * a[2] + c;
  return R;
}

M3 quaternion_rotation(const ex& w, const ex& x, const ex& y, const ex& z) {
  M3 R;
  R(0, 0) = 1 - 2 * (y * y + z * z);
  R(0, 1) = 2 * (x * y - w * z);
  R(0, 2) = 2 * (x * z + w * y);
  R(1, 0) = 2 * (x * y + w * z);
  R(1, 1) = 1 - 2 * (x * x + z * z);
  R(1, 2) = 2 * (y * z - w * x);
  R(2, 0) = 2 * (x * z - w * y);
  R(2, 1) = 2 * (y * z + w * x);
  R(2, 2) = 1 - 2 * (x * x + y * y);
  return R;
}

Motion operator+(const Motion& a, const Motion& b) { return {a.w + b.w, a.v + b.v}; }
Force operator+(const Force& a, const Force& b) { return {a.n + b.n, a.f + b.f}; }

Motion cross_motion(const Motion& a, const Motion& b) {
  return {cross(a.w, b.w), cross(a.w, b.v) + cross(a.v, b.w)};
}

Force cross_force(const Motion& a, const Force& b) {
  return {cross(a.w, b.n) + cross(a.v, b.f), cross(a.w, b.f)};
}

Motion motion_to_child(const M3& R, const V3& p, const Motion& m) {
  const M3 Rt = transpose(R);
  return {Rt * m.w, Rt * (m.v + cross(m.w, p))};
}

Force force_to_parent(const M3& R, const V3& p, const Force& f) {
  const V3 force = R * f.f;
  return {R * f.n + cross(p, force), force};
}

Motion motion_to_body(const M3& R, const V3& p, const Motion& m) {
  const V3 w = R * m.w;
  return {w, R * m.v + cross(p, w)};
}

Force Inertia::apply(const Motion& m) const {
  return {I_o * m.w + cross(h, m.v), mass * m.v - cross(h, m.w)};
}

ex tidy(const ex& e) {
  using GiNaC::wild;
  ex x = GiNaC::expand(e);
  x = x.subs(GiNaC::pow(GiNaC::sin(wild(0)), 2) == 1 - GiNaC::pow(GiNaC::cos(wild(0)), 2),
             GiNaC::subs_options::algebraic);
  return GiNaC::expand(x);
}

namespace {
void count_nodes(const ex& e, int cap, int& count) {
  if (++count > cap) return;
  for (std::size_t i = 0; i < e.nops() && count <= cap; ++i) count_nodes(e.op(i), cap, count);
}
}  // namespace

int expression_size(const ex& e, int cap) {
  int count = 0;
  count_nodes(e, cap, count);
  return count;
}

ex tidy_if_small(const ex& e) {
  if (expression_size(e, kTidyNodes) > kTidyNodes) return e;
  return tidy(e);
}

}  // namespace momenta::symbolic::detail
