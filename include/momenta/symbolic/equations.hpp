#pragma once
// Equations of motion in symbols: a model's M(q) v̇ + C(q, v) v + g(q) = Q(q, v, u) derived
// by computer algebra (GiNaC), its parameters left as numbers or turned into named symbols.
//
// Derivation. The recursive Newton–Euler algorithm (Featherstone 2008, §5.3) run on symbolic
// expressions, in body frames (so a chain's entries depend on its relative joint angles, as a
// textbook writes them): τ(q, v, v̇) = M v̇ + C v + g with gravity as an upward acceleration of
// the base; M_kj = ∂τ_k/∂v̇_j, g = τ(q, 0, 0), C v = τ(q, v, 0) − g. The force elements' generalized
// forces Q are a second pass with their wrenches as the only loads, plus the joint-space terms.
// Entries are expanded, sin² θ folded into 1 − cos² θ, and collected.
//
// Constraints (model/constraint.hpp) add a multiplier λ per row (lambda_<constraint>_<label>)
// and their rows: M v̇ + C v + g = Q + Gᵀλ with G v̇ + k = 0, and φ(q) = 0 on holonomic rows —
// the rows of dynamics/constraints.hpp, the same in number, order, sign and meaning (a unit λ
// is the same force), so λ is the constraint force momenta simulate reports.
//
// Coordinates. A joint with nq == nv contributes its coordinates as symbols named after it (a
// 1-dof joint by its own name, "pivot"; several as "<joint>_<coordinate>", "base_x"); their rates
// are "<name>_dot" and accelerations "<name>_ddot" (LaTeX \dot{}, \ddot{}). A ball or free joint
// contributes its quaternion "<joint>_qw" ... and its body-frame angular velocity "<joint>_wx" ...
// (and the free joint's position "<joint>_x" ... with rates "<joint>_x_dot" ...): its speeds are
// not the rates of its coordinates. A prescribed joint's coordinate is its signal's value, rate
// and acceleration: "<signal>", "<signal>_dot", "<signal>_ddot" — a prescribed ball or free
// joint's keep the names above (its quaternion, ω and ω̇, known functions of time from its
// signals' rotation vector: the values `evaluate` takes from q, v and v̇); every signal that
// scales a load is a symbol of its own name. Only the free (not prescribed) speeds get an
// equation.
//
// Parameters. With `symbols` (or all_symbols) a parameter becomes a symbol named:
//   m_<body>, I_<body>_xx … I_<body>_xy (inertia about the centre of mass, off-diagonals as
//   stored: minus the products of inertia), c_<body>_x … (centre of mass), g (gravity's size),
//   l_<joint>_x … (the joint frame's position in its parent), c_<joint> (joint damping),
//   k_<element>, c_<element>, l0_<element> (springs, dampers, friction), F_<element> (the size of
//   an applied force or torque).
//   Lengths: where a body's centre of mass, or a joint frame's position in its parent (or child),
//   lies along one axis of the frame, the distance is one positive symbol with the axis's sign —
//   L_<body> (c_<body>_z = −L_bob for a bob hanging below its pivot), L_<joint>, L_<joint>_child —
//   as a textbook writes a pendulum's m L² θ̈ + m g L sin θ = 0. `symbols` may name either form.
//   Constraints: p_<constraint>_a_x … / _b_ (a loop's or link's frame origins in their bodies),
//   p_<constraint>_centre_x … and p_<constraint>_point_x … (a rolling body's centre, a knife
//   edge's point), L_<link> (a link's length), r_<contact> (a rolling radius), n_<coupler> and
//   q0_<coupler> (ratio and offset).
// A parameter whose value is zero stays 0. Other numbers print as short decimals where they are
// one (9.81), else with 17 significant digits.

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "momenta/math/types.hpp"
#include "momenta/model/model.hpp"
#include "momenta/model/parameter_source.hpp"

