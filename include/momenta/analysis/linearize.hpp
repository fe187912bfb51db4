#pragma once
// Linearization of a multibody model (momenta::model::Model, run by system::MultibodySystem)
// about an operating point, for control design:
//
//     δẋ = A δx + B δu,     δy = C δx + D δu.
//
// States. x = [δq; v] over the free (not prescribed) joints' coordinates: δq is the tangent of
// the configuration, q = q₀ ⊕ δq (model::integrate; a ball joint's quaternion becomes its
// rotation vector in J', 3 coordinates, a free joint's 7 become 6), v the joints' velocities.
// Prescribed joints' coordinates are not states: their motion is an input.
//
// Dynamics through inverse dynamics. With r(q, v, v̇, u) = ID(q, v, v̇) − τ_elements(q, v, u) the
// free coordinates' generalized-force residual (rnea with the force elements' body wrenches,
// minus their joint forces), the motion obeys r_f(q, v, a(q, v, u), u) ≡ 0 and ∂r_f/∂v̇_f = M_ff,
// so at the operating point, with v̇₀ its acceleration,
//
//     A = [ T              I            ]     K = ∂r_f/∂δq,  C_v = ∂r_f/∂v    at v̇ = v̇₀
//         [ −M⁻¹ K      −M⁻¹ C_v       ],    B = [0; −M⁻¹ ∂r_f/∂u],
//
// M = M_ff(q₀) by CRBA, T = ∂(δ̇q)/∂δq = −½[ω₀]× on rotation coordinates (from δ̇ = J_r(δ)⁻¹ ω)
// and 0 elsewhere (so T = 0 at rest).
//
// Derivatives (docs/analysis.md, "Model linearization"):
//  - K and C_v analytically: ∂r/∂δq and ∂r/∂v are rnea_derivatives (at v̇ = v̇₀) less
//    force_element_derivatives (dynamics/), exact to round-off. (LinearizationOptions::derivatives
//    = differences takes them by the differences below instead: the tests' check.)
//  - Output columns, ∂/∂v: outputs are at most quadratic in v at fixed q, and for a quadratic the
//    central difference [y(v + h) − y(v − h)] / 2h is the derivative exactly, for any h: round-off
//    only (h = 1 rad/s or m/s).
//  - ∂/∂u: loads are linear in their signals' values, and a prescribed motion's rate enters
//    quadratically and its acceleration linearly, so these central differences are exact too.
//  - Output columns ∂/∂δq, and a prescribed motion's value: central differences with one
//    Richardson extrapolation, R(h) = (4 D(h/2) − D(h)) / 3 = f' + O(h⁴); truncation ~h⁴ against
//    round-off ~ε/h puts the best step near ε^(1/5) ≈ 7e-4 of the coordinate's scale: h = 1e-3 rad
//    on angles and 1e-3·L on lengths, L the model's characteristic length. Error ~1e-12 relative.
//
// Prescribed motion as an input. A prescribed coordinate p(t) (a road profile under a tire)
// acts through its value, rate and acceleration: δv̇ = … + b₀ δp + b₁ δṗ + b₂ δp̈. The input is
// the position δp itself: the rate and acceleration terms are folded in exactly by shifting the
// states, w = δx − E₁ δp − E₂ δṗ with E₂ = B₂, E₁ = A E₂ + B₁, which gives
//     ẇ = A w + (B₀ + A E₁) δp,    δy = C w + (D₀ + C E₁) δp,
// the same poles, the same transfer function C(sI − A)⁻¹(B₀ + B₁ s + B₂ s²) + D₀. Where the
// prescribed motion acts through its position only (a tire as a pure spring on a separate
// joint), E₁ = E₂ = 0 and the states are unchanged. An output that would feel δṗ or δp̈
// directly (C E₂ + D₁ ≠ 0 or D₂ ≠ 0: a velocity carried by the prescribed joint) makes the
// transfer function improper and is refused.
//
// A commanded coordinate (a prescribed joint's signal a controller drives: model/controller.hpp)
// is no motion of time but the integral of its commanded acceleration a: it and its rate join the
// states, after the others, and a is the input — ẋ = A x + B₀ p + B₁ ṗ + B₂ a,
// d/dt [p; ṗ] = [ṗ; a], y = C x + D₀ p + D₁ ṗ + D₂ a, from the same unfolded columns. So does the
// plant a controller is designed on (close_loops = false) and the closed loop.
//
// Models with constraints (model/constraint.hpp): the states are independent coordinates, by
// coordinate partitioning (Wehage & Haug 1982). At the operating point (made consistent first,
// as a simulation's initial state is) the independent rows of the constraint Jacobian G split
// the free coordinates: the configuration states ξ are the coordinates left after choosing, for
// the holonomic rows, dependent ones whose columns of G are well conditioned (taken from the last
// joint back, so the first joints' coordinates — a crank's angle — stay states; those named in
// LinearizationOptions::independent are kept whenever possible); the velocity states ζ are the
// configuration states left after choosing dependent velocities for the nonholonomic rows too
// (a rolling disk's x and y are configuration states, their rates are not). The motion in these
// states is exact: q(ξ) = q₀ ⊕ δ with δ_ξ = ξ and δ_dependent solved by Newton on φ = 0, v(q, ζ)
// with v_ζ = ζ and v_dependent from G v = 0, and
//
//     ξ̇ = [δ̇(δ, v)]_ξ,     ζ̇ = [v̇(q, v)]_ζ (the constrained forward dynamics),
//
// differentiated analytically: the chart's maps from G and the rows' derivatives
// (dynamics/constraint_derivatives.hpp), the accelerations' from the derivatives of the constrained
// equations r_f − G_fᵀ λ = 0, G v̇ + k = 0 (docs/constraints.md, "The derivatives"). For holonomic
// constraints the second-order form is the reduced one:
// mass = Tᵀ M_ff T with T = ∂v_f/∂ζ, stiffness = −mass ∂ζ̇/∂ξ, damping = −mass ∂ζ̇/∂ζ (at an
// equilibrium the stiffness is the Hessian of the potential in ξ, symmetric). With nonholonomic
// rows there are more configuration than velocity states and no such form: mass, damping and
// stiffness are empty. Prescribed-motion inputs on a constrained model are refused when named
// (they move the constraint manifold) and left out of the default inputs.

