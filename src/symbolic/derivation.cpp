// The derivation: symbols for coordinates, signals and parameters; the symbolic Newton–Euler
// passes in body frames; the elements' and the constraints' forces; M, g, the rest and Q split
// and tidied (equations.hpp).

#include "derivation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "constraint_rows.hpp"
#include "equations_impl.hpp"
#include "expression_algebra.hpp"
#include "momenta/common/error.hpp"
#include "momenta/inertia/unit_moments.hpp"
#include "momenta/model/units.hpp"

namespace momenta::symbolic::detail {
namespace {

using SourceKind = model::ParameterSource::Kind;

// A joint's number as a parameter's source (joint j carries body j + 1).
model::ParameterSource joint_source(SourceKind kind, const model::Joint& j) {
  return {kind, j.child_index - 1};
}

}  // namespace

JointMotion joint_motion(const model::Joint& j, const std::vector<ex>& q, int qi) {
  const V3 a = to_v3(j.axis), a2 = to_v3(j.axis2), zero;
  JointMotion m;
  m.R = M3::identity();
  switch (j.type) {
    case model::JointType::fixed:
      break;
    case model::JointType::revolute:
      m.R = axis_rotation(a, q[qi]);
      m.S = {Motion{a, zero}};
      break;
    case model::JointType::prismatic:
      m.p = q[qi] * a;
      m.S = {Motion{zero, a}};
      break;
    case model::JointType::cylindrical:
      m.R = axis_rotation(a, q[qi]);
      m.p = q[qi + 1] * a;
      m.S = {Motion{a, zero}, Motion{zero, a}};
      break;
    case model::JointType::universal: {
      const M3 R2 = axis_rotation(a2, q[qi + 1]);
      m.R = axis_rotation(a, q[qi]) * R2;
      m.S = {Motion{transpose(R2) * a, zero}, Motion{a2, zero}};
      break;
    }
    case model::JointType::spherical:
      m.R = quaternion_rotation(q[qi], q[qi + 1], q[qi + 2], q[qi + 3]);
      for (int k = 0; k < 3; ++k) {
        V3 e;
        e[k] = 1;
        m.S.push_back(Motion{e, zero});
      }
      break;
    case model::JointType::planar: {
      const M3 Rt = transpose(axis_rotation(to_v3(Vec3::UnitZ()), q[qi + 2]));
      m.R = transpose(Rt);
      m.p = {{q[qi], q[qi + 1], 0}};
      V3 c0, c1, z;
      for (int r = 0; r < 3; ++r) {
        c0[r] = Rt(r, 0);
        c1[r] = Rt(r, 1);
      }
      z[2] = 1;
      m.S = {Motion{zero, c0}, Motion{zero, c1}, Motion{z, zero}};
      break;
    }
    case model::JointType::free: {
      m.R = quaternion_rotation(q[qi + 3], q[qi + 4], q[qi + 5], q[qi + 6]);
      m.p = {{q[qi], q[qi + 1], q[qi + 2]}};
      const M3 Rt = transpose(m.R);
      for (int k = 0; k < 3; ++k) {
        V3 e;
        e[k] = 1;
        m.S.push_back(Motion{e, zero});
      }
      for (int k = 0; k < 3; ++k) {
        V3 c;
        for (int r = 0; r < 3; ++r) c[r] = Rt(r, k);
        m.S.push_back(Motion{zero, c});
      }
      break;
    }
  }
  return m;
}

Equations::Impl Derivation::run() {
  make_coordinate_symbols();
  make_input_symbols();
  newton_euler();
  element_forces();
  constraint_equations();
  params_.check();
  split();
  if (newton_euler_) newton_euler_form();
  impl_.parameter_symbols = params_.symbols_;
  impl_.parameters = params_.values_;
  impl_.form_numbers = params_.form_numbers_;
  return std::move(impl_);
}

// q, v, v̇ of every coordinate: symbols, or the prescribing signal's.
void Derivation::make_coordinate_symbols() {
  const int nq = model_.nq(), nv = model_.nv();
  impl_.nq = nq;
  impl_.nv = nv;
  impl_.q.assign(nq, 0);
  impl_.v.assign(nv, 0);
  impl_.vdot.assign(nv, 0);
  impl_.q_names.assign(nq, "");
  impl_.v_names.assign(nv, "");
  impl_.a_names.assign(nv, "");
  impl_.free.clear();
  rates_.clear();
  for (const model::Joint& j : model_.joints()) {
    const std::string base = identifier(j.name);
    if (j.nq() == j.nv()) {
      for (int k = 0; k < j.nv(); ++k) {
        const int qi = j.q_index + k, vi = j.v_index + k;
        std::string name = base;
        if (j.nv() > 1) {
          const std::string& full = model_.q_name(qi);
          name = base + "_" + identifier(full.substr(full.find('.') + 1));
        }
        // A prescribed coordinate is its signal, a function of time; a commanded one (its signal
        // a controller's: model/controller.hpp) stays the joint's coordinate, its acceleration
        // the controller's output.
        const bool commanded =
            j.is_prescribed() && model_.is_driven(j.prescribed_signal_indices[k]);
        if (j.is_prescribed() && !commanded) {
          const model::Signal& s = model_.signals()[j.prescribed_signal_indices[k]];
          name = identifier(s.name());
        }
        params_.coordinate(name);
        const bool renamed = params_.given(name) != name;
        name = params_.given(name);
        if (greek_ && !renamed && j.type == model::JointType::revolute && !j.is_prescribed()) {
          angles_.push_back(name);
        }
        const symbol q(name, coordinate_latex(name, "")),
            v(name + "_dot", coordinate_latex(name, "\\dot")),
            a(name + "_ddot", coordinate_latex(name, "\\ddot"));
        set_coordinate(qi, vi, q, v, a, name);
        rates_.push_back({q, v});
        if (!j.is_prescribed()) impl_.free.push_back(vi);
      }
      continue;
    }
    // Ball and free joints: quaternion, body angular velocity (and position, its rate). A
    // prescribed one's are known functions of time (from its signals' rotation vector and
    // position): the same symbols, without an equation.
    const int quat = j.q_index + (j.type == model::JointType::free ? 3 : 0);
    const char* parts[] = {"qw", "qx", "qy", "qz"};
    std::array<symbol, 4> Q;
    for (int k = 0; k < 4; ++k) {
      const std::string name = base + "_" + parts[k];
      Q[static_cast<std::size_t>(k)] = symbol(name, latex_name(name));
      impl_.q[quat + k] = Q[static_cast<std::size_t>(k)];
      impl_.q_names[quat + k] = name;
    }
    std::array<ex, 3> w;
    const char* axes[] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
      const std::string name = base + "_w" + axes[k];
      const symbol s(name, "\\omega_{" + latex_name(base) + "," + axes[k] + "}");
      const symbol sd(name + "_dot", "\\dot\\omega_{" + latex_name(base) + "," + axes[k] + "}");
      const int vi = j.v_index + k;
      impl_.v[vi] = s;
      impl_.vdot[vi] = sd;
      impl_.v_names[vi] = name;
      impl_.a_names[vi] = name + "_dot";
      if (!j.is_prescribed()) impl_.free.push_back(vi);
      w[static_cast<std::size_t>(k)] = s;
    }
    // q̇ = ½ q ⊗ [0; ω].
    const ex qw = Q[0], qx = Q[1], qy = Q[2], qz = Q[3];
    rates_.push_back({Q[0], -(qx * w[0] + qy * w[1] + qz * w[2]) / 2});
    rates_.push_back({Q[1], (qw * w[0] + qy * w[2] - qz * w[1]) / 2});
    rates_.push_back({Q[2], (qw * w[1] + qz * w[0] - qx * w[2]) / 2});
    rates_.push_back({Q[3], (qw * w[2] + qx * w[1] - qy * w[0]) / 2});
    if (j.type == model::JointType::free) {
      for (int k = 0; k < 3; ++k) {
        params_.coordinate(base + "_" + axes[k]);
        const std::string name = params_.given(base + "_" + axes[k]);
        const symbol q(name, coordinate_latex(name, "")),
            v(name + "_dot", coordinate_latex(name, "\\dot")),
            a(name + "_ddot", coordinate_latex(name, "\\ddot"));
        set_coordinate(j.q_index + k, j.v_index + 3 + k, q, v, a, name);
        rates_.push_back({q, v});
        if (!j.is_prescribed()) impl_.free.push_back(j.v_index + 3 + k);
      }
    }
  }
  std::sort(impl_.free.begin(), impl_.free.end());
  greek_display();
}