namespace momenta::symbolic {

class LinearEquations;

struct EquationOptions {
  std::vector<std::string> symbols;  ///< parameters to keep as symbols, by the names above
  bool all_symbols = false;          ///< every nonzero parameter a symbol
  bool newton_euler = false;         ///< derive the Newton–Euler form too (newton_euler_rows)
  /// The Newton–Euler rows of a body with products of inertia in its principal axes at G (e1,
  /// e2, e3 by increasing moment, named in the row's group) instead of its own axes.
  bool principal_axes = false;
  /// In a planar model's Newton–Euler rows, a body on a fixed pivot O has ΣF_n = m r̄ ω² and
  /// ΣF_t = m r̄ α (n from G towards O, t along G's motion, r̄ = |OG|) in place of its x and y.
  bool normal_tangential = false;
  /// The names a person gives (a model file's `symbols:` section): momenta's name of a parameter
  /// or a coordinate (m_bob, L_bob, pivot) → the name to write instead (m, L, theta), an
  /// identifier. Parameters given the same name must have the same value (to 1e-12): they are
  /// one symbol. A coordinate's rate and acceleration follow its name (theta_dot, theta_ddot).
  std::map<std::string, std::string> names;
  /// Text and LaTeX write the angles of revolute joints not named in `names` as θ (θ₁, θ₂, … in
  /// model order when there are several), their rates and accelerations θ̇, θ̈ (LaTeX \theta,
  /// \dot{\theta}_{1}). Display only: the generated code, --json names and the symbols' names
  /// stay as above.
  bool greek = false;
};

/// How an expression prints.
enum class Format { text, latex, cpp, python };

/// One parameter turned into a symbol: its name, the model's value, the symbol in LaTeX and the
/// value's SI unit ("kg", "m", "N·m/rad"; "" for a pure number or where it depends on the joint).
struct Parameter {
  std::string name;
  double value = 0.0;
  std::string latex;
  std::string unit;
  /// Where the value comes from (model/parameter_source.hpp): the model's numbers the symbol
  /// stands for — one, or several the `names` give one symbol (their values agree).
  std::vector<model::ParameterSource> sources;
};

/// A number of the model the equations' form depends on though no symbol stands for it: a
/// parameter that is 0 (the terms it would multiply are left out), a parameter kept as a number,
/// the size of a load along a signal's direction where it is 1 (the load is u along it), a
/// component of gravity's direction. With another value the equations are another form.
struct FormNumber {
  std::string name;  ///< momenta's name of it (m_cart, c_bob_x, "gravity's direction")
  model::ParameterSource source;
  double value = 0.0;
};

/// A term of an equation with its parameters as numbers: a coefficient, the polynomial in the
/// parameters Σ factor × Π pᵢ^eᵢ over `coefficient` (i indexes Equations::parameters()), times
/// `latex`, the rest of the term (accelerations, rates, coordinates, their functions, inputs,
/// multipliers; "1" for a constant), on the equation's left or right side.
struct EquationTerm {
  struct Monomial {
    double factor = 1.0;
    std::vector<std::pair<int, int>> powers;  ///< (parameter index, exponent)
  };
  std::vector<Monomial> coefficient;
  std::string latex;
  bool right = false;
};

/// A model's equations of motion in symbols (see the file comment). Holds GiNaC expressions
/// behind an opaque pointer; copies share them.
class Equations {
 public:
  ~Equations();
  Equations(const Equations&);
  Equations& operator=(const Equations&);

  /// The names of the configuration symbols (model q order), the speed symbols (model v order)
  /// and the acceleration symbols (model v order). Prescribed coordinates appear under their
  /// signal's names.
  const std::vector<std::string>& configuration_names() const;
  const std::vector<std::string>& speed_names() const;
  const std::vector<std::string>& acceleration_names() const;
  /// The model v indices that have an equation (those not prescribed), in order.
  const std::vector<int>& free_speeds() const;
  /// The symbols standing for signals (inputs u), their names.
  const std::vector<std::string>& input_names() const;
  /// The parameters kept as symbols, with the model's values.
  const std::vector<Parameter>& parameters() const;
  /// The numbers the form depends on that no symbol stands for (FormNumber).
  const std::vector<FormNumber>& form_numbers() const;

  /// Entries as text in `format`: M (free × free), C v, g, Q (each of size free), and the
  /// equation of each free speed, "M v̇ + C v + g = Q" written out and collected by acceleration.
  std::string mass_matrix_entry(int row, int column, Format format) const;
  std::string velocity_product(int row, Format format) const;
  std::string gravity(int row, Format format) const;
  std::string generalized_force(int row, Format format) const;
  std::string equation(int row, Format format) const;
  /// The equation of free speed `row` as its terms with their coefficients in the parameters
  /// (EquationTerm): the sides `equation` prints, expanded, each term's parameters taken out and
  /// the terms that share the rest added — the row's own acceleration first, then the other
  /// accelerations. Nothing where a parameter is not a factor of its term (inside a function,
  /// as √(L² + …) or sin(q − rest)). A page evaluates the coefficients at other values.
  std::optional<std::vector<EquationTerm>> equation_terms(int row) const;