#include <string>
#include <vector>

#include "momenta/analysis/modes.hpp"
#include "momenta/analysis/state_space.hpp"
#include "momenta/math/types.hpp"
#include "momenta/model/model.hpp"
#include "momenta/system/output_set.hpp"

namespace momenta::analysis {

/// A state of a model: time (signals are evaluated at t), configuration and velocity.
struct OperatingPoint {
  double t = 0.0;  ///< s
  VecX q;          ///< nq
  VecX v;          ///< nv
};

/// The model's initial state (each joint's q0 and v0) at t = 0.
OperatingPoint initial_operating_point(const model::Model& model);

/// What to linearize with respect to, and how.
struct LinearizationOptions {
  /// Inputs u: model signals by name (an applied load's value, or a prescribed motion), or a
  /// prescribed coordinate by its name ("road.position", model::Model::q_name), which stands for
  /// the signal driving it and keeps the name given. Empty: every signal of the model.
  std::vector<std::string> inputs;
  /// Outputs y: a column of `output_specs` ("tip.x"), a state ("hinge.angle",
  /// "hinge.angle_rate"), or any model coordinate by name (model::Model::q_name / v_name, e.g. a
  /// prescribed joint's "road.position" or a quaternion's "base.qw"). Empty: every column of
  /// `output_specs`, or every configuration state when there are none.
  std::vector<std::string> outputs;
  /// The named model quantities `outputs` may refer to (a model file's `outputs:`).
  std::vector<model::OutputSpec> output_specs;
  /// Largest step of the configuration differences, rad on angles; 0: automatic (1e-3).
  double angle_step = 0.0;
  /// The same on lengths, m; 0: automatic (1e-3 · characteristic_length(model)).
  double length_step = 0.0;
  /// How the equations of motion's rows of A (and of B for a prescribed motion's value) are
  /// differentiated: analytically, exact to round-off (rnea_derivatives, force elements'
  /// derivatives and, with constraints, constraint_derivatives), or by central differences with
  /// one Richardson extrapolation along the same coordinates (error ~1e-10 relative; the
  /// independent check the tests hold the analytic derivatives to). Outputs are differenced
  /// either way.
  enum class Derivatives { analytic, differences };
  Derivatives derivatives = Derivatives::analytic;
  /// Models with constraints: coordinates (model::Model::q_name, or a rotation tangent's
  /// "<joint>.rx") to keep as states where the constraints allow; empty: automatic.
  std::vector<std::string> independent;
  /// Models with controllers (model/controller.hpp): true linearizes the closed loop — the
  /// controllers' states appended to x ("cruise.integral"), the inputs the references and the
  /// inputs no controller drives (default: every one of those); false the plant alone, each
  /// driven input an input (what a controller is designed on: `momenta lqr`). Continuous
  /// controllers only; the laws linear (saturation and quantization left out), the plant taken
  /// with its driven inputs at the controllers' outputs at the point (their states as a run
  /// from the point starts them: integrals zero, filters at the error).
  bool close_loops = true;
  /// The value of each input a controller drives, at the point (indexed like model.signals();
  /// the entries of other signals ignored); empty: zero. The closed loop's linearization sets it
  /// to the controllers' outputs at the point, and the plant is linearized there.
  std::vector<double> driven_values;
};

/// The linear model about one operating point.
struct LinearModel {
  /// ẋ = A x + B u, y = C x + D u, with every name: states "<joint>.<coordinate>" then
  /// "<joint>.<coordinate>_rate" (model::Model::q_name / v_name; rotation tangents of ball and
  /// free joints "<joint>.rx", ".ry", ".rz"), the inputs and outputs as requested. B and D hold
  /// prescribed-motion inputs folded as the header comment says.
  StateSpace system{MatX(), MatX(), MatX(), MatX()};
  /// The point itself, its prescribed coordinates set from their signals.
  OperatingPoint point;
  /// v̇ at the point (nv); zero on the free coordinates at an equilibrium.
  VecX acceleration;
  /// y at the point (one per output).
  VecX output_values;
  /// The velocity index (into v) of each configuration state; without constraints every free
  /// coordinate, and state i and state nf + i belong to free coordinate i.
  std::vector<int> coordinates;
  /// The velocity index of each velocity state (state coordinates.size() + k); the same as
  /// `coordinates` unless nonholonomic constraints remove velocities.
  std::vector<int> velocity_coordinates;
  /// The velocity indices of the coordinates the constraints determine (empty without
  /// constraints): configuration ones, then the velocities that nonholonomic rows add.
  std::vector<int> dependent_coordinates, dependent_velocities;
  /// Second-order form over the nf free coordinates,
  ///   M δv̇ + damping δv + stiffness δq = −(∂r/∂u) δu − (∂r/∂u̇) δu̇ − (∂r/∂ü) δü,
  /// mass = M_ff(q₀) (symmetric positive definite), stiffness = ∂r_f/∂δq and damping = ∂r_f/∂v
  /// at v̇ = v̇₀ (damping includes gyroscopic terms when v₀ ≠ 0).
  MatX mass, damping, stiffness;
  /// The input columns before folding (n × m, rows over x): ∂ẋ/∂u (value), ∂ẋ/∂u̇ (rate) and
  /// ∂ẋ/∂ü (acceleration); the last two are zero for load signals.
  MatX input_value, input_rate, input_acceleration;
  /// The same for the outputs (p × m).
  MatX feedthrough_value, feedthrough_rate, feedthrough_acceleration;
  /// True when a prescribed input's rate or acceleration enters, so that the states of `system`
  /// are the shifted w = x − E₁ u − E₂ u̇ (see the header comment); A and the transfer functions
  /// are unaffected.
  bool states_shifted = false;
};

/// Linearizes `model` about `point` (q nq, v nv; quaternions unit to 1e-6) with respect to the
/// inputs and outputs of `options`.
/// Throws InvalidArgument when no joint is free (all fixed or prescribed), when the constraints
/// leave no state or conflict at the point, on a prescribed-motion input of a constrained model,
/// on a state of the wrong
/// size, an unknown input or output name (with a "did you mean"), a repeated name, an input that
/// drives nothing, or an output that feels a prescribed input's rate or acceleration directly (an
/// improper transfer function, named); NumericalError when the mass matrix of the free coordinates
/// is not positive definite or a derivative is not finite.
LinearModel linearize(const model::Model& model, const OperatingPoint& point,
                      const LinearizationOptions& options = {});

/// Checks the input and output names of `options` as linearize() resolves them (signals and
/// prescribed coordinates; output columns, states and joint coordinates), without linearizing:
/// a front end calls it before a long run whose report would linearize afterwards. Throws
/// InvalidArgument as linearize() does on an unknown (with a "did you mean"), repeated or
/// ineffective name. Names of a constrained model's dependent coordinates pass here and are
/// refused by linearize() itself.
void check_linearization_names(const model::Model& model, const LinearizationOptions& options);

/// The model's characteristic length (m): the largest joint offset, centre-of-mass offset, radius
/// of gyration, spring length or attachment offset; 1 m when all are zero. Sets the automatic
/// length step of linearize().
double characteristic_length(const model::Model& model);

/// Names of the states linearize() gives `model`: the free coordinates' tangent names, then
/// their velocity names.
std::vector<std::string> linear_state_names(const model::Model& model);

/// Below this largest free-coordinate acceleration (rad/s² or m/s²) a linearization's point is
/// at rest: an equilibrium, whose modes describe more than the instant.
inline constexpr double kAtRestAcceleration = 1e-9;

/// The largest |v̇| over the free coordinates at the linearization's point.
double largest_acceleration(const LinearModel& linear);

/// Above this largest free-coordinate speed (rad/s or m/s) a linearization's point moves: a
/// spinning top with no acceleration is still no equilibrium, and its gyroscopic terms couple
/// the coordinates.
inline constexpr double kAtRestSpeed = 1e-9;

/// The largest |v| over the free coordinates at the linearization's point.
double largest_speed(const LinearModel& linear);

/// Undamped normal modes of M δq̈ + K δq = 0 from a linearization (mass and stiffness), named
/// after the configuration states. K is symmetric for a conservative model at an equilibrium
/// (the Hessian of the potential); its symmetric part is used after checking that the
/// antisymmetric part is below 1e-6 of its largest entry (the finite-difference noise is
/// ~1e-12). Throws InvalidArgument naming the largest asymmetry when it is not (follower loads,
/// or a point that is not an equilibrium: use modes(linear.system)).
NormalModes undamped_modes(const LinearModel& linear);

}  // namespace momenta::analysis
