// The Newton–Euler form of the equations, body by body (equations.hpp): ΣF = m a_G and
// ΣM_G = Ī α + ω × Ī ω with the joints' reactions as unknowns, in each body's axes or its
// principal axes, and for a planar body on a fixed pivot in n–t components.

#include "derivation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include "equations_impl.hpp"
#include "expression_algebra.hpp"

namespace momenta::symbolic::detail {

// Per body, Newton's and Euler's equations in its own axes with the joint reactions as
// unknowns (symbols R_<joint>_x … for the force on the child, N_<joint>_x … for the moment
// about J'o, both in the child's axes): ΣF = m a_G, ΣM_G = Ī α + ω × Ī ω; then each free
// joint's reaction along its motion equals its elements' generalized force.
void Derivation::newton_euler_form() {
  std::vector<Motion> V, A;
  newton_euler(impl_.v, impl_.vdot, false, &V, &A);
  const int nb = model_.num_bodies();
  std::vector<V3> R(nb), N(nb);  // per child body: its joint's reaction
  for (const model::Joint& j : model_.joints()) {
    const int i = j.child_index;
    const char* axes = "xyz";
    for (int k = 0; k < 3; ++k) {
      const symbol r(fmt::format("R_{}_{}", identifier(j.name), axes[k]),
                     fmt::format("R_{{{},{}}}", latex_name(j.name), axes[k]));
      const symbol n(fmt::format("N_{}_{}", identifier(j.name), axes[k]),
                     fmt::format("N_{{{},{}}}", latex_name(j.name), axes[k]));
      R[i][k] = r;
      N[i][k] = n;
      impl_.reaction_symbols.push_back(r);
    }
    for (int k = 0; k < 3; ++k) impl_.reaction_symbols.push_back(GiNaC::ex_to<symbol>(N[i][k]));
  }
  for (const auto& row : impl_.constraints) impl_.reaction_symbols.push_back(row.multiplier);
  // Planar: every body's rows out of the plane of motion read 0 = 0 once the reactions out of
  // it are 0 — then only the three in the plane are written (and those reactions left out).
  const std::vector<int> normals = plane_normals();
  std::vector<BodyBalance> balance = balances(V, A, R, N, normals);
  const bool is_planar =
      !normals.empty() && std::all_of(balance.begin(), balance.end(), [](const BodyBalance& b) {
        return b.out_of_plane_balanced();
      });
  if (!normals.empty() && !is_planar) balance = balances(V, A, R, N, {});  // a 3-D motion after all
  impl_.newton_euler_planar = is_planar;
  for (const BodyBalance& b : balance) add_body_rows(b, is_planar);
}

// Per body, the axis of its frame along its joint's rotation when every joint is revolute (or
// planar) about an axis of its child's frame; empty otherwise (then not planar).
std::vector<int> Derivation::plane_normals() const {
  if (principal_axes_) return {};
  std::vector<int> normals(static_cast<std::size_t>(model_.num_bodies()), -1);
  for (const model::Joint& j : model_.joints()) {
    Vec3 axis;
    if (j.type == model::JointType::revolute) {
      axis = j.X_CJ.R * j.axis;
    } else if (j.type == model::JointType::planar) {
      axis = j.X_CJ.R * Vec3::UnitZ();
    } else {
      return {};
    }
    int k = 0;
    axis.cwiseAbs().maxCoeff(&k);
    if (std::abs(std::abs(axis[k]) - 1.0) > 1e-12) return {};
    normals[static_cast<std::size_t>(j.child_index)] = k;
  }
  return normals;
}

// Every body's balance; with `normals`, the reactions out of each plane of motion set to 0.
std::vector<Derivation::BodyBalance> Derivation::balances(const std::vector<Motion>& V,
                                                          const std::vector<Motion>& A,
                                                          std::vector<V3> R, std::vector<V3> N,
                                                          const std::vector<int>& normals) const {
  for (const model::Joint& j : model_.joints()) {
    if (normals.empty()) break;
    const int i = j.child_index, k = normals[static_cast<std::size_t>(i)];
    R[i][k] = 0;
    N[i][(k + 1) % 3] = 0;
    N[i][(k + 2) % 3] = 0;
  }
  const V3 gravity_W = ex(-1) * base_acceleration_;
  std::vector<BodyBalance> out;
  for (const model::Joint& j : model_.joints()) {
    const int i = j.child_index;
    BodyBalance b;
    b.body = i;
    b.joint = &j;
    b.R = R[i];
    b.N = N[i];
    b.normal = normals.empty() ? -1 : normals[static_cast<std::size_t>(i)];
    const Inertia& I = inertias_[i];
    const V3& c = com_[i];
    b.c = c;
    b.w = V[i].w;
    b.alpha = A[i].w;
    // Loads: weight, own joint, the joints it carries (reversed), the elements.
    V3 F = I.mass * (transpose(R_WB_[i]) * gravity_W) + R[i];
    V3 M = N[i] + cross(p_CJ_[i] - c, R[i]);
    for (const model::Joint& child : model_.joints()) {
      if (child.parent_index != i) continue;
      const int k = child.child_index;
      const V3 Rk = R_PC_[k] * R[k];
      F = F - Rk;
      M = M - (R_PC_[k] * N[k]) - cross(p_PC_[k] + R_PC_[k] * p_CJ_[k] - c, Rk);
    }
    const Force loads = body_loads_[i] + constraint_loads_[i];
    b.F = F + loads.f;
    b.M = M + loads.n - cross(c, loads.f);
    // Kinetics: a_G = a_Bo + α × c + ω × (ω × c), a_Bo = A.v + ω × V.v (Featherstone's
    // spatial acceleration to the classical one).
    const V3 a_G = A[i].v + cross(b.w, V[i].v) + cross(b.alpha, c) + cross(b.w, cross(b.w, c));
    b.ma = I.mass * a_G;
    b.H_dot = I_com_[i] * b.alpha + cross(b.w, I_com_[i] * b.w);
    out.push_back(std::move(b));
  }
  return out;
}

// A body's rows (its axes, its principal axes, or — planar — the three in its plane, with the
// n–t components of a_G on a fixed pivot when asked), then its joint's along its motion.
void Derivation::add_body_rows(const BodyBalance& b, bool planar) {
  const model::Joint& j = *b.joint;
  const int i = b.body;
  std::string body = model_.body(i).name;
  const char* axes = "xyz";
  const std::optional<PrincipalAxes> principal =
      principal_axes_ ? principal_axes_of(i) : std::nullopt;
  if (principal) {
    // Every vector in the principal axes P: F_P = R_BPᵀ F, and Euler's equations with
    // Ī_P diagonal: I1 α1 − (I2 − I3) ω2 ω3 = M1 and the two like it.
    const M3 R_PB = transpose(principal->R_BP);
    const V3 w_P = R_PB * b.w, alpha_P = R_PB * b.alpha;
    const V3 H_dot = principal->I * alpha_P + cross(w_P, principal->I * w_P);
    const V3 F = R_PB * b.F, M = R_PB * b.M, ma_P = R_PB * b.ma;
    body += principal->description;
    for (int k = 0; k < 3; ++k)
      add_newton_euler_row(body, fmt::format("ΣF_{} = m a_G{}", k + 1, k + 1), F[k], ma_P[k]);
    for (int k = 0; k < 3; ++k) {
      add_newton_euler_row(body, fmt::format("ΣM_G{} = (Ī α + ω × Ī ω)_{}", k + 1, k + 1), M[k],
                           H_dot[k]);
    }
  } else if (planar) {
    const int n = b.normal;
    const bool pivot = normal_tangential_ && j.parent_index == 0;
    if (!(pivot && add_normal_tangential_rows(b, body))) {
      for (int k = 0; k < 3; ++k) {
        if (k == n) continue;
        add_newton_euler_row(body, fmt::format("ΣF_{} = m a_G{}", axes[k], axes[k]), b.F[k],
                             b.ma[k]);
      }
    }
    add_newton_euler_row(body, fmt::format("ΣM_G{} = Ī α_{}", axes[n], axes[n]), b.M[n],
                         b.H_dot[n]);
  } else {
    for (int k = 0; k < 3; ++k)
      add_newton_euler_row(body, fmt::format("ΣF_{} = m a_G{}", axes[k], axes[k]), b.F[k], b.ma[k]);
    for (int k = 0; k < 3; ++k) {
      add_newton_euler_row(body, fmt::format("ΣM_G{} = (Ī α + ω × Ī ω)_{}", axes[k], axes[k]),
                           b.M[k], b.H_dot[k]);
    }
  }
  // Along the free motions: the reaction's generalized force is the elements', less what
  // accelerates the joint's rotor (armature · v̇), which the bodies do not feel.
  if (j.is_prescribed()) return;
  const V3 n_o = b.N + cross(p_CJ_[i], b.R);
  for (int k = 0; k < j.nv(); ++k) {
    const Motion& Sk = S_[i][static_cast<std::size_t>(k)];
    add_newton_euler_row(
        fmt::format("joint {}", j.name),
        fmt::format("along {}", impl_.v_names[static_cast<std::size_t>(j.v_index + k)]),
        dot(Sk.w, n_o) + dot(Sk.v, b.R),
        joint_space_[static_cast<std::size_t>(j.v_index + k)] +
            constraint_joint_forces_[static_cast<std::size_t>(j.v_index + k)] -
            armature_[static_cast<std::size_t>(j.v_index + k)] *
                impl_.vdot[static_cast<std::size_t>(j.v_index + k)]);
  }
}

// A body on a fixed pivot O, in its plane: ΣF_n = m r̄ ω² (n from G towards O) and
// ΣF_t = m r̄ α (t along the motion of G), r̄ = |OG| (Beer & Johnston §16.8). False when G is
// on the axis (no n–t directions).
bool Derivation::add_normal_tangential_rows(const BodyBalance& b, std::string& body) {
  const V3 r = b.c - p_CJ_[b.body];  // from O to G, in B
  V3 in_plane = r;
  in_plane[b.normal] = 0;
  const ex r_bar = line_length(in_plane);
  if (GiNaC::expand(r_bar).is_zero()) return false;
  V3 axis;  // the pivot's axis in B: a positive angle turns G along t
  axis[b.normal] = (b.joint->X_CJ.R * b.joint->axis)[b.normal] > 0 ? 1 : -1;
  const V3 n = (ex(-1) / r_bar) * in_plane, t = (ex(1) / r_bar) * cross(axis, in_plane);
  body += " (n from G towards the pivot, t along G's motion, r̄ = |OG|)";
  add_newton_euler_row(body, "ΣF_n = m a_Gn = m r̄ ω²", dot(b.F, n), dot(b.ma, n));
  add_newton_euler_row(body, "ΣF_t = m a_Gt = m r̄ α", dot(b.F, t), dot(b.ma, t));
  return true;
}

std::optional<Derivation::PrincipalAxes> Derivation::principal_axes_of(int b) const {
  const Mat3& Ic = model_.body(b).mass_properties.inertia_about_com();
  const Mat3 off = Ic - Mat3(Ic.diagonal().asDiagonal());
  if (off.cwiseAbs().maxCoeff() <= 1e-12 * Ic.cwiseAbs().maxCoeff()) return std::nullopt;
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(Ic);
  Mat3 R = eigen.eigenvectors();
  if (R.determinant() < 0) R.col(2) = -R.col(2);
  PrincipalAxes p;
  p.R_BP = to_m3(R);
  bool numbers = true;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) numbers = numbers && GiNaC::is_a<GiNaC::numeric>(I_com_[b](r, c));
  if (numbers) {
    for (int k = 0; k < 3; ++k) p.I(k, k) = exact_number(eigen.eigenvalues()[k]);
  } else {
    p.I = transpose(p.R_BP) * I_com_[b] * p.R_BP;
  }
  const auto column = [&](int k) {
    return fmt::format("[{:.6g}, {:.6g}, {:.6g}]", R(0, k), R(1, k), R(2, k));
  };
  p.description = fmt::format(" (principal axes e1 = {}, e2 = {}, e3 = {} in B)", column(0),
                              column(1), column(2));
  return p;
}

void Derivation::add_newton_euler_row(const std::string& body, const std::string& label,
                                      const ex& loads, const ex& kinetic) {
  const ex l = tidy_if_small(loads), r = tidy_if_small(kinetic);
  if (l.is_zero() && r.is_zero()) return;  // 0 = 0: nothing to say
  impl_.newton_euler.push_back({body, label, l, r});
}

}  // namespace momenta::symbolic::detail