  /// The Newton–Euler form (--form newton-euler): for each body, Newton's and Euler's equations
  /// in the body's own axes, ΣF = m a_G and ΣM_G = Ī α + ω × Ī ω (Euler's equations; the body's
  /// axes are its principal axes when its inertia is diagonal there), with the reactions of the
  /// joints as unknowns — R_<joint>_x, _y, _z the force the joint puts on its child and
  /// N_<joint>_x, _y, _z its moment about the child-side joint frame's origin J', both in the
  /// child's axes (dynamics::joint_reaction with ReactionFrame::child) — and, for each free joint,
  /// the reaction along its motion equal to its elements' generalized force. With
  /// EquationOptions::principal_axes, a body whose axes are not principal has its rows in its
  /// principal axes (ΣF_1 … ΣM_G3, Euler's equations I1 α1 − (I2 − I3) ω2 ω3 = ΣM_G1 …). Rows that
  /// read 0 = 0 are left out. A planar model — every joint revolute (or planar) about an axis of
  /// its child's frame, and every body's rows out of its plane of motion 0 = 0 once the joints'
  /// reactions out of it are 0 — has three rows per body, ΣF in its plane and ΣM_G = Ī α about
  /// the normal (those reactions left out), or with normal_tangential the n–t form on a fixed
  /// pivot. `newton_euler_group` names the body ("link1") or the joint ("joint j1"). Empty unless
  /// derived with EquationOptions::newton_euler.
  int newton_euler_rows() const;
  /// Whether the Newton–Euler rows are the planar form (three per body, see above).
  bool newton_euler_planar() const;
  std::string newton_euler_group(int row) const;
  /// "ΣF_x = m a_Gx: loads = kinetic term" in `format` (text or latex).
  std::string newton_euler_equation(int row, Format format) const;
  /// The reaction symbols' names, per joint in model order: R_x, R_y, R_z, N_x, N_y, N_z; then
  /// the constraints' multipliers (multiplier_names()), whose forces join the bodies' loads.
  std::vector<std::string> reaction_names() const;
  /// Each row's loads − kinetic term at a state (as `evaluate`) with the reactions' values (6 per
  /// joint, then one per constraint row, in reaction_names() order): zero for the motion and the
  /// reactions of the dynamics.
  VecX newton_euler_residuals(const VecX& q, const VecX& v, const VecX& vdot, const VecX& u,
                              const VecX& reactions) const;

  /// The constraints' rows (none without constraints): the row's name ("closure.x"), whether it
  /// restricts positions, its equation — φ(q) = 0 on a holonomic row, G(q) v = 0 on the others —,
  /// an entry of G (a free speed's column, as the equations' rows), k = Ġ v, and the multipliers'
  /// names (lambda_closure_x, one per row).
  int constraint_rows() const;
  const std::string& constraint_row_name(int row) const;
  bool constraint_row_holonomic(int row) const;
  std::string constraint_equation(int row, Format format) const;
  std::string constraint_jacobian_entry(int row, int column, Format format) const;
  std::string constraint_bias(int row, Format format) const;
  std::vector<std::string> multiplier_names() const;

  /// Evaluates φ (0 on velocity rows), G (rows × nv: every model speed, as
  /// dynamics::ConstraintRows::G) and k (= Ġ v at v̇ = 0, as ConstraintRows::bias) at a state,
  /// as `evaluate`.
  void evaluate_constraints(const VecX& q, const VecX& v, const VecX& u, VecX& position, MatX& G,
                            VecX& k) const;

  /// Evaluates M, C v + g − Q (the bias b) at a state, the parameters at their model values and
  /// the signals at `u` (one per input_names(), in that order): M v̇_free + b = 0 is the motion
  /// (M v̇_free + b = G_freeᵀ λ with constraints).
  /// q and v are the model's (prescribed coordinates taken from them too, with their
  /// accelerations in vdot). Slow (substitution): for tests and checks, not simulation.
  void evaluate(const VecX& q, const VecX& v, const VecX& vdot, const VecX& u, MatX& M,
                VecX& bias) const;

  /// A C++ or Python source that computes M(q) and b(q, v, u) (as `evaluate`, without the
  /// substitution), in a namespace or module named `name` (made an identifier: other characters
  /// become '_'). See docs/equations.md.
  std::string generate_code(Format language, const std::string& name) const;

  struct Impl;

 private:
  friend Equations derive_equations(const model::Model&, const EquationOptions&);
  friend LinearEquations linearize_equations(const Equations&, const model::Model&, double,
                                             const VecX&, const VecX&);
  explicit Equations(std::shared_ptr<const Impl> impl);
  std::shared_ptr<const Impl> impl_;
};

/// Derives the equations of `model`. Throws InvalidArgument for what it cannot write yet (a
/// two-body torsional spring whose bodies turn about more than one axis relative
/// to each other), naming it, and for
/// a name in options.symbols that is no parameter of the model (with the names it has).
Equations derive_equations(const model::Model& model, const EquationOptions& options = {});

}  // namespace momenta::symbolic
