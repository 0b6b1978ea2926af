#pragma once
// Scatter plots as SVG text: a report's figure that opens in any browser or
// Markdown preview, written without a plotting library. Panels stand side by
// side, each with its own axes (ticks at 1, 2 or 5 x 10^k), labels, points and
// optionally a straight line (a least-squares fit) clipped to the panel.
// Titles and notes are wrapped to the width they have (an estimate of the
// text's width: no font metrics without a renderer), and the panels grow to
// hold the longest, so that no text is cut off or overlaps.

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace occlusion {

struct PlotLine {
  double slope = 0.0;
  double intercept = 0.0;
};

struct ScatterPanel {
  std::string title;
  std::vector<std::string> notes;  // lines under the title (e.g. its statistics)
  std::string x_label;
  std::string y_label;
  std::vector<double> x, y;  // one point per pair
  // Empty, or per point its group (a scene): groups get colours of their own.
  std::vector<std::size_t> group;
  // The y axis's range when declared (mIoU: 0..1), so that a small spread is
  // drawn as small; else it fits the data.
  std::optional<std::pair<double, double>> y_range;
  std::optional<PlotLine> line;
};

// A whole SVG document. A panel without points gets empty axes over [0, 1] and
// says so. std::invalid_argument when a panel's x, y and (if given) group
// differ in size, hold a value that is not finite, or a y lies outside the
// declared range.
std::string scatter_plot_svg(const std::vector<ScatterPanel>& panels, const std::string& title);

}  // namespace occlusion