// θ (θ₁, θ₂, …) for the angles collected in angles_ (EquationOptions::greek); an angle named
// by a Greek letter (the Euler angles phi, theta, psi) keeps its own: φ, θ, ψ.
void Derivation::greek_display() {
  static const char* const subscripts[] = {"₀", "₁", "₂", "₃", "₄", "₅", "₆", "₇", "₈", "₉"};
  static const std::map<std::string_view, const char*> own_letters = {
      {"alpha", "α"}, {"beta", "β"},  {"gamma", "γ"}, {"delta", "δ"}, {"phi", "φ"},
      {"psi", "ψ"},   {"theta", "θ"}, {"chi", "χ"},   {"eta", "η"},   {"xi", "ξ"}};
  std::vector<std::string> others;
  bool theta_taken = false;  // then the others are numbered θ₁, θ₂, … however many
  for (const std::string& name : angles_) {
    const auto own = own_letters.find(name);
    if (own == own_letters.end()) {
      others.push_back(name);
      continue;
    }
    theta_taken = theta_taken || name == "theta";
    const std::string letter = own->second, latex = "\\" + name;
    impl_.display[name] = {letter, latex};
    impl_.display[name + "_dot"] = {letter + "\u0307", "\\dot{" + latex + "}"};
    impl_.display[name + "_ddot"] = {letter + "\u0308", "\\ddot{" + latex + "}"};
  }
  const bool numbered = others.size() > 1 || theta_taken;
  for (std::size_t k = 0; k < others.size(); ++k) {
    std::string text_index, latex_index;
    if (numbered) {
      for (char digit : std::to_string(k + 1)) text_index += subscripts[digit - '0'];
      latex_index = "_{" + std::to_string(k + 1) + "}";
    }
    const std::string& name = others[k];
    impl_.display[name] = {"θ" + text_index, "\\theta" + latex_index};
    impl_.display[name + "_dot"] = {"θ\u0307" + text_index, "\\dot{\\theta}" + latex_index};
    impl_.display[name + "_ddot"] = {"θ\u0308" + text_index, "\\ddot{\\theta}" + latex_index};
  }
}

