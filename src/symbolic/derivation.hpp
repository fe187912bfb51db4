#pragma once
// The derivation of the equations of motion in symbols (private to src/symbolic): the parameters
// and their names (Parameters), each joint's motion in symbols, and the Derivation — symbolic
// Newton–Euler in body frames (derivation.cpp) and the Newton–Euler form it presents the
// equations in, body by body (newton_euler_form.cpp). equations.cpp runs it.

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "constraint_rows.hpp"
#include "equations_impl.hpp"
#include "expression_algebra.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/symbolic/equations.hpp"

namespace momenta::symbolic::detail {

using GiNaC::ex;
using GiNaC::symbol;

std::string latex_name(const std::string& name);
std::string coordinate_latex(const std::string& name, std::string_view accent);

// Parameters: a symbol where the options ask for one, else the number. A parameter is asked
// for by momenta's name or by the name `options.names` gives it; the symbol carries the given
// name, and parameters given one name share one symbol (their values must agree).
class Parameters {
 public:
  Parameters(const model::Model& model, const EquationOptions& options)
      : model_(model),
        all_(options.all_symbols),
        asked_(options.symbols.begin(), options.symbols.end()),
        given_(options.names) {}

  // The parameter momenta calls `raw_name`, its value the model's number at `source`.
  ex operator()(const std::string& raw_name, const model::ParameterSource& source,
                std::string_view unit = {}) {
    return named(raw_name, source, {}, unit);
  }

  // A position in a frame, its components the model's numbers at `source` with row 0, 1, 2:
  // where it lies along one axis, a positive length `length_name` times the axis's sign (asked
  // for by that name or the component's); otherwise its components.
  V3 vector(const std::string& stem, model::ParameterSource source,
            const std::string& length_name = {}) {
    static const char* const axes[] = {"_x", "_y", "_z"};
    std::array<model::ParameterSource, 3> component{source, source, source};
    Vec3 value;
    for (int k = 0; k < 3; ++k) {
      component[static_cast<std::size_t>(k)].row = k;
      value[k] = model::parameter_value(model_, component[static_cast<std::size_t>(k)]);
    }
    const int nonzero = static_cast<int>((value.array() != 0.0).count());
    if (!length_name.empty() && nonzero == 1) {
      int k = 0;
      while (value[k] == 0.0) ++k;
      model::ParameterSource length = component[static_cast<std::size_t>(k)];
      length.magnitude = true;
      length.sign = value[k] < 0 ? -1 : 1;
      const ex L = named(length_name, length, identifier(stem + axes[k]), "m");
      V3 r;
      r[k] = value[k] < 0 ? -L : L;
      for (int other = 0; other < 3; ++other) {
        if (other == k) continue;
        names_.push_back(identifier(stem + axes[other]));
        form_numbers_.push_back(
            {identifier(stem + axes[other]), component[static_cast<std::size_t>(other)], 0.0});
      }
      return r;
    }
    return {{(*this)(stem + axes[0], component[0], "m"), (*this)(stem + axes[1], component[1], "m"),
             (*this)(stem + axes[2], component[2], "m")}};
  }

  // A number the form depends on that no symbol stands for (FormNumber).
  void form_number(const std::string& name, const model::ParameterSource& source) {
    form_numbers_.push_back({name, source, model::parameter_value(model_, source)});
  }

  // Whether `raw_name` is to be a symbol (every one, or asked for by it or its given name).
  bool asked(const std::string& raw_name) const {
    const std::string name = identifier(raw_name);
    return all_ || asked_.count(name) != 0 || asked_.count(given(name)) != 0;
  }

  // Marks a parameter's name as known (--symbols may name it) where it cancels from the equations.
  void known(const std::string& raw_name) { names_.push_back(identifier(raw_name)); }

  // The name a person gave `name` (options.names), or `name`.
  std::string given(const std::string& name) const {
    const auto it = given_.find(name);
    return it == given_.end() ? name : it->second;
  }
  // Marks a coordinate's name as known (options.names may name it).
  void coordinate(const std::string& name) {
    names_.push_back(name);
    coordinates_.push_back(name);
  }

