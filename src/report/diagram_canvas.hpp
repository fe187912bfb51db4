#pragma once
// Internal to momenta::report: what the SVG diagrams of a body share — the free-body and
// kinetic diagrams (free_body_svg.hpp) and the impulse–momentum diagram
// (impulse_momentum_svg.hpp): the view of the body (its plane of motion, or a 3-D projection),
// its placement in a panel, its outline, force and couple arrows with labels kept apart, and
// the table of what acts on it.

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include "momenta/analysis/free_body.hpp"
#include "momenta/common/number_text.hpp"
#include "momenta/io/part_file.hpp"
#include "page_data.hpp"

namespace momenta::report::drawing {

using analysis::DiagramBody;
using analysis::FreeBodyDiagram;
using analysis::Load;
using analysis::LoadKind;
using Vec2 = Eigen::Vector2d;

// Page geometry (px): square panels side by side under a title, the table below.
constexpr double kPanel = 460.0;
constexpr double kLeftX = 20.0;
constexpr double kPanelTop = 70.0;
constexpr double kArrowRoom = 100.0;  // kept free around the body for arrows and labels
constexpr double kShortest = 28.0, kLongest = 85.0;  // arrow lengths, by magnitude
constexpr double kRowHeight = 16.0;
constexpr double kCharWidth = 6.6;  // of the 12 px label font, for placing labels apart
constexpr double kTableTop = kPanelTop + kPanel + 64.0;  // under the panels and the residuals

// The page's height with a table of `rows` loads under the panels.
inline double page_height(std::size_t rows) {
  return kTableTop + kRowHeight * static_cast<double>(rows + 1) + 12.0;
}

// Below this fraction of the largest force (or moment) a vector is not drawn (it is listed).
constexpr double kNegligible = 1e-9;

inline const char* colour(const std::string& kind) {
  if (kind == "gravity") return "#2e7d32";
  if (kind == "reaction") return "#c62828";
  if (kind == "element") return "#6a1b9a";
  if (kind == "applied") return "#1565c0";
  if (kind == "drive") return "#ef6c00";
  return "#37474f";  // kinetic
}

inline std::string vector_text(const Vec3& v) {
  return fmt::format("[{:.6g}, {:.6g}, {:.6g}]", v.x(), v.y(), v.z());
}

// The components, round-off against `scale` written 0 (shown_value: the CLI's rule).
inline std::string chopped_text(const Vec3& v, double scale) {
  return vector_text(v.unaryExpr([&](double x) { return shown_value(x, scale); }));
}

// World → screen directions: `right` and `up` span the picture; `out` points at the viewer.
struct View {
  Vec3 right, up, out;
  bool planar = false;
  std::string caption;

