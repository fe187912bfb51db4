#pragma once
// A free-body diagram drawn: an SVG picture (no scripts, no external references) of one body's
// free-body diagram beside its kinetic diagram (analysis/free_body.hpp), as a textbook draws
// them — what `momenta diagram` writes and the HTML report shows.
//
// Left, the free-body diagram: the body as a rounded outline through its centre of mass G, its
// joints and attachment points; every force an arrow at its point labelled with its name and
// magnitude (a push ends at its point, a pull starts there), every couple a curved arrow (plane)
// or a double-headed arrow (3-D). Right, after "=", the kinetic diagram: m a_G at G and Ī_G α and
// ω × H_G as couples. Underneath, the residuals ΣF − m a_G and ΣM_G − Ḣ_G and a table of every
// load (its components in the world, its point). A planar diagram (FreeBodyDiagram::plane_normal)
// is drawn in its plane, one world axis to the right and one up; otherwise a 3-D projection with
// the world axes drawn.
//
// Structure, for tools and tests: each force is a <g class="force"> and each couple a
// <g class="couple">, with data-name, data-kind (analysis::load_kind_name; "kinetic" on the right)
// and data-value (the magnitude, N or N·m) attributes, holding its <line> or <path>, its arrow
// head and its <text> label. The residuals are <text class="residual">.

#include <span>
#include <string>

#include "momenta/analysis/free_body.hpp"
#include "momenta/io/part_file.hpp"

namespace momenta::report {

/// The SVG document of the diagrams. `title` heads the picture (the model's name). `parts`, the
/// body's parts where its file gives them (io::ModelFile::body_parts), shape its outline: a
/// cone's silhouette is a triangle; without them the outline goes round the box with the body's
/// inertia.
std::string free_body_svg(const analysis::FreeBodyDiagram& diagram, const std::string& title,
                          std::span<const io::PartSummary> parts = {});

}  // namespace momenta::report
