// Impulse–momentum diagrams (analysis/impulse_momentum.hpp) against Beer & Johnston's closed
// forms (ch. 17):
//  - the eccentric impact of examples/eccentric_impact.yaml (a 0.5 kg sphere at 3 m/s strikes the
//    hanging 4 kg, 1.2 m rod 1.1 m below its pin, e = 0.6): the rod at rest before, the contact's
//    impulse m_s (v0 − v_s) and the pin's R = m ω L/2 − m_s (v0 − v_s) on it, m v̄₂ = m ω L/2 and
//    H_G2 = (m L²/12) ω after; the sphere's m_s v0, −P and m_s v_s; both diagrams planar (y);
//  - the rod of examples/struck_rod.yaml struck at its centre of percussion (2L/3 below the pin):
//    no impulse at the pin;
//  - every diagram balances: m v̄₁ + Σ P = m v̄₂ and H_G1 + Σ M_G = H_G2 to round-off;
//  - the world and an unknown body refused.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/analysis/impulse_momentum.hpp"
#include "momenta/common/error.hpp"
#include "momenta/io/model_file.hpp"

namespace momenta {
namespace {

using analysis::ImpulseMomentumDiagram;
using analysis::Load;
using analysis::LoadKind;

// The diagram's largest momentum or impulse (N·s) and angular momentum or moment (N·m·s).
double linear_scale(const ImpulseMomentumDiagram& d) {
  double s = std::max(d.linear_before().norm(), d.linear_after().norm());
  for (const Load& p : d.impulses) s = std::max(s, p.force_W.norm());
  return s;
}

void expect_balanced(const ImpulseMomentumDiagram& d) {
  const double scale = linear_scale(d);
  // Sums of a few products of the impulse solution: round-off of the largest.
  EXPECT_LT(d.linear_residual().norm(), 1e-14 * scale) << d.body;
  EXPECT_LT(d.angular_residual().norm(), 1e-14 * scale * 1.2) << d.body;  // levers ≤ 1.2 m
}

const Load* find(const ImpulseMomentumDiagram& d, const std::string& name) {
  for (const Load& p : d.impulses) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

struct EccentricImpact {
  io::ModelFile file = io::read_model_file("examples/eccentric_impact.yaml");
  dynamics::PointContact contact;
  dynamics::Impact impact;
  std::vector<dynamics::PointImpulse> blow;

  EccentricImpact() {
    const model::Model& m = file.model;
    contact = {m.body_index("sphere"), Vec3::Zero(), m.body_index("rod"), Vec3(0, 0, -1.1),
               Vec3::UnitX()};
    impact = dynamics::restitution_impact(m, m.initial_q(), m.initial_v(), contact, 0.6);
    blow = {{contact.body_b, contact.p_BoPb_B, impact.normal_impulse * contact.normal_W},
            {contact.body_a, contact.p_AoPa_A, -impact.normal_impulse * contact.normal_W}};
  }
  ImpulseMomentumDiagram diagram(const std::string& body) const {
    return analysis::impulse_momentum_diagram(file.model, body, 0.0, file.model.initial_q(),
                                              impact.motion, blow, "contact impulse");
  }
};

TEST(ImpulseMomentumDiagram, EccentricImpactOnTheRodAsTheTextbookDrawsIt) {
  const double m = 4.0, L = 1.2, ms = 0.5, v0 = 3.0, d = 1.1, e = 0.6;
  const double I_O = m * L * L / 3;
  const double w = ms * v0 * d * (1 + e) / (I_O + ms * d * d);
  const double vs = v0 * (ms * d * d - e * I_O) / (I_O + ms * d * d);
  const double P = ms * (v0 - vs), R = m * w * L / 2 - P;
  const EccentricImpact impact;
  const ImpulseMomentumDiagram rod = impact.diagram("rod");
  EXPECT_EQ(rod.linear_before().norm(), 0.0);  // at rest before
  EXPECT_EQ(rod.angular_before().norm(), 0.0);
  ASSERT_EQ(rod.impulses.size(), 2u);
  const Load* hit = find(rod, "contact impulse");
  const Load* pin = find(rod, "pin");
  ASSERT_NE(hit, nullptr);
  ASSERT_NE(pin, nullptr);
  EXPECT_EQ(hit->kind, LoadKind::applied);
  EXPECT_EQ(pin->kind, LoadKind::reaction);
  EXPECT_EQ(pin->description, "impulsive reaction of joint pin (from world)");
  // The closed forms to their own round-off (a few products of 1e-16).
  EXPECT_LT((hit->force_W - P * Vec3::UnitX()).norm(), 1e-14 * P);
  EXPECT_LT((hit->p_WoP_W - Vec3(0, 0, -d)).norm(), 1e-15);
  EXPECT_LT((pin->force_W - R * Vec3::UnitX()).norm(), 1e-14 * P);
  EXPECT_LT(pin->p_WoP_W.norm(), 1e-15);       // at the pin
  EXPECT_LT(pin->couple_W.norm(), 1e-14 * P);  // a pin carries no impulsive couple about y
  EXPECT_LT((rod.linear_after() - m * w * L / 2 * Vec3::UnitX()).norm(), 1e-14 * P);
  // The rod turns about −y (the struck end moves along +x): H_G2 = −(m L²/12) ω y.
  EXPECT_LT((rod.angular_after() + m * L * L / 12 * w * Vec3::UnitY()).norm(), 1e-14 * P);
  ASSERT_TRUE(rod.plane_normal.has_value());
  EXPECT_NEAR(std::abs(rod.plane_normal->y()), 1.0, 1e-15);
  expect_balanced(rod);

  const ImpulseMomentumDiagram sphere = impact.diagram("sphere");
  EXPECT_LT((sphere.linear_before() - ms * v0 * Vec3::UnitX()).norm(), 1e-15);
  const Load* back = find(sphere, "contact impulse");
  ASSERT_NE(back, nullptr);
  EXPECT_LT((back->force_W + P * Vec3::UnitX()).norm(), 1e-14 * P);
  EXPECT_LT((sphere.linear_after() - ms * vs * Vec3::UnitX()).norm(), 1e-14 * P);
  expect_balanced(sphere);
}

TEST(ImpulseMomentumDiagram, TheCentreOfPercussionTakesNoImpulseAtThePin) {
  const io::ModelFile file = io::read_model_file("examples/struck_rod.yaml");
  const model::Model& model = file.model;
  const int rod = model.body_index("rod");
  // struck_rod.yaml: a 1.2 m rod hanging from its pin; 2L/3 = 0.8 m below it, 4 N·s along x.
  const std::vector<dynamics::PointImpulse> blow{{rod, Vec3(0, 0, -0.8), Vec3(4, 0, 0)}};
  const dynamics::ImpulsiveMotion motion =
      dynamics::impulsive_motion(model, model.initial_q(), model.initial_v(), blow);
  const ImpulseMomentumDiagram d = analysis::impulse_momentum_diagram(
      model, "rod", 0.0, model.initial_q(), motion, blow, "applied impulse");
  const Load* pin = find(d, "pin");
  ASSERT_NE(pin, nullptr);
  EXPECT_LT(pin->force_W.norm(), 1e-14 * 4.0);
  EXPECT_LT((d.linear_after() - Vec3(4, 0, 0)).norm(), 1e-14 * 4.0);  // the blow alone
  expect_balanced(d);
}

TEST(ImpulseMomentumDiagram, TheWorldAndUnknownBodiesAreRefused) {
  const EccentricImpact impact;
  EXPECT_THROW(impact.diagram("world"), InvalidArgument);
  try {
    impact.diagram("rdo");
    FAIL() << "an unknown body accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("rod"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace momenta