  Vec2 project(const Vec3& v) const { return {v.dot(right), v.dot(up)}; }
};

inline const char* axis_name(int k) { return k == 0 ? "x" : k == 1 ? "y" : "z"; }

inline View make_view(const DiagramBody& d) {
  View view;
  if (d.plane_normal) {
    const Vec3 n = *d.plane_normal;
    view.planar = true;
    // A world axis as the normal: the other two to the right and up, in the order x, y, z
    // (x right and z up for the x–z plane, the textbooks' choice).
    for (int k = 0; k < 3; ++k) {
      if (std::abs(std::abs(n[k]) - 1.0) > 1e-12) continue;
      const int a = k == 0 ? 1 : 0, b = k == 2 ? 1 : 2;
      view.right = Vec3::Unit(a);
      view.up = Vec3::Unit(b);
      view.out = view.right.cross(view.up);
      view.caption = fmt::format(
          "in the plane of motion, world {}–{} ({} out of the page)", axis_name(a), axis_name(b),
          view.out[k] > 0 ? std::string("+") + axis_name(k) : std::string("−") + axis_name(k));
      return view;
    }
    // A tilted plane: the world's z (or y) projected onto it points up.
    Vec3 up = Vec3::UnitZ() - n.z() * n;
    if (up.norm() < 1e-6) up = Vec3::UnitY() - n.y() * n;
    view.up = up.normalized();
    view.right = view.up.cross(n);
    view.out = n;
    view.caption = fmt::format("in the plane of motion, normal {} out of the page", vector_text(n));
    return view;
  }
  // 3-D: seen from azimuth −55°, elevation 25°, world z up.
  const double az = -55.0 * std::numbers::pi / 180.0, el = 25.0 * std::numbers::pi / 180.0;
  const Vec3 camera(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  const Vec3 forward = -camera;
  view.right = forward.cross(Vec3::UnitZ()).normalized();
  view.up = view.right.cross(forward);
  view.out = camera;
  view.caption = "3-D view (world axes drawn)";
  return view;
}

// Panel placement: world points → page coordinates, the body fitted in the middle of a panel.
struct Placement {
  const View* view;
  Vec3 origin;                       // world point at the panel's centre
  double scale;                      // px per m
  double x0, y0;                     // the panel's centre on the page
  const std::vector<Vec3>* outline;  // the points the body's outline goes round (body_points)

  Vec2 at(const Vec3& p) const {
    const Vec2 s = view->project(p - origin) * scale;
    return {x0 + s.x(), y0 - s.y()};
  }
  // A world direction on the page (y down), not normalized.
  Vec2 direction(const Vec3& v) const {
    const Vec2 s = view->project(v);
    return {s.x(), -s.y()};
  }
};

// The corners of the body's equivalent uniform box: the box of the same mass and central
// inertia (half-sides a_k with a_1² = 3 (I_2 + I_3 − I_1) / 2m, ...), along the principal axes
// — a rod's segment, a disc's square, nothing for a point mass.
inline std::vector<Vec3> equivalent_box(const DiagramBody& d) {
  if (d.mass <= 0.0) return {};
  const Eigen::SelfAdjointEigenSolver<Mat3> principal(d.I_G_W);
  const Vec3 I = principal.eigenvalues();
  Vec3 half;
  for (int k = 0; k < 3; ++k) {
    const double sum = I.sum() - 2.0 * I[k];  // I_j + I_l − I_k
    half[k] = std::sqrt(std::max(0.0, 1.5 * sum / d.mass));
  }
  std::vector<Vec3> corners;
  for (int c = 0; c < 8; ++c) {
    const Vec3 s((c & 1) ? 1.0 : -1.0, (c & 2) ? 1.0 : -1.0, (c & 4) ? 1.0 : -1.0);
    corners.push_back(d.p_WoG_W + principal.eigenvectors() * s.cwiseProduct(half));
  }
  return corners;
}

// What the outline of the body goes round: G, the points loads act at, and its parts' surface
// points (page_data.hpp) placed in the world, or its equivalent box where it has no parts.
inline std::vector<Vec3> body_points(const DiagramBody& d, std::span<const Load> loads,
                                     std::span<const io::PartSummary> parts) {
  std::vector<Vec3> points = {d.p_WoG_W};
  for (const Load& load : loads) points.push_back(load.p_WoP_W);
  std::vector<Vec3> surface;
  for (const io::PartSummary& part : parts) {
    for (const Vec3& p_BoP_B : detail::part_outline_points(part))
      surface.push_back(d.p_WoBo_W + d.R_WB * p_BoP_B);
  }
  if (surface.empty()) surface = equivalent_box(d);
  points.insert(points.end(), surface.begin(), surface.end());
  return points;
}

inline Placement place(const View& view, const std::vector<Vec3>& outline, const DiagramBody& d,
                       double panel_x) {
  Vec2 lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const Vec3& p : outline) {
    lo = lo.cwiseMin(view.project(p));
    hi = hi.cwiseMax(view.project(p));
  }
  const Vec2 centre = 0.5 * (lo + hi);
  const double extent = std::max((hi - lo).maxCoeff(), 1e-300);
  const double room = kPanel - 2.0 * kArrowRoom;
  // Where the centre is in the world: the point G plus the offset in the view's plane.
  const Vec2 g = view.project(d.p_WoG_W);
  const Vec3 origin =
      d.p_WoG_W + (centre.x() - g.x()) * view.right + (centre.y() - g.y()) * view.up;
  const double scale = (hi - lo).maxCoeff() > 0 ? room / extent : 1.0;
  return {&view, origin, scale, panel_x + kPanel / 2, kPanelTop + kPanel / 2, &outline};
}

// Labels placed so that they do not overlap: each new one moves down until it is clear.
class LabelBoard {
 public:
  Vec2 place(Vec2 anchor, double width, bool to_left) {
    for (int tries = 0; tries < 12; ++tries) {
      const double left = to_left ? anchor.x() - width : anchor.x();
      const bool clear = std::none_of(boxes_.begin(), boxes_.end(), [&](const Box& b) {
        return left < b.right && left + width > b.left && anchor.y() - 12 < b.bottom &&
               anchor.y() + 3 > b.top;
      });
      if (clear) {
        boxes_.push_back({left, left + width, anchor.y() - 12, anchor.y() + 3});
        return anchor;
      }
      anchor.y() += 14.0;
    }
    return anchor;
  }