  // Every name asked for must be a parameter of the model, every name given a parameter or a
  // coordinate.
  void check() const {
    const std::vector<std::string_view> views(names_.begin(), names_.end());
    const auto known = [&](const std::string& name) {
      return std::find(names_.begin(), names_.end(), name) != names_.end();
    };
    for (const std::string& name : asked_) {
      if (known(name) || std::any_of(given_.begin(), given_.end(),
                                     [&](const auto& g) { return g.second == name; })) {
        continue;
      }
      throw InvalidArgument(
          fmt::format("equations: no parameter named '{}'{}; the model's parameters are {}", name,
                      did_you_mean(name, views), fmt::join(listed_, ", ")));
    }
    for (const auto& [name, to] : given_) {
      if (known(name)) continue;
      InvalidArgument error(
          fmt::format("equations: symbols: names '{}' (as {}), which is no parameter or coordinate "
                      "of the model{}; its coordinates are {}, its parameters {}",
                      name, to, did_you_mean(name, views), fmt::join(coordinates_, ", "),
                      fmt::join(listed_, ", ")));
      error.about_symbol(name);
      throw error;
    }
  }
  std::vector<symbol> symbols_;
  std::vector<Parameter> values_;
  std::vector<FormNumber> form_numbers_;

 private:
  // The parameter momenta calls `raw_name` (also known as `alias`), its value the model's number
  // at `source`: 0, or a number where no symbol is asked for — both FormNumbers — else a symbol.
  ex named(const std::string& raw_name, const model::ParameterSource& source,
           const std::string& alias, std::string_view unit) {
    const double value = model::parameter_value(model_, source);
    const std::string name = identifier(raw_name);
    names_.push_back(name);
    if (!alias.empty()) names_.push_back(alias);
    if (value == 0.0) {
      form_numbers_.push_back({name, source, value});
      return 0;
    }
    listed_.push_back(name);
    std::string shown = given(name);
    if (shown == name && !alias.empty()) shown = given(alias) == alias ? name : given(alias);
    const bool asked = all_ || asked_.count(name) != 0 || asked_.count(shown) != 0 ||
                       (!alias.empty() && asked_.count(alias) != 0);
    if (!asked) {
      form_numbers_.push_back({name, source, value});
      return exact_number(value);
    }
    for (std::size_t k = 0; k < symbols_.size(); ++k) {
      if (symbols_[k].get_name() != shown) continue;
      const double other = values_[k].value;
      if (std::abs(other - value) > 1e-12 * std::max(std::abs(other), std::abs(value))) {
        InvalidArgument error(fmt::format(
            "equations: two parameters are named '{}' with different values, {} and {} ({}); give "
            "them different names",
            shown, other, value, name));
        error.about_symbol(shown);
        throw error;
      }
      values_[k].sources.push_back(source);
      return symbols_[k];
    }
    const symbol s(shown, latex_name(shown));
    symbols_.push_back(s);
    values_.push_back({shown, value, latex_name(shown), std::string(unit), {source}});
    return s;
  }

  const model::Model& model_;
  bool all_;
  std::set<std::string> asked_;
  std::map<std::string, std::string> given_;
  std::vector<std::string> names_;        // every name a parameter or coordinate answers to
  std::vector<std::string> listed_;       // the nonzero parameters, for messages
  std::vector<std::string> coordinates_;  // the coordinates' names, for messages
};

// One joint's motion in J': its rotation and translation, and the columns of S.
struct JointMotion {
  M3 R;
  V3 p;
  std::vector<Motion> S;
};

JointMotion joint_motion(const model::Joint& j, const std::vector<ex>& q, int qi);

// The one axis of W a spring's line keeps (its length ±d_axis), or axis −1 (√(d·d)).
struct Line {
  int axis = -1;
  int sign = 1;
};

class Derivation {
 public:
  Derivation(const model::Model& model, const EquationOptions& options)
      : model_(model),
        params_(model, options),
        greek_(options.greek),
        newton_euler_(options.newton_euler),
        principal_axes_(options.principal_axes),
        normal_tangential_(options.normal_tangential) {}

  Equations::Impl run();

 private:
  // q, v, v̇ of every coordinate: symbols, or the prescribing signal's.
  void make_coordinate_symbols();

  // θ (θ₁, θ₂, …) for the angles collected in angles_ (EquationOptions::greek); an angle named
  // by a Greek letter (the Euler angles phi, theta, psi) keeps its own: φ, θ, ψ.
  void greek_display();

  void set_coordinate(int qi, int vi, const symbol& q, const symbol& v, const symbol& a,
                      const std::string& name);

  // Signals that scale a load are inputs, symbols of their own names.
  void make_input_symbols();

  // d/dt of an expression of the coordinates: the chain rule with q̇ from the speeds.
  ex rate(const ex& e) const;
  Motion rate(const Motion& m) const;

  // The body frames' poses, the joints' subspaces in the body frames and their rates, the
  // inertias: what every Newton–Euler pass shares.
  void kinematics();

  // One Newton–Euler pass: τ for the speeds `v` and accelerations `vdot` (expressions per model
  // coordinate), with or without gravity; the body velocities into `velocities` when asked.
  std::vector<ex> newton_euler(const std::vector<ex>& v, const std::vector<ex>& vdot, bool gravity,
                               std::vector<Motion>* velocities = nullptr,
                               std::vector<Motion>* accelerations = nullptr) const;