void Derivation::set_coordinate(int qi, int vi, const symbol& q, const symbol& v, const symbol& a,
                                const std::string& name) {
  impl_.q[qi] = q;
  impl_.v[vi] = v;
  impl_.vdot[vi] = a;
  impl_.q_names[qi] = name;
  impl_.v_names[vi] = name + "_dot";
  impl_.a_names[vi] = name + "_ddot";
}

// Signals that scale a load are inputs, symbols of their own names.
void Derivation::make_input_symbols() {
  impl_.inputs.clear();
  impl_.input_names.clear();
  input_of_signal_.assign(model_.signals().size(), ex(0));
  for (const model::ForceElement& e : model_.force_elements()) {
    int s = -1;
    if (const auto* f = std::get_if<model::AppliedForce>(&e)) s = f->signal_index;
    if (const auto* t = std::get_if<model::AppliedTorque>(&e)) s = t->signal_index;
    if (s < 0 || !input_of_signal_[static_cast<std::size_t>(s)].is_zero()) continue;
    const std::string name = identifier(model_.signals()[static_cast<std::size_t>(s)].name());
    const symbol u(name, latex_name(name));
    input_of_signal_[static_cast<std::size_t>(s)] = u;
    impl_.inputs.push_back(u);
    impl_.input_names.push_back(name);
  }
}

// d/dt of an expression of the coordinates: the chain rule with q̇ from the speeds.
ex Derivation::rate(const ex& e) const {
  ex d = 0;
  for (const auto& [q, q_dot] : rates_) d += GiNaC::diff(e, GiNaC::ex_to<symbol>(q)) * q_dot;
  return d;
}

Motion Derivation::rate(const Motion& m) const {
  Motion r;
  for (int k = 0; k < 3; ++k) {
    r.w[k] = rate(m.w[k]);
    r.v[k] = rate(m.v[k]);
  }
  return r;
}

// The body frames' poses, the joints' subspaces in the body frames and their rates, the
// inertias: what every Newton–Euler pass shares.
void Derivation::kinematics() {
  const int nb = model_.num_bodies();
  R_PC_.assign(nb, M3::identity());
  p_PC_.assign(nb, V3{});
  R_WB_.assign(nb, M3::identity());
  p_WB_.assign(nb, V3{});
  S_.assign(nb, {});
  dS_.assign(nb, {});
  p_CJ_.assign(nb, V3{});
  com_.assign(nb, V3{});
  I_com_.assign(nb, M3{});
  inertias_.assign(nb, Inertia{});
  for (const model::Joint& j : model_.joints()) {
    const int i = j.child_index, p = j.parent_index;
    const JointMotion jm = joint_motion(j, impl_.q, j.q_index);
    const M3 R_PJ = to_m3(j.X_PJ.R), R_CJ = to_m3(j.X_CJ.R);
    const V3 p_PJ = params_.vector("l_" + j.name, joint_source(SourceKind::joint_parent_offset, j),
                                   "L_" + j.name);
    const V3 p_CJ =
        params_.vector("l_" + j.name + "_child", joint_source(SourceKind::joint_child_offset, j),
                       "L_" + j.name + "_child");
    p_CJ_[i] = p_CJ;
    R_PC_[i] = R_PJ * jm.R * transpose(R_CJ);
    p_PC_[i] = p_PJ + R_PJ * jm.p - R_PC_[i] * p_CJ;
    R_WB_[i] = R_WB_[p] * R_PC_[i];
    p_WB_[i] = p_WB_[p] + R_WB_[p] * p_PC_[i];
    for (int k = 0; k < j.nv(); ++k) {
      const Motion S = motion_to_body(R_CJ, p_CJ, jm.S[static_cast<std::size_t>(k)]);
      S_[i].push_back(S);
      dS_[i].push_back(rate(S));
    }
    inertias_[i] = inertia(i);
  }
  const Vec3 gravity = model_.gravity();
  const double g_size = gravity.norm();
  const ex g = params_("g", {SourceKind::gravity}, "m/s²");
  if (g_size > 0) {
    base_acceleration_ = (-g) * to_v3(gravity / g_size);
    for (int k = 0; k < 3; ++k)
      params_.form_number("gravity's direction", {SourceKind::gravity_direction, 0, k});
  }
}

// One Newton–Euler pass: τ for the speeds `v` and accelerations `vdot` (expressions per model
// coordinate), with or without gravity; the body velocities into `velocities` when asked.
std::vector<ex> Derivation::newton_euler(const std::vector<ex>& v, const std::vector<ex>& vdot,
                                         bool gravity, std::vector<Motion>* velocities,
                                         std::vector<Motion>* accelerations) const {
  const int nb = model_.num_bodies();
  std::vector<Motion> V(nb), A(nb);
  std::vector<Force> f(nb);
  if (gravity) A[0].v = base_acceleration_;
  for (const model::Joint& j : model_.joints()) {
    const int i = j.child_index, p = j.parent_index;
    Motion vJ, cJ, aJ;
    for (int k = 0; k < j.nv(); ++k) {
      const Motion& S = S_[i][static_cast<std::size_t>(k)];
      const Motion& dS = dS_[i][static_cast<std::size_t>(k)];
      const ex& vk = v[static_cast<std::size_t>(j.v_index + k)];
      const ex& ak = vdot[static_cast<std::size_t>(j.v_index + k)];
      if (!vk.is_zero()) {
        vJ = vJ + Motion{vk * S.w, vk * S.v};
        cJ = cJ + Motion{vk * dS.w, vk * dS.v};
      }
      if (!ak.is_zero()) aJ = aJ + Motion{ak * S.w, ak * S.v};
    }
    V[i] = motion_to_child(R_PC_[i], p_PC_[i], V[p]) + vJ;
    A[i] = motion_to_child(R_PC_[i], p_PC_[i], A[p]) + aJ + cJ + cross_motion(V[i], vJ);
    const Inertia& I = inertias_[i];
    f[i] = I.apply(A[i]) + cross_force(V[i], I.apply(V[i]));
  }
  std::vector<ex> tau(static_cast<std::size_t>(model_.nv()), 0);
  project_down(f, tau);
  if (velocities) *velocities = std::move(V);
  if (accelerations) *accelerations = std::move(A);
  return tau;
}