 private:
  struct Box {
    double left, right, top, bottom;
  };
  std::vector<Box> boxes_;
};

inline Vec2 clamp_to_page(Vec2 p, double width, double height) {
  return {std::clamp(p.x(), 4.0, width - 4.0), std::clamp(p.y(), 14.0, height - 4.0)};
}

class Canvas {
 public:
  // A white page of width × height px.
  Canvas(double width, double height)
      : width_(width), height_(height), left_(4.0), right_(width - 4.0) {
    svg_ = fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.0f}\" height=\"{1:.0f}\" "
        "viewBox=\"0 0 {0:.0f} {1:.0f}\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n"
        "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
        width, height);
  }

  // Labels drawn from now on turn to the other side rather than run out of [left, right] (a
  // panel), as far as they can; the page's edges by default.
  void keep_labels_within(double left, double right) {
    left_ = left;
    right_ = right;
  }

  std::string& svg() { return svg_; }

  void body(const Placement& at, const DiagramBody& d) {
    // The outline: a thick rounded stroke through the body's points (their convex hull), a
    // capsule for two points, a disc for one.
    std::vector<Vec2> points;
    for (const Vec3& p : *at.outline) points.push_back(at.at(p));
    const std::vector<Vec2> hull = convex_hull(points);
    std::string path;
    for (std::size_t i = 0; i < hull.size(); ++i)
      path += fmt::format("{}{:.1f},{:.1f} ", i == 0 ? "M" : "L", hull[i].x(), hull[i].y());
    svg_ += fmt::format(
        "<path class=\"body\" d=\"{}Z\" fill=\"#cfd8dc\" stroke=\"#cfd8dc\" stroke-width=\"22\" "
        "stroke-linejoin=\"round\" stroke-linecap=\"round\"/>\n",
        path);
    // G: the centre-of-mass symbol, quarters filled.
    const Vec2 g = at.at(d.p_WoG_W);
    svg_ += fmt::format(
        "<g class=\"centre-of-mass\"><circle cx=\"{0:.1f}\" cy=\"{1:.1f}\" r=\"6\" fill=\"white\" "
        "stroke=\"black\"/><path d=\"M{0:.1f},{1:.1f} l6,0 a6,6 0 0,1 -6,6 Z M{0:.1f},{1:.1f} "
        "l-6,0 a6,6 0 0,1 6,-6 Z\" fill=\"black\"/><text x=\"{2:.1f}\" y=\"{3:.1f}\" "
        "font-size=\"12\">G</text></g>\n",
        g.x(), g.y(), g.x() + 8, g.y() - 8);
  }

  // A force arrow of `length` px at the point: ending there when it pushes toward G, starting
  // there otherwise.
  void force(const Placement& at, const Vec3& point, const Vec3& pushes_toward, const Vec3& f,
             double length, const std::string& name, const std::string& kind,
             const std::string& label, LabelBoard& labels) {
    Vec2 dir = at.direction(f.normalized());
    // Seen end-on in 3-D a force is drawn short, not as a dot.
    const double shown = std::max(dir.norm(), 0.25);
    dir = dir.norm() > 1e-9 ? Vec2(dir.normalized()) : Vec2(0, -1);
    const Vec2 p = at.at(point);
    const bool push = f.dot(pushes_toward - point) > 0.0;
    const Vec2 tail = push ? Vec2(p - dir * length * shown) : p;
    const Vec2 head = push ? p : Vec2(p + dir * length * shown);
    const Vec2 free_end = push ? tail : head;
    const char* c = colour(kind);
    svg_ += fmt::format(
        "<g class=\"force\" data-name=\"{}\" data-kind=\"{}\" data-value=\"{:.17g}\">"
        "<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" "
        "stroke-width=\"2.2\"/>{}",
        detail::escape_html(name), kind, f.norm(), tail.x(), tail.y(), head.x(), head.y(), c,
        arrow_head(head, dir, c));
    // The label beyond the free end, on the side the arrow points away from the body.
    const Vec2 outward = push ? Vec2(-dir) : dir;
    text_at(free_end + outward * 6.0, outward.x() < -0.2, label, c, labels);
    svg_ += "</g>\n";
  }

  // A couple: a curved arrow about the point (plane: counter-clockwise when it points out of
  // the page) or a double-headed arrow along it (3-D).
  void couple(const Placement& at, const View& view, const Vec3& point, const Vec3& m, double size,
              const std::string& name, const std::string& kind, const std::string& label,
              LabelBoard& labels) {
    const char* c = colour(kind);
    const Vec2 p = at.at(point);
    svg_ +=
        fmt::format("<g class=\"couple\" data-name=\"{}\" data-kind=\"{}\" data-value=\"{:.17g}\">",
                    detail::escape_html(name), kind, m.norm());
    if (view.planar) {
      const double r = size;
      const bool ccw = m.dot(view.out) > 0.0;
      // Three quarters of a turn between −45° and 225° (angles counter-clockwise on the page),
      // the head at the end: SVG's sweep flag 0 turns counter-clockwise on the page.
      const double a0 = (ccw ? -45.0 : 225.0) * std::numbers::pi / 180.0;
      const double a1 = (ccw ? 225.0 : -45.0) * std::numbers::pi / 180.0;
      const Vec2 s = p + r * Vec2(std::cos(a0), -std::sin(a0));
      const Vec2 e = p + r * Vec2(std::cos(a1), -std::sin(a1));
      svg_ += fmt::format(
          "<path d=\"M{:.1f},{:.1f} A{:.1f},{:.1f} 0 1,{} {:.1f},{:.1f}\" fill=\"none\" "
          "stroke=\"{}\" stroke-width=\"2.2\"/>",
          s.x(), s.y(), r, r, ccw ? 0 : 1, e.x(), e.y(), c);
      // The tangent at the end, in the sense of travel.
      const Vec2 tangent =
          ccw ? Vec2(-std::sin(a1), -std::cos(a1)) : Vec2(std::sin(a1), std::cos(a1));
      svg_ += arrow_head(e, tangent.normalized(), c);
      text_at(p + Vec2(r + 6.0, r * 0.8), false, label, c, labels);
    } else {
      Vec2 dir = at.direction(m.normalized());
      const double shown = std::max(dir.norm(), 0.25);
      dir = dir.norm() > 1e-9 ? Vec2(dir.normalized()) : Vec2(0, -1);
      const Vec2 head = p + dir * size * 1.6 * shown;
      svg_ += fmt::format(
          "<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" "
          "stroke-width=\"2.2\"/>{}{}",
          p.x(), p.y(), head.x(), head.y(), c, arrow_head(head, dir, c),
          arrow_head(head - dir * 9.0, dir, c));
      text_at(head + dir * 6.0, dir.x() < -0.2, label, c, labels);
    }
    svg_ += "</g>\n";
  }

  void text(double x, double y, const std::string& content, const std::string& attributes = "") {
    const Vec2 p = clamp_to_page({x, y}, width_, height_);
    svg_ += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" {}>{}</text>\n", p.x(), p.y(), attributes,
                        detail::escape_html(content));
  }

  void axes(const View& view, double x, double y) {
    svg_ += "<g class=\"axes\">";
    for (int k = 0; k < 3; ++k) {
      const Vec2 d = Vec2(Vec3::Unit(k).dot(view.right), -Vec3::Unit(k).dot(view.up)) * 30.0;
      if (d.norm() < 3.0) continue;  // the axis out of the page
      svg_ += fmt::format(
          "<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#555\"/>"
          "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"11\" fill=\"#555\">{}</text>",
          x, y, x + d.x(), y + d.y(), x + d.x() * 1.25 - 3, y + d.y() * 1.25 + 4, axis_name(k));
    }
    svg_ += "</g>\n";
  }

 private:
  static std::string arrow_head(const Vec2& tip, const Vec2& dir, const char* c) {
    const Vec2 normal(-dir.y(), dir.x());
    const Vec2 a = tip - dir * 10.0 + normal * 4.5, b = tip - dir * 10.0 - normal * 4.5;
    return fmt::format(
        "<polygon points=\"{:.1f},{:.1f} {:.1f},{:.1f} {:.1f},{:.1f}\" fill=\"{}\"/>", tip.x(),
        tip.y(), a.x(), a.y(), b.x(), b.y(), c);
  }

  void text_at(Vec2 anchor, bool to_left, const std::string& label, const char* c,
               LabelBoard& labels) {
    const double width = kCharWidth * static_cast<double>(label.size());
    anchor.y() += 4.0;
    // Kept within the panel: a label that would run past its edge is set against the edge,
    // under the line it labels (not turned back across its arrow).
    if (!to_left && anchor.x() + width > right_) {
      to_left = true;
      anchor = {right_, anchor.y() + 16.0};
    } else if (to_left && anchor.x() - width < left_) {
      to_left = false;
      anchor = {left_, anchor.y() + 16.0};
    }
    anchor = labels.place(anchor, width, to_left);
    anchor = clamp_to_page(anchor, width_, height_);
    svg_ += fmt::format(
        "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"12\" fill=\"{}\" text-anchor=\"{}\">{}</text>",
        anchor.x(), anchor.y(), c, to_left ? "end" : "start", detail::escape_html(label));
  }

  static std::vector<Vec2> convex_hull(std::vector<Vec2> points) {
    // Andrew's monotone chain.
    std::sort(points.begin(), points.end(), [](const Vec2& a, const Vec2& b) {
      return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    });
    points.erase(std::unique(points.begin(), points.end(),
                             [](const Vec2& a, const Vec2& b) { return (a - b).norm() < 0.5; }),
                 points.end());
    if (points.size() < 3) return points;
    const auto cross = [](const Vec2& o, const Vec2& a, const Vec2& b) {
      return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
    };
    std::vector<Vec2> hull(2 * points.size());
    std::size_t k = 0;
    for (const Vec2& p : points) {
      while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
      hull[k++] = p;
    }
    for (std::size_t i = points.size() - 1, t = k + 1; i-- > 0;) {
      while (k >= t && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
      hull[k++] = points[i];
    }
    hull.resize(k - 1);
    return hull;
  }

  double width_, height_;
  double left_, right_;  // where labels are kept (keep_labels_within)
  std::string svg_;
};