  // The passes: τ with the free accelerations zero (C v + g and the prescribed motion's terms),
  // g at rest, and each column of M (a unit free acceleration, nothing else).
  void newton_euler();

  // τ_j = S_jᵀ f_i from the leaves to the root, f_p += ᵖX_i* f_i.
  void project_down(std::vector<Force>& f, std::vector<ex>& out) const;

  Inertia inertia(int b);

  // A body that is one standard shape, with a dimension of it asked for as a symbol (its
  // `<size>_<body>`: length_rod, radius_wheel, size_x_block): its inertia about the centre of mass,
  // R_BS (m × its unit moments in those dimensions) R_BSᵀ. Its other dimensions are numbers.
  // Nothing when no dimension is asked for, or its moments are (every parameter is, with
  // --all-symbols, which keeps the body's moments as the symbols I_*).
  std::optional<M3> shape_inertia(int b, const ex& m, bool moments_asked);

  // Q: the elements' wrenches projected on the speeds, and the joint-space terms.
  void element_forces();

  // A torsional spring between two bodies whose relative rotation turns about one axis n: every
  // joint on the tree path between them is revolute about an axis parallel to n, or does not
  // turn (fixed, prismatic). Its angle from the rest orientation is φ = Σ ±(q_j − q_j0) (+ on the
  // way down to b, − down to a) and it puts the moment −(k φ + c φ̇) n on b and the opposite on
  // a, n being fixed in both. Other paths (a ball joint between them, two axes) are refused.
  // `element`: its index in the model's force elements (its parameters' sources).
  void add_two_body_torsion(const model::TorsionalSpringDamper& t, int element,
                            std::vector<Force>& f);
  // A fixed tendon's generalized forces −nᵢ (k (L − rest) + c L̇) on its joints, into Q_.
  void add_tendon(const model::FixedTendon& tendon, int element);

  // A spring's stretch, length − l0. Along a line (line_length) the length is the joints'
  // offsets plus the coordinates; its value at q = 0 (inputs at 0 too) is the offsets' part. A
  // textbook writes the spring relaxed there, k (x − y): where l0 is that value, offsets and free
  // length cancel and are left out; where not, their difference, the stretch at q = 0, is the
  // parameter d0_<spring> (m). Off a line, √(d·d) − l0 as it is. `element`: the spring's index.
  ex stretch(const std::string& name, int element, const ex& length, const Line& line);

  // |d|. Where the line keeps one direction (d has one nonzero component, as a suspension's
  // vertical spring) it is ±d_k with the sign d_k has at the initial configuration — a spring
  // that does not pass through zero length, as a textbook writes k (x_b − x_a) — else √(d·d).
  // `line`, when given, says which: the axis of W it keeps and the sign, or axis −1.
  ex line_length(const V3& d, Line* line = nullptr);

  // An expression's value at the model's initial configuration, parameters at their values.
  double initial_value(const ex& e) const;

  // An applied load's vector in W: size (a parameter F_<name>) × direction × signal.
  // `element`: the load's index in the model's force elements.
  V3 load(const std::string& name, int element, const Vec3& vector, int signal,
          model::LoadFrame frame, int body, std::string_view unit);

  // The constraints' rows (constraint_rows.hpp): φ(q) on holonomic rows, G (jacobian_row),
  // k = Ġ v as the rate of G v at v̇ = 0, and a multiplier λ per row, whose forces join the
  // Newton–Euler form's loads (add_row_loads).
  void constraint_equations();

  // Every motion-subspace column in W about Wo: [R s_w; R s_v + p × R s_w], per model speed.
  std::vector<Motion> world_subspaces() const;

  // A row of G over every model speed: a wrench row's G_j = w·S_j over the joints that support
  // body b, minus those supporting a (as dynamics::constraint_equations assembles it); a
  // coupler's as written.
  std::vector<ex> jacobian_row(const SymbolicRow& row, const std::vector<Motion>& S_W) const;

  // The row's force with multiplier λ: λ w on body b and −λ w on a, in B about Bo; a coupler's
  // λ G on its joints' generalized forces.
  void add_row_loads(const SymbolicRow& row, const symbol& lambda);

  // Per body, Newton's and Euler's equations in its own axes with the joint reactions as
  // unknowns (symbols R_<joint>_x … for the force on the child, N_<joint>_x … for the moment
  // about J'o, both in the child's axes): ΣF = m a_G, ΣM_G = Ī α + ω × Ī ω; then each free
  // joint's reaction along its motion equals its elements' generalized force.
  void newton_euler_form();