// The passes: τ with the free accelerations zero (C v + g and the prescribed motion's terms),
// g at rest, and each column of M (a unit free acceleration, nothing else).
void Derivation::newton_euler() {
  kinematics();
  const std::size_t nv = static_cast<std::size_t>(model_.nv());
  std::vector<ex> vdot_prescribed = impl_.vdot;
  for (int vi : impl_.free) vdot_prescribed[static_cast<std::size_t>(vi)] = 0;
  tau_no_acceleration_ = newton_euler(impl_.v, vdot_prescribed, true, &V_);
  const std::vector<ex> zero(nv, ex(0));
  tau_gravity_ = newton_euler(zero, zero, true);
  mass_columns_.clear();
  for (int vi : impl_.free) {
    std::vector<ex> unit = zero;
    unit[static_cast<std::size_t>(vi)] = 1;
    mass_columns_.push_back(newton_euler(zero, unit, false));
  }
}

// τ_j = S_jᵀ f_i from the leaves to the root, f_p += ᵖX_i* f_i.
void Derivation::project_down(std::vector<Force>& f, std::vector<ex>& out) const {
  const auto& joints = model_.joints();
  for (auto it = joints.rbegin(); it != joints.rend(); ++it) {
    const int i = it->child_index, p = it->parent_index;
    for (int k = 0; k < it->nv(); ++k) {
      const Motion& S = S_[i][static_cast<std::size_t>(k)];
      out[it->v_index + k] += dot(S.w, f[i].n) + dot(S.v, f[i].f);
    }
    if (p > 0) f[p] = f[p] + force_to_parent(R_PC_[i], p_PC_[i], f[i]);
  }
}

Inertia Derivation::inertia(int b) {
  const model::Body& body = model_.body(b);
  const inertia::MassProperties& mp = body.mass_properties;
  const ex m = params_("m_" + body.name, {SourceKind::body_mass, b}, "kg");
  // Round-off in the mass properties (a composed part's products of inertia of 1e-20 against
  // moments of 1e-2) is 0, as the command line shows it (common/number_text.hpp): not a
  // coefficient, nor with --all-symbols a parameter, of the equations (model::parameter_value).
  const V3 c =
      params_.vector("c_" + body.name, {SourceKind::body_center_of_mass, b}, "L_" + body.name);
  const char* axes = "xyz";
  const auto moment_name = [&](int r, int col) {
    return fmt::format("I_{}_{}{}", body.name, axes[r], axes[col]);
  };
  bool moments_asked = false;
  for (int r = 0; r < 3; ++r)
    for (int col = r; col < 3; ++col)
      moments_asked = moments_asked || params_.asked(moment_name(r, col));
  // A uniform solid's inertia, unless its moments are asked for as symbols themselves: m × its
  // tensor per unit mass when its mass is a symbol (a rod's I_G = m L²/12), and in its
  // dimensions when those are symbols too (shape_inertia).
  M3 I;
  const std::optional<M3> in_dimensions = shape_inertia(b, m, moments_asked);
  for (int r = 0; r < 3; ++r) {
    for (int col = r; col < 3; ++col) {
      const std::string name = moment_name(r, col);
      const model::ParameterSource source{SourceKind::body_inertia, b, r, col};
      ex e;
      if (in_dimensions) {
        params_.known(name);
        e = (*in_dimensions)(r, col);
      } else if (!moments_asked && body.inertia_scales_with_mass &&
                 !GiNaC::is_a<GiNaC::numeric>(m)) {
        params_.known(name);
        e = m * exact_number(model::parameter_value(model_, source) / mp.mass());
      } else {
        e = params_(name, source, "kg·m²");
      }
      I(r, col) = e;
      I(col, r) = e;
    }
  }
  com_[b] = c;
  I_com_[b] = I;
  Inertia out;
  out.mass = m;
  out.h = m * c;
  const ex cc = dot(c, c);
  for (int r = 0; r < 3; ++r)
    for (int col = 0; col < 3; ++col)
      out.I_o(r, col) = I(r, col) + m * ((r == col ? cc : ex(0)) - c[r] * c[col]);
  return out;
}

