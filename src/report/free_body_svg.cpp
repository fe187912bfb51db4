#include "momenta/report/free_body_svg.hpp"

#include <algorithm>
#include <span>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "diagram_canvas.hpp"

namespace momenta::report {

namespace {

using namespace drawing;

// Page geometry (px): two square panels side by side under a title, the table below.
constexpr double kRightX = kLeftX + kPanel + 80.0;
constexpr double kWidth = kRightX + kPanel + 20.0;

std::string force_label(const Load& load) {
  const std::string name = load.kind == LoadKind::gravity ? "W = m g" : load.name;
  return fmt::format("{} {:.4g} N", name, load.force_W.norm());
}

Scales largest(const FreeBodyDiagram& d) {
  Scales s{d.m_a_G().norm(), std::max(d.I_alpha().norm(), d.w_cross_H().norm())};
  for (const Load& load : d.loads) {
    s.force = std::max(s.force, load.force_W.norm());
    s.moment = std::max(s.moment, load.couple_W.norm());
  }
  return s;
}

void draw_free_body(Canvas& canvas, const Placement& at, const View& view, const FreeBodyDiagram& d,
                    const Scales& scale) {
  LabelBoard labels;
  canvas.body(at, d);
  for (const Load& load : d.loads) {
    const std::string kind = analysis::load_kind_name(load.kind);
    if (load.force_W.norm() > kNegligible * scale.force) {
      canvas.force(at, load.p_WoP_W, d.p_WoG_W, load.force_W,
                   arrow_length(load.force_W.norm(), scale.force), load.name, kind,
                   force_label(load), labels);
    }
    if (load.couple_W.norm() > kNegligible * scale.moment) {
      canvas.couple(at, view, load.p_WoP_W, load.couple_W, 22.0, load.name, kind,
                    fmt::format("{} {:.4g} N·m", load.name, load.couple_W.norm()), labels);
    }
  }
}

void draw_kinetic(Canvas& canvas, const Placement& at, const View& view, const FreeBodyDiagram& d,
                  const Scales& scale) {
  LabelBoard labels;
  canvas.body(at, d);
  const Vec3 ma = d.m_a_G();
  if (ma.norm() > kNegligible * scale.force) {
    // Drawn from G, whichever way it points: it is not a force pushing on the body.
    canvas.force(at, d.p_WoG_W, d.p_WoG_W, ma, arrow_length(ma.norm(), scale.force), "m a_G",
                 "kinetic", fmt::format("m a_G {:.4g} N", ma.norm()), labels);
  }
  if (d.I_alpha().norm() > kNegligible * scale.moment) {
    canvas.couple(at, view, d.p_WoG_W, d.I_alpha(), 24.0, "I_G alpha", "kinetic",
                  fmt::format("Ī α {:.4g} N·m", d.I_alpha().norm()), labels);
  }
  if (d.w_cross_H().norm() > kNegligible * scale.moment) {
    canvas.couple(at, view, d.p_WoG_W, d.w_cross_H(), 36.0, "omega x H_G", "kinetic",
                  fmt::format("ω × H_G {:.4g} N·m", d.w_cross_H().norm()), labels);
  }
  if (ma.norm() <= kNegligible * scale.force && d.H_G_dot().norm() <= kNegligible * scale.moment) {
    canvas.text(at.x0, at.y0 + kPanel / 2 - 40, "0  (the body is in equilibrium)",
                "font-size=\"13\" text-anchor=\"middle\"");
  }
}

}  // namespace

std::string free_body_svg(const FreeBodyDiagram& d, const std::string& title,
                          std::span<const io::PartSummary> parts) {
  const View view = make_view(d);
  const std::vector<Vec3> outline = body_points(d, d.loads, parts);
  const Scales scale = largest(d);
  Canvas canvas(kWidth, page_height(d.loads.size()));
  canvas.text(kLeftX, 24, fmt::format("{} — body {} at t = {:.6g} s", title, d.body, d.t),
              "font-size=\"16\" font-weight=\"bold\"");
  canvas.text(kLeftX, 44, view.caption, "font-size=\"12\" fill=\"#555\"");
  canvas.text(kLeftX + kPanel / 2, kPanelTop - 4, "free-body diagram",
              "font-size=\"13\" text-anchor=\"middle\"");
  canvas.text(kRightX + kPanel / 2, kPanelTop - 4, "kinetic diagram",
              "font-size=\"13\" text-anchor=\"middle\"");
  canvas.svg() += fmt::format(
      "<rect x=\"{:.0f}\" y=\"{:.0f}\" width=\"{:.0f}\" height=\"{:.0f}\" fill=\"none\" "
      "stroke=\"#ddd\"/><rect x=\"{:.0f}\" y=\"{:.0f}\" width=\"{:.0f}\" height=\"{:.0f}\" "
      "fill=\"none\" stroke=\"#ddd\"/>\n",
      kLeftX, kPanelTop, kPanel, kPanel, kRightX, kPanelTop, kPanel, kPanel);
  canvas.text((kLeftX + kPanel + kRightX) / 2, kPanelTop + kPanel / 2 + 10, "=",
              "font-size=\"32\" text-anchor=\"middle\"");

  canvas.keep_labels_within(kLeftX + 4.0, kLeftX + kPanel - 4.0);
  draw_free_body(canvas, place(view, outline, d, kLeftX), view, d, scale);
  canvas.keep_labels_within(kRightX + 4.0, kRightX + kPanel - 4.0);
  draw_kinetic(canvas, place(view, outline, d, kRightX), view, d, scale);
  canvas.keep_labels_within(4.0, kWidth - 4.0);
  canvas.axes(view, kLeftX + 30, kPanelTop + kPanel - 30);
  canvas.axes(view, kRightX + 30, kPanelTop + kPanel - 30);

  const Vec3 rf = d.force_residual(), rm = d.moment_residual();
  canvas.text(kLeftX, kPanelTop + kPanel + 22,
              fmt::format("ΣF − m a_G = {} N   (|·| = {:.2e} N of {:.4g} N)", vector_text(rf),
                          rf.norm(), scale.force),
              "class=\"residual\" font-size=\"12\"");
  canvas.text(kLeftX, kPanelTop + kPanel + 40,
              fmt::format("ΣM_G − Ḣ_G = {} N·m   (|·| = {:.2e} N·m of {:.4g} N·m)", vector_text(rm),
                          rm.norm(), std::max(scale.moment, d.sum_of_moments_about_G().norm())),
              "class=\"residual\" font-size=\"12\"");
  table(canvas, d.loads, scale, kTableTop, "load", "N", "N·m");
  canvas.svg() += "</svg>\n";
  return canvas.svg();
}

}  // namespace momenta::report
