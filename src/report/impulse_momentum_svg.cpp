#include "momenta/report/impulse_momentum_svg.hpp"

#include <algorithm>
#include <span>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "diagram_canvas.hpp"

namespace momenta::report {

namespace {

using analysis::ImpulseMomentumDiagram;
using namespace drawing;

// Page geometry (px): three square panels side by side, "+" and "=" between them.
constexpr double kPanelGap = 70.0;
constexpr double kImpulsesX = kLeftX + kPanel + kPanelGap;
constexpr double kAfterX = kImpulsesX + kPanel + kPanelGap;
constexpr double kImpulsePageWidth = kAfterX + kPanel + 20.0;

// The body as the drawing helpers take it: its pose, inertia and plane, the impulses as loads.
Scales largest_momenta(const ImpulseMomentumDiagram& d) {
  Scales s{std::max(d.linear_before().norm(), d.linear_after().norm()),
           std::max(d.angular_before().norm(), d.angular_after().norm())};
  for (const Load& impulse : d.impulses) {
    s.force = std::max(s.force, impulse.force_W.norm());
    s.moment = std::max(s.moment, impulse.couple_W.norm());
  }
  return s;
}

// One side's momenta: m v̄ from G, H_G about G; "0 (at rest)" where both are negligible.
void draw_momenta(Canvas& canvas, const Placement& at, const View& view,
                  const ImpulseMomentumDiagram& d, const Vec3& linear, const Vec3& angular,
                  const std::string& when, const std::string& index, const Scales& scale) {
  LabelBoard labels;
  canvas.body(at, d);
  const Vec3& G = d.p_WoG_W;
  const bool moving = linear.norm() > kNegligible * scale.force;
  const bool turning = angular.norm() > kNegligible * scale.moment;
  if (moving) {
    canvas.force(at, G, G, linear, arrow_length(linear.norm(), scale.force), "m v_G " + when,
                 "kinetic", fmt::format("m v̄{} {:.4g} N·s", index, linear.norm()), labels);
  }
  if (turning) {
    canvas.couple(at, view, G, angular, 30.0, "H_G " + when, "kinetic",
                  fmt::format("H_G{} = Ī ω{} {:.4g} N·m·s", index, index, angular.norm()), labels);
  }
  if (!moving && !turning) {
    canvas.text(at.x0, at.y0 + kPanel / 2 - 40, "0  (at rest)",
                "font-size=\"13\" text-anchor=\"middle\"");
  }
}

void draw_impulses(Canvas& canvas, const Placement& at, const View& view,
                   const ImpulseMomentumDiagram& d, const Scales& scale) {
  LabelBoard labels;
  canvas.body(at, d);
  for (const Load& impulse : d.impulses) {
    const std::string kind = analysis::load_kind_name(impulse.kind);
    if (impulse.force_W.norm() > kNegligible * scale.force) {
      // A push ends at its point; one at G (a particle's) is drawn as the push it is.
      const bool at_G = (impulse.p_WoP_W - d.p_WoG_W).norm() * at.scale < 1.0;
      const Vec3 toward = at_G ? Vec3(impulse.p_WoP_W + impulse.force_W) : d.p_WoG_W;
      canvas.force(at, impulse.p_WoP_W, toward, impulse.force_W,
                   arrow_length(impulse.force_W.norm(), scale.force), impulse.name, kind,
                   fmt::format("{} {:.4g} N·s", impulse.name, impulse.force_W.norm()), labels);
    }
    if (impulse.couple_W.norm() > kNegligible * scale.moment) {
      canvas.couple(at, view, impulse.p_WoP_W, impulse.couple_W, 22.0, impulse.name, kind,
                    fmt::format("{} {:.4g} N·m·s", impulse.name, impulse.couple_W.norm()), labels);
    }
  }
}

}  // namespace

std::string impulse_momentum_svg(const ImpulseMomentumDiagram& d, const std::string& title,
                                 std::span<const io::PartSummary> parts) {
  const View view = make_view(d);
  const std::vector<Vec3> outline = body_points(d, d.impulses, parts);
  const Scales scale = largest_momenta(d);
  Canvas canvas(kImpulsePageWidth, page_height(d.impulses.size()));
  canvas.text(kLeftX, 24, fmt::format("{} — body {} at t = {:.6g} s", title, d.body, d.t),
              "font-size=\"16\" font-weight=\"bold\"");
  canvas.text(kLeftX, 44,
              fmt::format("impulse and momentum: m v̄₁ + Σ P = m v̄₂, H_G1 + Σ M_G = H_G2 — {}",
                          view.caption),
              "font-size=\"12\" fill=\"#555\"");
  const struct {
    double x;
    const char* name;
    const char* heading;
  } panels[] = {{kLeftX, "before", "momenta just before"},
                {kImpulsesX, "impulses", "impulses on the body"},
                {kAfterX, "after", "momenta just after"}};
  for (const auto& panel : panels) {
    canvas.text(panel.x + kPanel / 2, kPanelTop - 4, panel.heading,
                "font-size=\"13\" text-anchor=\"middle\"");
    canvas.svg() += fmt::format(
        "<rect x=\"{:.0f}\" y=\"{:.0f}\" width=\"{:.0f}\" height=\"{:.0f}\" fill=\"none\" "
        "stroke=\"#ddd\"/>\n",
        panel.x, kPanelTop, kPanel, kPanel);
  }
  canvas.text(kLeftX + kPanel + kPanelGap / 2, kPanelTop + kPanel / 2 + 10, "+",
              "font-size=\"32\" text-anchor=\"middle\"");
  canvas.text(kImpulsesX + kPanel + kPanelGap / 2, kPanelTop + kPanel / 2 + 10, "=",
              "font-size=\"32\" text-anchor=\"middle\"");

  const auto panel_group = [&](const char* name, double x, auto&& draw) {
    canvas.svg() += fmt::format("<g class=\"panel\" data-panel=\"{}\">\n", name);
    canvas.keep_labels_within(x + 4.0, x + kPanel - 4.0);
    draw();
    canvas.svg() += "</g>\n";
  };
  panel_group("before", kLeftX, [&] {
    draw_momenta(canvas, place(view, outline, d, kLeftX), view, d, d.linear_before(),
                 d.angular_before(), "before", "₁", scale);
  });
  panel_group("impulses", kImpulsesX,
              [&] { draw_impulses(canvas, place(view, outline, d, kImpulsesX), view, d, scale); });
  panel_group("after", kAfterX, [&] {
    draw_momenta(canvas, place(view, outline, d, kAfterX), view, d, d.linear_after(),
                 d.angular_after(), "after", "₂", scale);
  });
  canvas.keep_labels_within(4.0, kImpulsePageWidth - 4.0);
  for (const auto& panel : panels) canvas.axes(view, panel.x + 30, kPanelTop + kPanel - 30);

  const Vec3 rl = d.linear_residual(), ra = d.angular_residual();
  canvas.text(kLeftX, kPanelTop + kPanel + 22,
              fmt::format("m v̄₁ + Σ P − m v̄₂ = {} N·s   (|·| = {:.2e} N·s of {:.4g} N·s)",
                          vector_text(rl), rl.norm(), scale.force),
              "class=\"residual\" font-size=\"12\"");
  canvas.text(kLeftX, kPanelTop + kPanel + 40,
              fmt::format("H_G1 + Σ M_G − H_G2 = {} N·m·s   (|·| = {:.2e} N·m·s of {:.4g} N·m·s)",
                          vector_text(ra), ra.norm(),
                          std::max(scale.moment, d.sum_of_moments_about_G().norm())),
              "class=\"residual\" font-size=\"12\"");
  table(canvas, d.impulses, scale, kTableTop, "impulse", "N·s", "N·m·s");
  canvas.svg() += "</svg>\n";
  return canvas.svg();
}

}  // namespace momenta::report
