#include "occlusion/io/svg_plot.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace occlusion {
namespace {

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

ScatterPanel panel() {
  ScatterPanel p;
  p.title = "occlusion <level> & mIoU";
  p.x_label = "occlusion_level";
  p.y_label = "mIoU";
  p.x = {0.01, 0.02, 0.04, 0.08};
  p.y = {0.7, 0.65, 0.6, 0.41};
  p.line = PlotLine{-4.0, 0.73};
  return p;
}

TEST(SvgPlot, IsOneSvgElementWithAPointPerPairAndTheLine) {
  const std::string svg = scatter_plot_svg({panel()}, "study");
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
  EXPECT_EQ(count(svg, "<svg"), 1u);
  EXPECT_EQ(count(svg, "<g "), count(svg, "</g>"));
  EXPECT_EQ(count(svg, "<text"), count(svg, "</text>"));
  EXPECT_EQ(count(svg, "<circle"), 4u);
  EXPECT_EQ(count(svg, "class=\"fit\""), 1u);
  EXPECT_NE(svg.find("clip-path=\"url(#plot-area-0)\""), std::string::npos);
  // Text is escaped, so the document stays well formed.
  EXPECT_NE(svg.find("occlusion &lt;level&gt; &amp; mIoU"), std::string::npos);
  EXPECT_EQ(svg.find("<level>"), std::string::npos);
}

TEST(SvgPlot, TicksAreRoundNumbersCoveringTheData) {
  const std::string svg = scatter_plot_svg({panel()}, "");
  // x spans 0.01..0.08 plus a margin: ticks every 0.02 from 0.00 to 0.10.
  for (const char* tick : {">0.00<", ">0.02<", ">0.10<", ">0.4<", ">0.7<"}) {
    EXPECT_NE(svg.find(tick), std::string::npos) << tick;
  }
}

TEST(SvgPlot, PanelsStandSideBySide) {
  ScatterPanel empty;
  empty.title = "nothing";
  const std::string svg = scatter_plot_svg({panel(), empty}, "two");
  EXPECT_EQ(count(svg, "class=\"panel\""), 2u);
  EXPECT_EQ(count(svg, "<circle"), 4u);
  EXPECT_NE(svg.find("no data"), std::string::npos);
  EXPECT_NE(svg.find("width=\"760\""), std::string::npos);
}

TEST(SvgPlot, OneValueStillGivesAnAxis) {
  ScatterPanel p;
  p.x = {0.5};
  p.y = {0.5};
  const std::string svg = scatter_plot_svg({p}, "");
  EXPECT_EQ(count(svg, "<circle"), 1u);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

TEST(SvgPlot, RejectsMismatchedOrNonFiniteData) {
  ScatterPanel p = panel();
  p.y.pop_back();
  EXPECT_THROW(scatter_plot_svg({p}, ""), std::invalid_argument);
  p = panel();
  p.x[0] = NAN;
  EXPECT_THROW(scatter_plot_svg({p}, ""), std::invalid_argument);
}

TEST(SvgPlot, LongTitlesAndNotesWrapInsideTheirPanelAndThePanelsGrow) {
  ScatterPanel p = panel();
  p.title =
      "exterior occlusion level (-poc from 9 grid viewpoints; blocking: wall, floor, ceiling)";
  p.notes = {"Pearson r = -0.52 [-0.71, -0.30], p = 0.001; 60 runs in 10 scenes"};
  const std::string short_svg = scatter_plot_svg({panel()}, "study");
  const std::string svg = scatter_plot_svg(
      {p},
      "mIoU against occlusion, one point per run (60 runs; baseline, mIoU over support "
      "classes, point radius auto, 20000 rays per viewpoint)");
  // Every text line fits the 380 px panel at about 7.6 px per character.
  for (std::size_t at = svg.find("<text"); at != std::string::npos;
       at = svg.find("<text", at + 1)) {
    const std::size_t begin = svg.find('>', at) + 1, end = svg.find("</text>", at);
    EXPECT_LE(end - begin, 48u) << svg.substr(begin, end - begin);
  }
  EXPECT_EQ(count(svg, "font-weight=\"bold\""), 2u);  // the title in two lines
  EXPECT_EQ(count(svg, "class=\"note\""), 2u);
  // The words are all there, in order.
  EXPECT_NE(svg.find(">exterior occlusion level (-poc from 9 grid"), std::string::npos);
  const auto height = [](const std::string& text) {
    const std::size_t at = text.find("height=\"") + 8;
    return std::stod(text.substr(at, text.find('"', at) - at));
  };
  EXPECT_GT(height(svg), height(short_svg) + 3 * 16);
}

TEST(SvgPlot, GroupsGetTheirOwnColoursAndADeclaredRangeHoldsTheAxis) {
  ScatterPanel p = panel();
  p.group = {0, 0, 1, 2};
  p.y = {0.2290, 0.2280, 0.2285, 0.2276};  // a spread of 0.0014, drawn as small on 0..1
  p.y_range = std::make_pair(0.0, 1.0);
  p.line.reset();
  const std::string svg = scatter_plot_svg({p}, "");
  EXPECT_EQ(count(svg, "fill=\"#1f77b4\""), 2u);
  EXPECT_EQ(count(svg, "fill=\"#ff7f0e\""), 1u);
  EXPECT_EQ(count(svg, "fill=\"#2ca02c\""), 1u);
  for (const char* tick : {">0.0<", ">0.2<", ">1.0<"}) {
    EXPECT_NE(svg.find(tick), std::string::npos) << tick;
  }
  EXPECT_EQ(svg.find(">0.2290<"), std::string::npos);
  p.y[0] = 1.2;
  EXPECT_THROW(scatter_plot_svg({p}, ""), std::invalid_argument);
  p = panel();
  p.group = {0};
  EXPECT_THROW(scatter_plot_svg({p}, ""), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