// A body that is one standard shape, with a dimension of it asked for as a symbol (its
// `<size>_<body>`: length_rod, radius_wheel, size_x_block): its inertia about the centre of mass,
// R_BS (m × its unit moments in those dimensions) R_BSᵀ. Its other dimensions are numbers.
// Nothing when no dimension is asked for, or its moments are (every parameter is, with
// --all-symbols, which keeps the body's moments as the symbols I_*).
std::optional<M3> Derivation::shape_inertia(int b, const ex& m, bool moments_asked) {
  const model::Body& body = model_.body(b);
  if (!body.shape) return std::nullopt;
  const inertia::PrimitiveShape& shape = *body.shape;
  const auto size_name = [&](const std::string& key) { return key + "_" + body.name; };
  bool asked = false;
  for (const auto& [key, value] : shape.sizes) {
    params_.known(size_name(key));
    asked = asked || params_.asked(size_name(key));
  }
  if (!asked || moments_asked) return std::nullopt;
  const auto size = [&](std::string_view key) -> ex {
    for (std::size_t k = 0; k < shape.sizes.size(); ++k) {
      if (shape.sizes[k].first == key) {
        return params_(size_name(shape.sizes[k].first),
                       {SourceKind::body_shape_size, b, static_cast<int>(k)}, "m");
      }
    }
    throw InvalidArgument(
        fmt::format("equations: body '{}' ({}) has no size '{}'", body.name, shape.kind, key));
  };
  const auto unit = inertia::unit_moments_of<ex>(shape.kind, size);
  if (!unit) return std::nullopt;
  const ex moments[3] = {unit->xx, unit->yy, unit->zz};
  M3 I;
  for (int r = 0; r < 3; ++r) {
    for (int col = r; col < 3; ++col) {
      ex e = 0;
      for (int k = 0; k < 3; ++k) {
        const double rr = shape.R_BS(r, k) * shape.R_BS(col, k);
        if (std::abs(rr) > 1e-15) e += exact_number(rr) * moments[k];
      }
      I(r, col) = m * e;
      I(col, r) = I(r, col);
    }
  }
  return I;
}

// Q: the elements' wrenches projected on the speeds, and the joint-space terms.
void Derivation::element_forces() {
  const int nb = model_.num_bodies();
  std::vector<Force> f(nb);
  Q_.assign(model_.nv(), 0);
  const auto world_point = [&](int b, const V3& p) { return p_WB_[b] + R_WB_[b] * p; };
  const auto world_velocity = [&](int b, const V3& p) {
    return R_WB_[b] * (V_[b].v + cross(V_[b].w, p));
  };
  // A force F (in W) at p (in B) on body b.
  const auto push = [&](int b, const V3& p, const V3& F_W) {
    if (b == 0) return;
    const V3 F = transpose(R_WB_[b]) * F_W;
    f[b] = f[b] + Force{cross(p, F), F};
  };
  armature_.assign(model_.nv(), 0);
  for (const model::Joint& j : model_.joints()) {
    const ex c = params_("c_" + j.name, joint_source(SourceKind::joint_damping, j),
                         model::joint_damping_unit(model_, j));
    for (int k = 0; k < j.nv(); ++k) Q_[j.v_index + k] -= c * impl_.v[j.v_index + k];
    if (j.armature == 0.0) continue;
    // A rotor's reflected inertia.
    const ex armature = params_("Ia_" + j.name, joint_source(SourceKind::joint_armature, j),
                                model::joint_armature_unit(model_, j));
    for (int k = 0; k < j.nv(); ++k) armature_[j.v_index + k] = armature;
  }
  int e = -1;  // the element's index (its parameters' sources)
  for (const model::ForceElement& element : model_.force_elements()) {
    ++e;
    const std::string name = model::force_element_name(element);
    if (const auto* s = std::get_if<model::LinearSpringDamper>(&element)) {
      const ex k = params_("k_" + name, {SourceKind::element_stiffness, e}, "N/m"),
               c = params_("c_" + name, {SourceKind::element_damping, e}, "N·s/m");
      const int a = s->a.body_index, b = s->b.body_index;
      const V3 pa = to_v3(s->a.p_BoP_B), pb = to_v3(s->b.p_BoP_B);
      const V3 d = world_point(b, pb) - world_point(a, pa);
      Line line;
      const ex length = line_length(d, &line);
      const ex length_rate = dot(d, world_velocity(b, pb) - world_velocity(a, pa)) / length;
      const ex T = k * stretch(name, e, length, line) + c * length_rate;
      push(b, pb, (-T / length) * d);
      push(a, pa, (T / length) * d);
    } else if (const auto* t = std::get_if<model::TorsionalSpringDamper>(&element);
               t && t->joint_index < 0) {
      add_two_body_torsion(*t, e, f);
    } else if (t) {
      const model::Joint& j = model_.joint(t->joint_index);
      const ex k = params_("k_" + name, {SourceKind::element_stiffness, e}, "N·m/rad"),
               c = params_("c_" + name, {SourceKind::element_damping, e}, "N·m·s/rad"),
               rest = params_("rest_" + name, {SourceKind::element_rest, e}, "rad");
      Q_[j.v_index] -= k * (impl_.q[j.q_index] - rest) + c * impl_.v[j.v_index];
    } else if (const auto* tendon = std::get_if<model::FixedTendon>(&element)) {
      add_tendon(*tendon, e);
    } else if (const auto* fr = std::get_if<model::JointFriction>(&element)) {
      const model::Joint& j = model_.joint(fr->joint_index);
      const ex c = params_("c_" + name, {SourceKind::element_viscous, e},
                           model::joint_damping_unit(model_, j));
      for (int k = 0; k < j.nv(); ++k) Q_[j.v_index + k] -= c * impl_.v[j.v_index + k];
    } else if (const auto* F = std::get_if<model::AppliedForce>(&element)) {
      const V3 F_W = load(name, e, F->vector, F->signal_index, F->frame, F->at.body_index, "N");
      push(F->at.body_index, to_v3(F->at.p_BoP_B), F_W);
    } else if (const auto* T = std::get_if<model::AppliedTorque>(&element)) {
      const V3 M_W = load(name, e, T->vector, T->signal_index, T->frame, T->body_index, "N·m");
      if (T->body_index > 0) {
        f[T->body_index] = f[T->body_index] + Force{transpose(R_WB_[T->body_index]) * M_W, V3{}};
      }
    }
  }
  body_loads_ = f;
  joint_space_ = Q_;
  project_down(f, Q_);
}

