// Uses one function from each of three areas of an installed momenta; prints the results so that
// check_installed_package.sh can compare them with their closed forms.
#include <cstdio>

#include "momenta/dynamics/crba.hpp"
#include "momenta/inertia/primitives.hpp"
#include "momenta/model/model_builder.hpp"

int main() {
  namespace mi = momenta::inertia;
  namespace mm = momenta::model;
  // A 2 kg rod of 1 m on a hinge at its end: M = m L²/3.
  const mi::MassProperties rod = mi::slender_rod(mi::Amount::mass(2.0), 1.0);
  mm::Joint hinge;
  hinge.name = "hinge";
  hinge.type = mm::JointType::revolute;
  hinge.parent = "world";
  hinge.child = "rod";
  hinge.axis = momenta::Vec3::UnitX();
  hinge.X_CJ = momenta::Transform::translation(momenta::Vec3(0, 0, 0.5));
  const mm::Model model = mm::ModelBuilder().add_body("rod", rod).add_joint(hinge).build();
  const momenta::MatX M = momenta::dynamics::mass_matrix(model, model.initial_q());
  std::printf("%.15g\n", M(0, 0));
  return 0;
}