// Length of a force's arrow: from kShortest to kLongest in proportion to its magnitude.
inline double arrow_length(double magnitude, double largest) {
  return kShortest + (kLongest - kShortest) * magnitude / largest;
}

// The largest force (or impulse) and moment a diagram draws: its arrows' scales.
struct Scales {
  double force = 0.0, moment = 0.0;
};

// The table of a diagram's loads: `what` names them ("load", "impulse"), `force_unit` and
// `couple_unit` their units ("N" and "N·m", or "N·s" and "N·m·s").
inline void table(Canvas& canvas, std::span<const Load> loads, const Scales& scale, double top,
                  const std::string& what, const std::string& force_unit,
                  const std::string& couple_unit) {
  // Columns: what the load is, then its force, point and couple in the world's axes, each as
  // wide as its longest text (about 0.6 em a character) and 24 px apart, so none overlaps.
  const std::array<std::string, 4> header = {
      what, fmt::format("{} in the world ({})", what == "load" ? "force" : what, force_unit),
      "at (m)", fmt::format("couple ({})", couple_unit)};
  double size = 0.0;
  for (const Load& load : loads) size = std::max(size, load.p_WoP_W.norm());
  std::vector<std::array<std::string, 4>> rows;
  for (const Load& load : loads) {
    rows.push_back({load.description, chopped_text(load.force_W, scale.force),
                    chopped_text(load.p_WoP_W, size), chopped_text(load.couple_W, scale.moment)});
  }
  const auto characters = [](const std::string& text) {  // UTF-8 code points
    return static_cast<double>(
        std::count_if(text.begin(), text.end(), [](char c) { return (c & 0xC0) != 0x80; }));
  };
  std::array<double, 4> column{};
  for (std::size_t c = 1; c < column.size(); ++c) {
    double widest = 7.2 * characters(header[c - 1]);  // bold, 12 px
    for (const auto& row : rows) widest = std::max(widest, 6.6 * characters(row[c - 1]));
    column[c] = column[c - 1] + widest + 24.0;
  }
  const char* bold = "class=\"table\" font-size=\"12\" font-weight=\"bold\"";
  for (std::size_t c = 0; c < column.size(); ++c)
    canvas.text(kLeftX + column[c], top, header[c], bold);
  double y = top;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    y += kRowHeight;
    const std::string attributes = fmt::format("class=\"table\" font-size=\"11\" fill=\"{}\"",
                                               colour(analysis::load_kind_name(loads[r].kind)));
    for (std::size_t c = 0; c < column.size(); ++c)
      canvas.text(kLeftX + column[c], y, rows[r][c], attributes);
  }
}

}  // namespace momenta::report::drawing