// A fixed tendon: L = offset + Σ nᵢ qᵢ, T = k (L − rest) + c L̇, τᵢ = −nᵢ T on its joints.
void Derivation::add_tendon(const model::FixedTendon& tendon, int e) {
  const std::string& name = tendon.name;
  const model::TendonUnits units = model::tendon_units(model_, tendon);
  const ex k = params_("k_" + name, {SourceKind::element_stiffness, e}, units.stiffness),
           c = params_("c_" + name, {SourceKind::element_damping, e}, units.damping),
           rest = params_("rest_" + name, {SourceKind::element_rest, e}, units.length),
           offset = params_("offset_" + name, {SourceKind::element_offset, e}, units.length);
  std::vector<ex> n;
  ex length = offset, rate = 0;
  int term_index = 0;
  for (const model::TendonTerm& term : tendon.terms) {
    const model::Joint& j = model_.joint(term.joint_index);
    n.push_back(
        params_("n_" + name + "_" + j.name, {SourceKind::element_coefficient, e, term_index++}));
    length += n.back() * impl_.q[j.q_index];
    rate += n.back() * impl_.v[j.v_index];
  }
  const ex tension = k * (length - rest) + c * rate;
  for (std::size_t i = 0; i < tendon.terms.size(); ++i) {
    Q_[model_.joint(tendon.terms[i].joint_index).v_index] -= n[i] * tension;
  }
}

// A torsional spring between two bodies whose relative rotation turns about one axis n: every
// joint on the tree path between them is revolute about an axis parallel to n, or does not
// turn (fixed, prismatic). Its angle from the rest orientation is φ = Σ ±(q_j − q_j0) (+ on the
// way down to b, − down to a) and it puts the moment −(k φ + c φ̇) n on b and the opposite on
// a, n being fixed in both. Other paths (a ball joint between them, two axes) are refused.
void Derivation::add_two_body_torsion(const model::TorsionalSpringDamper& t, int e,
                                      std::vector<Force>& f) {
  const std::string& name = t.name;
  // Every body's orientation at the initial configuration, numerically.
  const VecX q0 = model_.initial_q();
  std::vector<Mat3> R_W(static_cast<std::size_t>(model_.num_bodies()), Mat3::Identity());
  for (const model::Joint& j : model_.joints()) {
    const Transform X_JJc = model::joint_transform(j, q0.data() + j.q_index);
    R_W[static_cast<std::size_t>(j.child_index)] =
        R_W[static_cast<std::size_t>(j.parent_index)] * j.X_PJ.R * X_JJc.R * j.X_CJ.R.transpose();
  }
  // The joints from each body up to the first body both reach.
  const auto ancestors = [&](int body) {
    std::vector<int> chain = {body};
    while (body != 0) chain.push_back(body = model_.body(body).parent_index);
    return chain;
  };
  const std::vector<int> from_a = ancestors(t.body_a_index), from_b = ancestors(t.body_b_index);
  int common = 0;
  for (const int body : from_a) {
    if (std::find(from_b.begin(), from_b.end(), body) != from_b.end()) {
      common = body;
      break;
    }
  }
  std::optional<Vec3> axis;  // n in W at the initial configuration
  ex phi = 0, phi_rate = 0;
  const auto walk = [&](const std::vector<int>& chain, int sign) {
    for (const int body : chain) {
      if (body == common) return;
      const model::Joint& j = model_.joint(model_.body(body).joint_index);
      if (j.type == model::JointType::fixed || j.type == model::JointType::prismatic) continue;
      if (j.type != model::JointType::revolute) {
        throw InvalidArgument(fmt::format(
            "equations: force element '{}': a torsional spring across the {} joint '{}' is not "
            "written yet (only revolute joints about one axis between its bodies)",
            name, model::joint_type_name(j.type), j.name));
      }
      const Vec3 n_W = R_W[static_cast<std::size_t>(j.parent_index)] * j.X_PJ.R * j.axis;
      if (!axis) axis = n_W;
      if (n_W.cross(*axis).norm() > 1e-9) {
        throw InvalidArgument(fmt::format(
            "equations: force element '{}': its bodies turn about more than one axis relative "
            "to each other (joint '{}'); not written yet",
            name, j.name));
      }
      const int s = sign * (n_W.dot(*axis) > 0 ? 1 : -1);
      phi += s * (impl_.q[static_cast<std::size_t>(j.q_index)] - exact_number(q0[j.q_index]));
      phi_rate += s * impl_.v[static_cast<std::size_t>(j.v_index)];
    }
  };
  walk(from_b, +1);
  walk(from_a, -1);
  if (!axis) return;  // nothing turns between them: the spring stays relaxed
  const ex k = params_("k_" + name, {SourceKind::element_stiffness, e}, "N·m/rad"),
           c = params_("c_" + name, {SourceKind::element_damping, e}, "N·m·s/rad");
  const ex moment = k * phi + c * phi_rate;
  const auto push_moment = [&](int body, double sign) {
    if (body == 0) return;
    const V3 n = to_v3(R_W[static_cast<std::size_t>(body)].transpose() * *axis);
    f[body] = f[body] + Force{(ex(sign) * moment) * n, V3{}};
  };
  push_moment(t.body_b_index, -1.0);
  push_moment(t.body_a_index, +1.0);
}

