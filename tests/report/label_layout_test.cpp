#include "report/label_layout.h"

#include <gtest/gtest.h>

#include <random>

namespace iblkit {
namespace {

std::vector<LabelBox> placed(std::vector<LabelBox> boxes, double top, double bottom) {
  const std::vector<double> y = placeLabels(boxes, top, bottom);
  for (std::size_t i = 0; i < boxes.size(); ++i) boxes[i].y = y[i];
  return boxes;
}

void expectNoOverlap(const std::vector<LabelBox>& boxes) {
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      EXPECT_FALSE(overlaps(boxes[i], boxes[j])) << "labels " << i << " and " << j << " at y " << boxes[i].y << ", "
                                                 << boxes[j].y;
}

TEST(LabelLayout, BoxesOverlapOnlyWhenTheirInteriorsMeet) {
  EXPECT_TRUE(overlaps({0, 0, 10, 10}, {5, 5, 10, 10}));
  EXPECT_FALSE(overlaps({0, 0, 10, 10}, {0, 10, 10, 10}));  // touching edges are clear
  EXPECT_FALSE(overlaps({0, 0, 10, 10}, {10, 0, 10, 10}));
}

TEST(LabelLayout, LabelsThatAreClearStayWhereTheyWant) {
  const std::vector<LabelBox> boxes = {{0, 10, 50, 12}, {0, 40, 50, 12}, {60, 10, 50, 12}};
  EXPECT_EQ(placeLabels(boxes, 0, 200), (std::vector<double>{10, 40, 10}));
}

// The ladder plot's column of environment names: six lines ending at nearly the same height.
TEST(LabelLayout, AColumnOfLabelsAtOneHeightIsSpreadWithinTheBand) {
  std::vector<LabelBox> boxes(6, LabelBox{460, 100, 60, 13});
  boxes[3].y = 101;
  const std::vector<LabelBox> result = placed(boxes, 16, 220);
  expectNoOverlap(result);
  for (const LabelBox& box : result) {
    EXPECT_GE(box.y, 16);
    EXPECT_LE(box.y + box.height, 220);
    EXPECT_LE(std::abs(box.y - 100), 6 * 13);  // nudged, not thrown far away
  }
}

TEST(LabelLayout, LabelsAtTheBandsEdgeStayInside) {
  std::vector<LabelBox> boxes(4, LabelBox{0, 195, 40, 12});
  const std::vector<LabelBox> result = placed(boxes, 0, 200);
  expectNoOverlap(result);
  for (const LabelBox& box : result) EXPECT_LE(box.y + box.height, 200);
}

// More labels than the band holds: they leave it rather than overlap.
TEST(LabelLayout, TooManyLabelsForTheBandStillDoNotOverlap) {
  std::vector<LabelBox> boxes(10, LabelBox{0, 20, 40, 12});
  expectNoOverlap(placed(boxes, 0, 50));
}

// The cost plot: labels beside random points, overlapping in x and y.
TEST(LabelLayout, RandomLabelsNeverOverlap) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> x(0, 300), y(0, 200), width(20, 90);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<LabelBox> boxes;
    for (int i = 0; i < 12; ++i) boxes.push_back({x(random), y(random), width(random), 13});
    expectNoOverlap(placed(boxes, 0, 220));
  }
}

TEST(LabelLayout, WidthGrowsWithTheText) {
  EXPECT_GT(labelWidth("lights-shadowed", 11), labelWidth("sh", 11));
  EXPECT_GE(labelWidth("lights-shadowed", 11), 15 * 11 * 0.55);
}

}  // namespace
}  // namespace iblkit
