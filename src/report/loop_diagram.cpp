// The report's feedback loops: each controller of the model drawn as the block diagram a control
// text draws (Franklin, Powell & Emami-Naeini ch. 4): the reference into a summing junction,
// the control law, the hold of a sampled law, the actuator's saturation, the mechanism, and the
// measured quantities back through the sensor to the junction's minus sign.

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "momenta/model/units.hpp"
#include "sections.hpp"

namespace momenta::report::detail {
namespace {

using model::ControllerKind;

// Geometry (px). One row of blocks along the forward path at kPathY, the feedback path below it.
constexpr double kPathY = 70.0;
constexpr double kFeedbackY = 150.0;
constexpr double kBlockHeight = 46.0;
constexpr double kGap = 52.0;       // between blocks: room for an arrow and its label
constexpr double kCharWidth = 7.4;  // of the 13 px block font, per character
constexpr double kLineHeight = 15.0;
constexpr double kJunctionRadius = 11.0;

double characters(const std::string& text) {  // UTF-8 code points
  return static_cast<double>(
      std::count_if(text.begin(), text.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

// A block: its lines of text (the first bold), its fill.
struct Block {
  std::vector<std::string> lines;
  const char* fill = "#eef3fb";
  double width() const {
    double widest = 0.0;
    for (const std::string& line : lines) widest = std::max(widest, characters(line));
    return std::max(96.0, kCharWidth * widest + 24.0);
  }
};

std::string number(double x) { return fmt::format("{:.4g}", x); }

// What the law computes, in the textbook's words.
Block law_block(const model::ResolvedController& c) {
  const model::Controller& s = c.spec;
  const bool sampled = s.discrete();
  switch (s.kind) {
    case ControllerKind::pid: {
      std::vector<std::string> terms = {"kp = " + number(s.pid.kp)};
      if (s.pid.ki != 0.0) terms.push_back("ki = " + number(s.pid.ki));
      if (s.pid.kd != 0.0) terms.push_back("kd = " + number(s.pid.kd));
      std::string name =
          s.pid.ki != 0.0 ? (s.pid.kd != 0.0 ? "PID" : "PI") : (s.pid.kd != 0.0 ? "PD" : "P");
      Block b{{fmt::format("{} {}", name, s.name), fmt::format("{}", fmt::join(terms, ", "))}};
      if (s.pid.kd != 0.0 && s.pid.derivative_filter > 0.0)
        b.lines.push_back("Tf = " + number(s.pid.derivative_filter) + " s");
      return b;
    }
    case ControllerKind::state_feedback:
      return {{fmt::format("state feedback {}", s.name),
               fmt::format("u = K e, K {}×{}", s.gain.rows(), s.gain.cols())}};
    case ControllerKind::linear:
      return {{fmt::format("{} {}", sampled ? "C(z)" : "C(s)", s.name),
               fmt::format("{} state{}", s.block.A.rows(), s.block.A.rows() == 1 ? "" : "s")}};
    case ControllerKind::external:
      break;
  }
  return {{fmt::format("function {}", s.name), "u = fn(t, q, v)"}};
}

class LoopPicture {
 public:
  std::string draw(const model::Model& model, const model::ResolvedController& c) {
    const model::Controller& s = c.spec;
    const bool junction = s.kind != ControllerKind::external;
    // The forward path's blocks after the junction.
    std::vector<Block> path = {law_block(c)};
    if (s.discrete())
      path.push_back({{"hold (ZOH)", fmt::format("T = {} s", number(s.sample_time))}, "#f5f0e6"});
    if (s.actuator.saturates()) {
      const auto bound = [](double x) { return std::isfinite(x) ? number(x) : std::string("∞"); };
      path.push_back(
          {{"actuator", fmt::format("[{}, {}]", bound(s.actuator.min), bound(s.actuator.max))},
           "#f5f0e6"});
    }
    std::vector<std::string> driven;
    for (int d : c.drives) {
      const std::string unit = model::signal_unit(model, d);
      driven.push_back(model.signals()[static_cast<std::size_t>(d)].name() +
                       (unit.empty() ? "" : " (" + unit + ")"));
    }
    const Block plant{{"mechanism", fmt::format("{} bod{}, {} dof", model.num_bodies() - 1,
                                                model.num_bodies() == 2 ? "y" : "ies", model.nv())},
                      "#e8f3ea"};
    // The feedback: what is measured, through the sensor when it does anything.
    std::string measured = s.kind == ControllerKind::external
                               ? "q, v"
                               : fmt::format("{}", fmt::join(s.measured, ", "));
    if (characters(measured) > 48) measured = fmt::format("x: {} quantities", s.measured.size());
    std::vector<std::string> sensor;
    if (s.sensor.quantization > 0.0) sensor.push_back("step " + number(s.sensor.quantization));
    if (s.sensor.noise > 0.0) sensor.push_back("noise σ " + number(s.sensor.noise));
    if (s.sensor.delay > 0) sensor.push_back(fmt::format("delay {} samples", s.sensor.delay));
    if (s.discrete()) sensor.push_back(fmt::format("sampled every {} s", number(s.sample_time)));

    // Left to right: the reference's label, the junction, the blocks, the plant, the output.
    const std::string reference =
        s.kind == ControllerKind::state_feedback ? "x_ref"
        : c.reference >= 0 ? model.signals()[static_cast<std::size_t>(c.reference)].name()
                           : "r = " + number(s.setpoint);
    const double x = 16.0;
    double junction_x = x + kCharWidth * characters(reference) + 30.0 + kJunctionRadius;
    double cursor = x;
    if (junction) {
      text(x, kPathY - 8, reference, "font-size=\"13\"");
      arrow(x, kPathY, junction_x - kJunctionRadius, kPathY);
      svg_ += fmt::format(
          "<circle class=\"junction\" cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{:.1f}\" fill=\"white\" "
          "stroke=\"#333\" stroke-width=\"1.5\"/>\n",
          junction_x, kPathY, kJunctionRadius);
      text(junction_x, kPathY + 5, "Σ", "font-size=\"13\" text-anchor=\"middle\"");
      text(junction_x - 20, kPathY + 26, "−", "font-size=\"16\"");
      cursor = junction_x + kJunctionRadius;
    }
    for (std::size_t i = 0; i < path.size(); ++i) {
      const double left = cursor + kGap;
      if (i > 0 || junction) arrow(cursor, kPathY, left, kPathY, i == 0 ? "e" : "");
      block(left, path[i]);
      cursor = left + path[i].width();
    }
    // The drives' arrow as long as its label ("cart_drive (m/s²)"), at least the usual gap.
    const std::string drives = fmt::format("{}", fmt::join(driven, ", "));
    const double plant_left =
        cursor + std::max(kGap + 40.0, kCharWidth * characters(drives) + 24.0);
    arrow(cursor, kPathY, plant_left, kPathY, drives);
    block(plant_left, plant);
    const double plant_right = plant_left + plant.width();
    const double tap = plant_right + 40.0;
    const double out_end = tap + std::max(60.0, kCharWidth * characters(measured) + 20.0);
    arrow(plant_right, kPathY, out_end, kPathY);
    text(tap + 8, kPathY - 8, measured, "font-size=\"12\"");
    circle_dot(tap, kPathY);
    // The feedback path: down from the tap, back under the blocks, up into the junction (or the
    // law's input, for an external law reading the whole state).
    const double back_to = junction ? junction_x : starts_of_law_;
    std::string back = fmt::format("M {:.1f} {:.1f} L {:.1f} {:.1f}", tap, kPathY, tap, kFeedbackY);
    if (!sensor.empty()) {
      const Block box{{"sensor", fmt::format("{}", fmt::join(sensor, ", "))}, "#f5f0e6"};
      const double mid = (tap + back_to) / 2.0 - box.width() / 2.0;
      svg_ += fmt::format(
          "<path d=\"{} L {:.1f} {:.1f}\" fill=\"none\" stroke=\"#333\" stroke-width=\"1.5\"/>\n",
          back, mid + box.width(), kFeedbackY);
      block(mid, box, kFeedbackY);
      back = fmt::format("M {:.1f} {:.1f}", mid, kFeedbackY);
    }
    const double entry = junction ? kPathY + kJunctionRadius : kPathY + kBlockHeight / 2.0;
    svg_ += fmt::format(
        "<path d=\"{} L {:.1f} {:.1f} L {:.1f} {:.1f}\" fill=\"none\" stroke=\"#333\" "
        "stroke-width=\"1.5\" marker-end=\"url(#head)\"/>\n",
        back, back_to, kFeedbackY, back_to, entry + 1.0);
    width_ = out_end + 16.0;
    const double height = kFeedbackY + kBlockHeight / 2.0 + 40.0;
    std::string caption =
        s.kind == ControllerKind::external
            ? "a function of the state, called by the run"
            : fmt::format("{} loop{}", s.discrete() ? "sampled" : "continuous",
                          s.discrete()
                              ? fmt::format(", every {} s (zero-order hold)", number(s.sample_time))
                              : "");
    text(16, height - 12, fmt::format("controller {}: {}", s.name, caption),
         "font-size=\"12\" fill=\"#555\"");
    return fmt::format(
               "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"loop-diagram\" width=\"{0:.0f}\" "
               "height=\"{1:.0f}\" viewBox=\"0 0 {0:.0f} {1:.0f}\" font-family=\"DejaVu Sans, "
               "Arial, sans-serif\">\n<defs><marker id=\"head\" viewBox=\"0 0 10 10\" refX=\"10\" "
               "refY=\"5\" markerWidth=\"8\" markerHeight=\"8\" orient=\"auto-start-reverse\">"
               "<path d=\"M 0 0 L 10 5 L 0 10 z\" fill=\"#333\"/></marker></defs>\n"
               "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
               width_, height) +
           svg_ + "</svg>\n";
  }

 private:
  void text(double x, double y, const std::string& content, const std::string& attributes) {
    if (content.empty()) return;
    svg_ += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" {}>{}</text>\n", x, y, attributes,
                        escape_html(content));
  }
  void arrow(double x0, double y0, double x1, double y1, const std::string& label = "") {
    svg_ += fmt::format(
        "<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#333\" "
        "stroke-width=\"1.5\" marker-end=\"url(#head)\"/>\n",
        x0, y0, x1, y1);
    text((x0 + x1) / 2.0, y0 - 8, label,
         "class=\"signal\" font-size=\"12\" text-anchor=\"middle\"");
  }
  void circle_dot(double x, double y) {
    svg_ += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3\" fill=\"#333\"/>\n", x, y);
  }
  void block(double left, const Block& b, double centre_y = kPathY) {
    if (starts_of_law_ < 0.0) starts_of_law_ = left + b.width() / 2.0;
    const double top = centre_y - kBlockHeight / 2.0;
    svg_ += fmt::format(
        "<rect class=\"block\" x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" "
        "rx=\"4\" fill=\"{}\" stroke=\"#333\" stroke-width=\"1.2\"/>\n",
        left, top, b.width(), kBlockHeight, b.fill);
    const double first =
        centre_y - (static_cast<double>(b.lines.size()) - 1.0) * kLineHeight / 2.0 + 5.0;
    for (std::size_t i = 0; i < b.lines.size(); ++i) {
      text(left + b.width() / 2.0, first + kLineHeight * static_cast<double>(i), b.lines[i],
           fmt::format("font-size=\"{}\" text-anchor=\"middle\"{}", i == 0 ? 13 : 12,
                       i == 0 ? " font-weight=\"bold\"" : ""));
    }
  }

  std::string svg_;
  double width_ = 0.0;
  double starts_of_law_ =
      -1.0;  // the first block's centre: where an external law's feedback enters
};

}  // namespace

json loops_json(const io::ModelFile& file) {
  json loops = json::array();
  for (const model::ResolvedController& c : file.model.controllers()) {
    loops.push_back({{"name", c.spec.name},
                     {"kind", model::controller_kind_name(c.spec.kind)},
                     {"sample_time", c.spec.sample_time},
                     {"svg", LoopPicture().draw(file.model, c)}});
  }
  return loops;
}

}  // namespace momenta::report::detail