// A spring's stretch, length − l0. Along a line (line_length) the length is the joints'
// offsets plus the coordinates; its value at q = 0 (inputs at 0 too) is the offsets' part. A
// textbook writes the spring relaxed there, k (x − y): where l0 is that value, offsets and free
// length cancel and are left out; where not, their difference, the stretch at q = 0, is the
// parameter d0_<spring> (m). Off a line, √(d·d) − l0 as it is.
ex Derivation::stretch(const std::string& name, int element, const ex& length, const Line& line) {
  if (line.axis < 0)
    return length - params_("l0_" + name, {SourceKind::element_free_length, element}, "m");
  GiNaC::exmap zero;
  for (const ex& q : impl_.q) zero[q] = 0;
  const ex at_zero = GiNaC::expand(length.subs(zero));
  params_.known("l0_" + name);
  const model::ParameterSource d0{
      SourceKind::element_stretch_at_zero, element, line.axis, 0, false, line.sign};
  return GiNaC::expand(length - at_zero) + params_("d0_" + name, d0, "m");
}

// |d|. Where the line keeps one direction (d has one nonzero component, as a suspension's
// vertical spring) it is ±d_k with the sign d_k has at the initial configuration — a spring
// that does not pass through zero length, as a textbook writes k (x_b − x_a) — else √(d·d).
// `line`, when given, says which.
ex Derivation::line_length(const V3& d, Line* line) {
  int nonzero = -1, count = 0;
  for (int k = 0; k < 3; ++k) {
    if (!GiNaC::expand(d[k]).is_zero()) {
      nonzero = k;
      ++count;
    }
  }
  if (count != 1) return GiNaC::sqrt(dot(d, d));
  const ex component = GiNaC::expand(d[nonzero]);
  const double at_start = initial_value(component);
  if (at_start == 0.0) return GiNaC::sqrt(dot(d, d));
  if (line != nullptr) *line = {nonzero, at_start > 0 ? 1 : -1};
  return at_start > 0 ? component : -component;
}

// An expression's value at the model's initial configuration, parameters at their values.
double Derivation::initial_value(const ex& e) const {
  GiNaC::exmap numbers;
  const VecX q0 = model_.initial_q();
  for (int i = 0; i < model_.nq(); ++i) {
    if (GiNaC::is_a<symbol>(impl_.q[i])) numbers[impl_.q[i]] = GiNaC::numeric(q0[i]);
  }
  for (const model::Joint& j : model_.joints()) {
    for (int k = 0; k < static_cast<int>(j.prescribed_signal_indices.size()); ++k) {
      if (model_.is_driven(j.prescribed_signal_indices[static_cast<std::size_t>(k)])) continue;
      const double u = model_
                           .signals()[static_cast<std::size_t>(
                               j.prescribed_signal_indices[static_cast<std::size_t>(k)])]
                           .value(0.0);
      numbers[impl_.q[j.q_index + k]] = GiNaC::numeric(u);
    }
  }
  for (std::size_t k = 0; k < params_.symbols_.size(); ++k)
    numbers[params_.symbols_[k]] = GiNaC::numeric(params_.values_[k].value);
  const ex x = GiNaC::evalf(e.subs(numbers));
  return GiNaC::is_a<GiNaC::numeric>(x) ? GiNaC::ex_to<GiNaC::numeric>(x).to_double() : 0.0;
}

// An applied load's vector in W: size (a parameter F_<name>) × direction × signal.
V3 Derivation::load(const std::string& name, int e, const Vec3& vector, int signal,
                    model::LoadFrame frame, int body, std::string_view unit) {
  const double size = vector.norm();
  // A signal's unit direction (N per unit of u, of length 1) is no parameter of the physics:
  // the force is u along it. A gain of another size, or a constant load, is one.
  ex magnitude = 1;
  if (signal >= 0 && size == 1.0) {
    params_.form_number("F_" + name, {SourceKind::element_load, e});
  } else {
    magnitude = params_("F_" + name, {SourceKind::element_load, e}, unit);
  }
  if (size > 0)
    for (int k = 0; k < 3; ++k)
      params_.form_number(name + "'s direction", {SourceKind::element_load_direction, e, k});
  V3 v = size > 0 ? magnitude * to_v3(vector / size) : V3{};
  if (signal >= 0) v = input_of_signal_[static_cast<std::size_t>(signal)] * v;
  if (frame == model::LoadFrame::body) v = R_WB_[body] * v;
  return v;
}

