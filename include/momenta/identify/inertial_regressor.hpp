#pragma once
// The joint-force regressor of a tree: τ = Y(q, v, v̇) π, linear in the bodies' inertial
// parameters π (inertial_parameters.hpp) — the classical route to a robot's inertia from
// measured motion and joint forces (Atkeson, An & Hollerbach 1986; Khalil & Dombre 2002, §12.3).
//
// Y is nv × 10 (num_bodies − 1). Column block b is body b's share: the net wrench body b needs,
// F_b = I_b A_b + V_b ×* I_b V_b (gravity entering as the base's upward acceleration, as in
// RNEA), is linear in its ten, F_b = K_b(V_b, A_b) π_b; joint j feels the bodies its child
// carries, Y(j, b) = S_jᵀ ʲX_b* K_b for b in the subtree of j's child (zero otherwise).
// What Y π leaves out is the rotors' reflected inertia (Joint::armature), which is not a body's:
//   rnea(q, v, v̇) = Y π + armature ∘ v̇   (tested to round-off on random trees of every joint).

#include "momenta/dynamics/data.hpp"
#include "momenta/identify/inertial_parameters.hpp"

namespace momenta::identify {

/// Y at one state, with a workspace of its own: construct once per model (and thread), then
/// compute() does not allocate. Sizes are checked: q nq, v and v̇ nv (InvalidArgument).
class InertialRegressor {
 public:
  explicit InertialRegressor(const Model& model);

  /// Y(q, v, v̇), nv × num_inertial_parameters(model); valid until the next call.
  const MatX& compute(VecRef q, VecRef v, VecRef vdot);

  /// The rotors' share τ_a = armature ∘ v̇ (size nv) that Y π leaves out.
  VecX armature_torque(VecRef vdot) const;

  const Model& model() const { return model_; }

 private:
  const Model& model_;
  dynamics::Data data_;
  MatX Y_;
};

/// Allocating convenience form.
MatX inertial_regressor(const Model& model, VecRef q, VecRef v, VecRef vdot);

}  // namespace momenta::identify
