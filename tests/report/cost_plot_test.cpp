#include "report/cost_plot.h"

#include <gtest/gtest.h>

#include <regex>

#include "report/label_layout.h"

namespace iblkit {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(CostPlot, TheParetoFrontIsWhatNoOtherModeBeatsOnBoth) {
  const std::vector<CostPoint> points = {{"sh", 1.0, 0.10},  {"sh-ao", 1.2, 0.13},  // sh-ao: slower and worse than sh
                                         {"prt", 2.0, 0.08}, {"full", 4.0, 0.05},
                                         {"lights", 4.0, 0.06},                     // as slow as full, worse
                                         {"mirror", kNaN, 0.01}, {"fast", 0.5, kNaN}};
  EXPECT_EQ(paretoFront(points), (std::vector<bool>{true, false, true, true, false, false, false}));
  // Ties: two equal points are both on the front.
  EXPECT_EQ(paretoFront({{"a", 1.0, 0.1}, {"b", 1.0, 0.1}}), (std::vector<bool>{true, true}));
}

CaseResult caseWith(const std::string& environment, std::vector<std::pair<std::string, double>> modes, double ms) {
  CaseResult result;
  result.scene = "bunny";
  result.environment = environment;
  for (const auto& [mode, flip] : modes) {
    ModeResult modeResult;
    modeResult.mode = mode;
    modeResult.scores.meanFlip = flip;
    modeResult.frameMilliseconds = ms;
    result.modes.push_back(modeResult);
  }
  return result;
}

TEST(CostPlot, PointsAreTheMedianFrameTimeAndTheMeanFlipOverTheMaps) {
  const std::vector<CaseResult> cases = {caseWith("sky", {{"sh", 0.2}, {"full", 0.1}}, 3.0),
                                         caseWith("city", {{"sh", 0.4}, {"full", 0.3}}, 5.0),
                                         caseWith("forest", {{"sh", 0.3}}, 4.0)};
  EXPECT_DOUBLE_EQ(sceneFrameMilliseconds(cases, "bunny", "sh"), 4.0);
  EXPECT_TRUE(std::isnan(sceneFrameMilliseconds(cases, "bunny", "prt")));
  const std::vector<CostPoint> points = costPoints(cases, "bunny", {"sh", "prt", "full"});
  ASSERT_EQ(points.size(), 2u);  // prt was not scored
  EXPECT_EQ(points[0].mode, "sh");
  EXPECT_NEAR(points[0].meanFlip, 0.3, 1e-12);
  EXPECT_NEAR(points[1].meanFlip, 0.2, 1e-12);
}

// Ten modes crowded at nearly the same cost and error: every label is drawn, none overlaps.
TEST(CostPlot, TheSvgMarksTheFrontAndItsLabelsDoNotOverlap) {
  std::vector<CostPoint> points;
  const char* names[] = {"mirror", "sh", "sh-ao", "sh-ao-bent", "prt", "full", "lights", "lights-shadowed",
                         "full-gltf-ao", "full-both-ao"};
  for (int i = 0; i < 10; ++i) points.push_back({names[i], 10.0 + 0.1 * i, 0.1 + 0.001 * (i % 3)});
  const std::string svg = costSvg(points);
  const std::regex label("<text class=label x=\"([0-9.-]+)\" y=\"([0-9.-]+)\"( font-weight=\"bold\")?>([a-z-]+)</text>");
  std::vector<LabelBox> boxes;
  int bold = 0;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), label); it != std::sregex_iterator(); ++it) {
    boxes.push_back({std::stod((*it)[1]), std::stod((*it)[2]) - 11.0, labelWidth((*it)[4], 11), 11.0});
    bold += (*it)[3].matched;
  }
  ASSERT_EQ(boxes.size(), 10u);
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j) EXPECT_FALSE(overlaps(boxes[i], boxes[j])) << i << " " << j;
  const std::vector<bool> front = paretoFront(points);
  EXPECT_EQ(bold, std::count(front.begin(), front.end(), true));
  EXPECT_NE(svg.find("class=front"), std::string::npos);
}

TEST(CostPlot, WithoutFrameTimesItSaysSo) {
  EXPECT_NE(costSvg({{"sh", kNaN, 0.1}, {"full", kNaN, 0.05}}).find("--bench"), std::string::npos);
}

}  // namespace
}  // namespace iblkit