// The constraints' rows (constraint_rows.hpp): φ(q) on holonomic rows, G (jacobian_row),
// k = Ġ v as the rate of G v at v̇ = 0, and a multiplier λ per row, whose forces join the
// Newton–Euler form's loads (add_row_loads).
void Derivation::constraint_equations() {
  const auto rows =
      constraint_rows(model_, R_WB_, p_WB_, impl_.q,
                      [this](const std::string& name, const model::ParameterSource& source) {
                        // Frame origins, lengths and radii are lengths; a coupler's ratio and
                        // offset are not.
                        const bool length = name.rfind("p_", 0) == 0 || name.rfind("L_", 0) == 0 ||
                                            name.rfind("r_", 0) == 0;
                        return params_(name, source, length ? "m" : "");
                      });
  const std::vector<Motion> S_W = world_subspaces();
  constraint_loads_.assign(model_.num_bodies(), Force{});
  constraint_joint_forces_.assign(static_cast<std::size_t>(model_.nv()), 0);
  for (const SymbolicRow& row : rows) {
    Equations::Impl::ConstraintRow out;
    out.name = row.name;
    out.holonomic = row.holonomic;
    out.position = tidy_if_small(row.position);
    out.multiplier =
        symbol("lambda_" + identifier(row.name), "\\lambda_{" + latex_name(row.name) + "}");
    out.G = jacobian_row(row, S_W);
    ex Gv = 0;
    for (std::size_t vi = 0; vi < out.G.size(); ++vi) Gv += out.G[vi] * impl_.v[vi];
    out.bias = tidy_if_small(rate(Gv));
    add_row_loads(row, out.multiplier);
    impl_.constraints.push_back(std::move(out));
  }
}

// Every motion-subspace column in W about Wo: [R s_w; R s_v + p × R s_w], per model speed.
std::vector<Motion> Derivation::world_subspaces() const {
  std::vector<Motion> S_W(static_cast<std::size_t>(model_.nv()));
  for (const model::Joint& j : model_.joints()) {
    const int i = j.child_index;
    for (int k = 0; k < j.nv(); ++k) {
      const Motion& S = S_[i][static_cast<std::size_t>(k)];
      const V3 w = R_WB_[i] * S.w;
      S_W[static_cast<std::size_t>(j.v_index + k)] = {w, R_WB_[i] * S.v + cross(p_WB_[i], w)};
    }
  }
  return S_W;
}

// A row of G over every model speed: a wrench row's G_j = w·S_j over the joints that support
// body b, minus those supporting a (as dynamics::constraint_equations assembles it); a
// coupler's as written.
std::vector<ex> Derivation::jacobian_row(const SymbolicRow& row,
                                         const std::vector<Motion>& S_W) const {
  std::vector<ex> G(S_W.size(), ex(0));
  for (const auto& [vi, coefficient] : row.joint_row)
    G[static_cast<std::size_t>(vi)] += coefficient;
  const auto add_support = [&](int body, int sign) {
    for (; body > 0; body = model_.body(body).parent_index) {
      const model::Joint& j = model_.joint(model_.body(body).joint_index);
      for (int k = 0; k < j.nv(); ++k) {
        const auto vi = static_cast<std::size_t>(j.v_index + k);
        G[vi] += sign * (dot(row.moment, S_W[vi].w) + dot(row.force, S_W[vi].v));
      }
    }
  };
  if (row.joint_row.empty()) {
    add_support(row.body_b, +1);
    add_support(row.body_a, -1);
  }
  for (ex& entry : G) entry = tidy_if_small(entry);
  return G;
}

// The row's force with multiplier λ: λ w on body b and −λ w on a, in B about Bo; a coupler's
// λ G on its joints' generalized forces.
void Derivation::add_row_loads(const SymbolicRow& row, const symbol& lambda) {
  for (const auto& [vi, coefficient] : row.joint_row)
    constraint_joint_forces_[static_cast<std::size_t>(vi)] += coefficient * lambda;
  if (!row.joint_row.empty()) return;
  const auto push = [&](int body, int sign) {
    if (body == 0) return;
    const M3 Rt = transpose(R_WB_[body]);
    const ex scale = sign * lambda;
    const V3 f = scale * row.force, n = scale * (row.moment - cross(p_WB_[body], row.force));
    constraint_loads_[body] = constraint_loads_[body] + Force{Rt * n, Rt * f};
  };
  push(row.body_b, +1);
  push(row.body_a, -1);
}

// M, g, the rest and Q of each free speed; tidied where small enough to expand (a general 3-D
// tree's entries multiply out into more terms than any reader wants, and than time allows: they
// are kept as the recursion built them, exact all the same).
void Derivation::split() {
  const auto& free = impl_.free;
  const int n = static_cast<int>(free.size());
  impl_.M = GiNaC::matrix(static_cast<unsigned>(n), static_cast<unsigned>(n));
  impl_.rest.clear();
  impl_.g.clear();
  impl_.Q.clear();
  for (int r = 0; r < n; ++r) {
    const auto row = static_cast<std::size_t>(free[r]);
    for (int c = 0; c < n; ++c) {
      impl_.M(static_cast<unsigned>(r), static_cast<unsigned>(c)) =
          tidy_if_small(mass_columns_[static_cast<std::size_t>(c)][row]);
    }
    // The rotor's reflected inertia (a joint's armature) on the coordinate's own diagonal entry.
    if (const ex& armature = armature_[row]; !armature.is_zero()) {
      impl_.M(static_cast<unsigned>(r), static_cast<unsigned>(r)) += armature;
    }
    const ex g = tidy_if_small(tau_gravity_[row]);
    impl_.g.push_back(g);
    impl_.rest.push_back(tidy_if_small(tau_no_acceleration_[row] - tau_gravity_[row]));
    impl_.Q.push_back(tidy_if_small(Q_[row]));
  }
}

}  // namespace momenta::symbolic::detail