  // A body's Newton–Euler balance, in its axes: loads F, M about G; m a_G, Ī α + ω × Ī ω.
  struct BodyBalance {
    int body = 0;
    const model::Joint* joint = nullptr;  // the joint that carries it
    V3 F, M, ma, H_dot, w, alpha, c;
    V3 R, N;          // its joint's reaction (out of the plane 0 when planar)
    int normal = -1;  // planar: the body axis normal to the plane of motion
    bool out_of_plane_balanced() const {
      for (int k = 0; k < 3; ++k) {
        const ex force = k == normal ? F[k] - ma[k] : ex(0);
        const ex moment = k != normal ? M[k] - H_dot[k] : ex(0);
        if (!GiNaC::expand(force).is_zero() || !GiNaC::expand(moment).is_zero()) return false;
      }
      return true;
    }
  };

  // Per body, the axis of its frame along its joint's rotation when every joint is revolute (or
  // planar) about an axis of its child's frame; empty otherwise (then not planar).
  std::vector<int> plane_normals() const;

  // Every body's balance; with `normals`, the reactions out of each plane of motion set to 0.
  std::vector<BodyBalance> balances(const std::vector<Motion>& V, const std::vector<Motion>& A,
                                    std::vector<V3> R, std::vector<V3> N,
                                    const std::vector<int>& normals) const;

  // A body's rows (its axes, its principal axes, or — planar — the three in its plane, with the
  // n–t components of a_G on a fixed pivot when asked), then its joint's along its motion.
  void add_body_rows(const BodyBalance& b, bool planar);

  // A body on a fixed pivot O, in its plane: ΣF_n = m r̄ ω² (n from G towards O) and
  // ΣF_t = m r̄ α (t along the motion of G), r̄ = |OG| (Beer & Johnston §16.8). False when G is
  // on the axis (no n–t directions).
  bool add_normal_tangential_rows(const BodyBalance& b, std::string& body);

  // A body's principal axes at its centre of mass where its axes are not (Ī has products of
  // inertia): R_BP (columns e1, e2, e3 in B: the eigenvectors of Ī by increasing moment, right-
  // handed) and Ī_P = R_BPᵀ Ī R_BP — diagonal, the principal moments, when Ī is numbers; the
  // rotated matrix of symbols when its entries are symbols (then still exact, not diagonal).
  struct PrincipalAxes {
    M3 R_BP, I;
    std::string description;  // " (principal axes e1 = [..], e2, e3 in B)"
  };
  std::optional<PrincipalAxes> principal_axes_of(int b) const;

  void add_newton_euler_row(const std::string& body, const std::string& label, const ex& loads,
                            const ex& kinetic);

  // M, g, the rest and Q of each free speed; tidied where small enough to expand (a general 3-D
  // tree's entries multiply out into more terms than any reader wants, and than time allows: they
  // are kept as the recursion built them, exact all the same).
  void split();

  const model::Model& model_;
  Parameters params_;
  bool greek_ = false;               // θ for the revolute joints' angles in text and LaTeX
  std::vector<std::string> angles_;  // their symbols' names, in model order
  bool newton_euler_ = false;        // derive the Newton–Euler form too
  bool principal_axes_ = false;      // its rows in each body's principal axes
  bool normal_tangential_ = false;   // planar: n–t components of a_G on a fixed pivot
  Equations::Impl impl_;
  std::vector<std::pair<ex, ex>> rates_;  // (coordinate symbol, its rate)
  std::vector<ex> input_of_signal_;
  std::vector<M3> R_PC_, R_WB_;
  std::vector<V3> p_PC_, p_WB_;
  std::vector<Motion> V_;  // body velocities (in B), for the elements
  std::vector<std::vector<Motion>> S_, dS_;
  std::vector<Inertia> inertias_;
  V3 base_acceleration_;
  std::vector<ex> tau_no_acceleration_, tau_gravity_, Q_;
  std::vector<ex> armature_;  // each speed's rotor inertia (a joint's armature), 0 without
  std::vector<std::vector<ex>> mass_columns_;
  std::vector<V3> p_CJ_, com_;           // per body: its joint's J'o and its centre of mass, in B
  std::vector<M3> I_com_;                // per body: Ī about the centre of mass, in B
  std::vector<Force> body_loads_;        // per body: the elements' wrench, in B about Bo
  std::vector<ex> joint_space_;          // per speed: the elements' joint-space terms
  std::vector<Force> constraint_loads_;  // per body: Σ λ w of the constraint rows, in B about Bo
  std::vector<ex> constraint_joint_forces_;  // per speed: Σ λ G of the couplers' rows
};

}  // namespace momenta::symbolic::detail
