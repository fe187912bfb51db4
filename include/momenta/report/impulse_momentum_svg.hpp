#pragma once
// An impulse–momentum diagram drawn (analysis/impulse_momentum.hpp): an SVG picture (no scripts,
// no external references) of one body at an impact as a textbook draws it (Beer & Johnston
// §17.8) — three panels, the body's momenta before + the impulses on it = its momenta after.
//
// Left, "momenta before": m v̄₁ as an arrow from G and H_G1 = Ī ω₁ as a curved arrow (plane) or a
// double-headed one (3-D) about G. Middle, after "+", "impulses": every impulse an arrow at its
// point (the blow blue, joints' and constraints' impulsive reactions red, a drive's orange),
// impulsive couples curved. Right, after "=", "momenta after": m v̄₂ and H_G2. Momenta and impulses
// share one scale (N·s), so the arrows' lengths compare. Underneath, the residuals of the
// impulse–momentum principle and a table of every impulse. Drawn in the plane of motion where
// there is one, else in 3-D with the world axes.
//
// Structure, for tools and tests: each arrow is a <g class="force"> (momenta and impulses) or a
// <g class="couple"> (angular momenta, impulsive couples) with data-name, data-kind ("kinetic"
// for the momenta; analysis::load_kind_name for the impulses) and data-value (N·s or N·m·s);
// each panel a <g class="panel" data-panel="before|impulses|after">; the residuals
// <text class="residual">.

#include <span>
#include <string>

#include "momenta/analysis/impulse_momentum.hpp"
#include "momenta/io/part_file.hpp"

namespace momenta::report {

/// The SVG document of the diagram. `title` heads the picture (the model's name, the impact).
/// `parts`, the body's parts where its file gives them, shape its outline (as free_body_svg's).
std::string impulse_momentum_svg(const analysis::ImpulseMomentumDiagram& diagram,
                                 const std::string& title,
                                 std::span<const io::PartSummary> parts = {});

}  // namespace momenta::report
