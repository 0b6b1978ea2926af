#pragma once
// Scatter plots as SVG text: a report's figure that opens in any browser or
// Markdown preview, written without a plotting library. Panels stand side by
// side, each with its own axes (ticks at 1, 2 or 5 x 10^k), labels, points and
// optionally a straight line (a least-squares fit) clipped to the panel.

#include <optional>
#include <string>
#include <vector>

namespace occlusion {

struct PlotLine {
  double slope = 0.0;
  double intercept = 0.0;
};

struct ScatterPanel {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<double> x, y;  // one point per pair
  std::optional<PlotLine> line;
};

// A whole SVG document. A panel without points gets empty axes over [0, 1] and
// says so. std::invalid_argument when a panel's x and y differ in size or hold
// a value that is not finite.
std::string scatter_plot_svg(const std::vector<ScatterPanel>& panels, const std::string& title);

}  // namespace occlusion
