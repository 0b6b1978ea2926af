#include "occlusion/io/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace occlusion {

namespace {

constexpr double kPanelWidth = 380, kPlotHeight = 232;
constexpr double kLeft = 62, kRight = 18, kBottom = 52;
constexpr double kLineHeight = 16, kTopPad = 8;
// An estimate of one character's width at 12 px sans-serif (bold a little
// wider): wrapping at it keeps text inside its panel.
constexpr double kCharWidth = 7.0, kBoldCharWidth = 7.6, kTitleCharWidth = 8.6;
// Tableau's ten categorical colours; an eleventh scene takes the first again.
const char* const kGroupColours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                     "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};

// `text` broken at spaces into lines of at most `width` pixels; a word
// longer than a line is broken inside.
std::vector<std::string> wrapped(const std::string& text, double width, double char_width) {
  const auto per_line = static_cast<std::size_t>(std::max(8.0, width / char_width));
  std::vector<std::string> lines;
  std::string line;
  std::istringstream words(text);
  std::string word;
  while (words >> word) {
    while (word.size() > per_line) {
      if (!line.empty()) lines.push_back(line);
      lines.push_back(word.substr(0, per_line));
      line.clear();
      word = word.substr(per_line);
    }
    if (!line.empty() && line.size() + 1 + word.size() > per_line) {
      lines.push_back(line);
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

double panel_text_width() {
  return kPanelWidth - 20;
}

std::vector<std::string> heading_lines(const ScatterPanel& panel) {
  return wrapped(panel.title, panel_text_width(), kBoldCharWidth);
}
std::vector<std::string> note_lines(const ScatterPanel& panel) {
  std::vector<std::string> lines;
  for (const auto& note : panel.notes) {
    for (auto& line : wrapped(note, panel_text_width(), kCharWidth)) lines.push_back(line);
  }
  return lines;
}

std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string number(double value, int decimals) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// An axis from `lo` to `hi` whose ends are ticks, about five of them.
struct Axis {
  double lo = 0.0, hi = 1.0, step = 0.2;
  int decimals = 1;

  static Axis around(double lo, double hi) {
    if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) {
      const double pad = lo == 0.0 ? 0.5 : 0.1 * std::abs(lo);
      lo -= pad;
      hi += pad;
    }
    const double rough = (hi - lo) / 5.0;
    const double magnitude = std::pow(10.0, std::floor(std::log10(rough)));
    double step = magnitude;
    for (const double factor : {1.0, 2.0, 5.0, 10.0}) {
      step = factor * magnitude;
      if (step >= rough) break;
    }
    Axis axis;
    axis.step = step;
    axis.lo = std::floor(lo / step + 1e-9) * step;
    axis.hi = std::ceil(hi / step - 1e-9) * step;
    axis.decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
    return axis;
  }
  std::vector<double> ticks() const {
    std::vector<double> values;
    const auto count = static_cast<int>(std::llround((hi - lo) / step));
    for (int k = 0; k <= count; ++k) values.push_back(lo + k * step);
    return values;
  }
};

void check(const ScatterPanel& panel) {
  if (panel.x.size() != panel.y.size() ||
      (!panel.group.empty() && panel.group.size() != panel.x.size())) {
    throw std::invalid_argument("scatter_plot_svg: panel '" + panel.title + "' has " +
                                std::to_string(panel.x.size()) + " x but " +
                                std::to_string(panel.y.size()) + " y values");
  }
  const auto finite = [](double v) { return std::isfinite(v); };
  if (!std::all_of(panel.x.begin(), panel.x.end(), finite) ||
      !std::all_of(panel.y.begin(), panel.y.end(), finite)) {
    throw std::invalid_argument("scatter_plot_svg: panel '" + panel.title +
                                "' has a value that is not finite");
  }
  if (panel.y_range) {
    const double lo = panel.y_range->first, hi = panel.y_range->second;
    if (!(lo < hi) || !std::isfinite(lo) || !std::isfinite(hi) ||
        std::any_of(panel.y.begin(), panel.y.end(), [&](double v) { return v < lo || v > hi; })) {
      throw std::invalid_argument("scatter_plot_svg: panel '" + panel.title +
                                  "' has a y outside its declared range");
    }
  }
}

// A margin of 5 % keeps the extreme points off the frame.
Axis axis_of(const std::vector<double>& values) {
  if (values.empty()) return Axis::around(0.0, 1.0);
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  const double margin = 0.05 * (*hi - *lo);
  return Axis::around(*lo - margin, *hi + margin);
}

// `heading` is the height every panel keeps for its title and notes.
void draw_panel(std::ostream& out, const ScatterPanel& panel, std::size_t index, double top,
                double heading) {
  const double left = static_cast<double>(index) * kPanelWidth;
  const double x0 = left + kLeft, x1 = left + kPanelWidth - kRight;
  const double y1 = top + heading, y0 = y1 + kPlotHeight;  // y0: the bottom
  const Axis ax = axis_of(panel.x);
  const Axis ay =
      panel.y_range ? Axis::around(panel.y_range->first, panel.y_range->second) : axis_of(panel.y);
  const auto px = [&](double x) { return x0 + (x - ax.lo) / (ax.hi - ax.lo) * (x1 - x0); };
  const auto py = [&](double y) { return y0 - (y - ay.lo) / (ay.hi - ay.lo) * (y0 - y1); };
  const std::string clip = "plot-area-" + std::to_string(index);

  out << "<g class=\"panel\">\n";
  out << "<clipPath id=\"" << clip << "\"><rect x=\"" << x0 << "\" y=\"" << y1 << "\" width=\""
      << x1 - x0 << "\" height=\"" << y0 - y1 << "\"/></clipPath>\n";
  double line_y = top + kTopPad + kLineHeight - 4;
  const double centre = left + kPanelWidth / 2;
  for (const auto& line : heading_lines(panel)) {
    out << "<text x=\"" << centre << "\" y=\"" << line_y
        << "\" text-anchor=\"middle\" font-weight=\"bold\">" << escaped(line) << "</text>\n";
    line_y += kLineHeight;
  }
  for (const auto& line : note_lines(panel)) {
    out << "<text class=\"note\" x=\"" << centre << "\" y=\"" << line_y
        << "\" text-anchor=\"middle\" fill=\"#333\">" << escaped(line) << "</text>\n";
    line_y += kLineHeight;
  }
  out << "<rect x=\"" << x0 << "\" y=\"" << y1 << "\" width=\"" << x1 - x0 << "\" height=\""
      << y0 - y1 << "\" fill=\"none\" stroke=\"#444\"/>\n";
  for (const double t : ax.ticks()) {
    out << "<line class=\"tick\" x1=\"" << px(t) << "\" y1=\"" << y0 << "\" x2=\"" << px(t)
        << "\" y2=\"" << y0 + 5 << "\" stroke=\"#444\"/><text x=\"" << px(t) << "\" y=\"" << y0 + 18
        << "\" text-anchor=\"middle\">" << number(t, ax.decimals) << "</text>\n";
  }
  for (const double t : ay.ticks()) {
    out << "<line class=\"tick\" x1=\"" << x0 - 5 << "\" y1=\"" << py(t) << "\" x2=\"" << x0
        << "\" y2=\"" << py(t) << "\" stroke=\"#444\"/><text x=\"" << x0 - 8 << "\" y=\""
        << py(t) + 4 << "\" text-anchor=\"end\">" << number(t, ay.decimals) << "</text>\n";
  }
  out << "<text x=\"" << (x0 + x1) / 2 << "\" y=\"" << y0 + 40 << "\" text-anchor=\"middle\">"
      << escaped(panel.x_label) << "</text>\n";
  out << "<text transform=\"translate(" << left + 16 << "," << (y0 + y1) / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << escaped(panel.y_label) << "</text>\n";
  if (panel.x.empty()) {
    out << "<text x=\"" << (x0 + x1) / 2 << "\" y=\"" << (y0 + y1) / 2
        << "\" text-anchor=\"middle\" fill=\"#888\">no data</text>\n";
  }
  for (std::size_t i = 0; i < panel.x.size(); ++i) {
    const std::size_t colour = panel.group.empty() ? 0 : panel.group[i] % std::size(kGroupColours);
    out << "<circle cx=\"" << px(panel.x[i]) << "\" cy=\"" << py(panel.y[i]) << "\" r=\"4\" fill=\""
        << kGroupColours[colour] << "\" fill-opacity=\"0.75\"/>\n";
  }
  if (panel.line) {
    const auto y_at = [&](double x) { return panel.line->slope * x + panel.line->intercept; };
    out << "<line class=\"fit\" clip-path=\"url(#" << clip << ")\" x1=\"" << x0 << "\" y1=\""
        << py(y_at(ax.lo)) << "\" x2=\"" << x1 << "\" y2=\"" << py(y_at(ax.hi))
        << "\" stroke=\"#d62728\" stroke-width=\"1.5\"/>\n";
  }
  out << "</g>\n";
}

}  // namespace

std::string scatter_plot_svg(const std::vector<ScatterPanel>& panels, const std::string& title) {
  for (const auto& panel : panels) check(panel);
  const double width = kPanelWidth * static_cast<double>(std::max<std::size_t>(panels.size(), 1));
  const std::vector<std::string> title_lines = wrapped(title, width - 20, kTitleCharWidth);
  const double top = title_lines.empty()
                         ? 0.0
                         : kTopPad + kLineHeight * 1.25 * static_cast<double>(title_lines.size());
  std::size_t heading_count = 1;
  for (const auto& panel : panels) {
    heading_count = std::max(heading_count, heading_lines(panel).size() + note_lines(panel).size());
  }
  const double heading = kTopPad * 2 + kLineHeight * static_cast<double>(heading_count);
  const double height = top + heading + kPlotHeight + kBottom;
  std::ostringstream out;
  out.precision(6);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  double line_y = kTopPad + kLineHeight;
  for (const auto& line : title_lines) {
    out << "<text x=\"" << width / 2 << "\" y=\"" << line_y
        << "\" text-anchor=\"middle\" font-size=\"15\">" << escaped(line) << "</text>\n";
    line_y += kLineHeight * 1.25;
  }
  for (std::size_t i = 0; i < panels.size(); ++i) draw_panel(out, panels[i], i, top, heading);
  out << "</svg>\n";
  return out.str();
}

}  // namespace occlusion
