#include "momenta/report/free_body_svg.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include "momenta/common/number_text.hpp"
#include "page_data.hpp"

namespace momenta::report {

namespace {

using analysis::FreeBodyDiagram;
using analysis::Load;
using analysis::LoadKind;
using Vec2 = Eigen::Vector2d;

// Page geometry (px): two square panels side by side under a title, the table below.
constexpr double kPanel = 460.0;
constexpr double kLeftX = 20.0;
constexpr double kRightX = 560.0;
constexpr double kPanelTop = 70.0;
constexpr double kWidth = kRightX + kPanel + 20.0;
constexpr double kArrowRoom = 100.0;  // kept free around the body for arrows and labels
constexpr double kShortest = 28.0, kLongest = 85.0;  // arrow lengths, by magnitude
constexpr double kRowHeight = 16.0;
constexpr double kCharWidth = 6.6;  // of the 12 px label font, for placing labels apart

// Below this fraction of the largest force (or moment) a vector is not drawn (it is listed).
constexpr double kNegligible = 1e-9;

const char* colour(const std::string& kind) {
  if (kind == "gravity") return "#2e7d32";
  if (kind == "reaction") return "#c62828";
  if (kind == "element") return "#6a1b9a";
  if (kind == "applied") return "#1565c0";
  if (kind == "drive") return "#ef6c00";
  return "#37474f";  // kinetic
}

std::string vector_text(const Vec3& v) {
  return fmt::format("[{:.6g}, {:.6g}, {:.6g}]", v.x(), v.y(), v.z());
}

// The components, round-off against `scale` written 0 (shown_value: the CLI's rule).
std::string chopped_text(const Vec3& v, double scale) {
  return vector_text(v.unaryExpr([&](double x) { return shown_value(x, scale); }));
}

// World → screen directions: `right` and `up` span the picture; `out` points at the viewer.
struct View {
  Vec3 right, up, out;
  bool planar = false;
  std::string caption;

  Vec2 project(const Vec3& v) const { return {v.dot(right), v.dot(up)}; }
};

const char* axis_name(int k) { return k == 0 ? "x" : k == 1 ? "y" : "z"; }

View make_view(const FreeBodyDiagram& d) {
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
std::vector<Vec3> equivalent_box(const FreeBodyDiagram& d) {
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
std::vector<Vec3> body_points(const FreeBodyDiagram& d, std::span<const io::PartSummary> parts) {
  std::vector<Vec3> points = {d.p_WoG_W};
  for (const Load& load : d.loads) points.push_back(load.p_WoP_W);
  std::vector<Vec3> surface;
  for (const io::PartSummary& part : parts) {
    for (const Vec3& p_BoP_B : detail::part_outline_points(part))
      surface.push_back(d.p_WoBo_W + d.R_WB * p_BoP_B);
  }
  if (surface.empty()) surface = equivalent_box(d);
  points.insert(points.end(), surface.begin(), surface.end());
  return points;
}

Placement place(const View& view, const std::vector<Vec3>& outline, const FreeBodyDiagram& d,
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

Vec2 clamp_to_page(Vec2 p, double height) {
  return {std::clamp(p.x(), 4.0, kWidth - 4.0), std::clamp(p.y(), 14.0, height - 4.0)};
}

class Canvas {
 public:
  explicit Canvas(double height) : height_(height) {}

  std::string& svg() { return svg_; }

  void body(const Placement& at, const FreeBodyDiagram& d) {
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
    const Vec2 p = clamp_to_page({x, y}, height_);
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
    anchor = labels.place(anchor, width, to_left);
    // Kept on the page: a label that would run off the edge turns to the other side.
    if (!to_left && anchor.x() + width > kWidth - 4.0) to_left = true;
    if (to_left && anchor.x() - width < 4.0) to_left = false;
    anchor = clamp_to_page(anchor, height_);
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

  double height_;
  std::string svg_;
};

std::string force_label(const Load& load) {
  const std::string name = load.kind == LoadKind::gravity ? "W = m g" : load.name;
  return fmt::format("{} {:.4g} N", name, load.force_W.norm());
}

// Length of a force's arrow: from kShortest to kLongest in proportion to its magnitude.
double arrow_length(double magnitude, double largest) {
  return kShortest + (kLongest - kShortest) * magnitude / largest;
}

struct Scales {
  double force = 0.0, moment = 0.0;
};

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

void table(Canvas& canvas, const FreeBodyDiagram& d, const Scales& scale, double top) {
  // Columns: what the load is, then its force, point and couple in the world's axes, each as
  // wide as its longest text (about 0.6 em a character) and 24 px apart, so none overlaps.
  const std::array<std::string, 4> header = {"load", "force in the world (N)", "at (m)",
                                             "couple (N·m)"};
  double size = 0.0;
  for (const Load& load : d.loads) size = std::max(size, load.p_WoP_W.norm());
  std::vector<std::array<std::string, 4>> rows;
  for (const Load& load : d.loads) {
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
                                               colour(analysis::load_kind_name(d.loads[r].kind)));
    for (std::size_t c = 0; c < column.size(); ++c)
      canvas.text(kLeftX + column[c], y, rows[r][c], attributes);
  }
}

}  // namespace

std::string free_body_svg(const FreeBodyDiagram& d, const std::string& title,
                          std::span<const io::PartSummary> parts) {
  const View view = make_view(d);
  const std::vector<Vec3> outline = body_points(d, parts);
  const Scales scale = largest(d);
  const double table_top = kPanelTop + kPanel + 64.0;
  const double height = table_top + kRowHeight * static_cast<double>(d.loads.size() + 1) + 12.0;
  Canvas canvas(height);
  canvas.svg() = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.0f}\" height=\"{1:.0f}\" "
      "viewBox=\"0 0 {0:.0f} {1:.0f}\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      kWidth, height);
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

  draw_free_body(canvas, place(view, outline, d, kLeftX), view, d, scale);
  draw_kinetic(canvas, place(view, outline, d, kRightX), view, d, scale);
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
  table(canvas, d, scale, table_top);
  canvas.svg() += "</svg>\n";
  return canvas.svg();
}

}  // namespace momenta::report
