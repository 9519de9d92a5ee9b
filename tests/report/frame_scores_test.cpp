#include "report/frame_scores.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "score/image_metrics.h"

namespace iblkit {
namespace {

Image constant(int w, int h, float value) { return Image(w, h, glm::vec4(value, value, value, 1.0f)); }

TEST(FrameScores, IdenticalFramesScoreZero) {
  const Image reference = constant(32, 24, 0.7f);
  const FrameScores scores = scoreFrame(reference, reference, {}, ExposureRange{-2.0f, 2.0f, 4});
  EXPECT_EQ(scores.meanFlip, 0.0);
  EXPECT_EQ(scores.relMse, 0.0);
  EXPECT_EQ(scores.meanRelativeError, 0.0);
  EXPECT_NEAR(scores.ssim, 1.0, 1e-9);
  EXPECT_EQ(scores.invalidPixels, 0u);
}

TEST(FrameScores, MeanRelativeErrorIsLuminanceWeighted) {
  // Half the scored pixels 10% too bright, on a reference of 1 and 3: sum|dL| / sum L.
  Image reference = constant(4, 1, 1.0f), test = constant(4, 1, 1.0f);
  reference.at(1, 0) = glm::vec4(3, 3, 3, 1);
  test.at(1, 0) = glm::vec4(3.3f, 3.3f, 3.3f, 1);
  test.at(0, 0) = glm::vec4(1.1f, 1.1f, 1.1f, 1);
  const std::vector<std::uint8_t> mask = {1, 1, 0, 0};
  const FrameScores scores = scoreFrame(reference, test, mask, ExposureRange{-1.0f, 1.0f, 2});
  EXPECT_NEAR(scores.meanRelativeError, 0.4 / 4.0, 1e-6);
  EXPECT_NEAR(scores.relMse, relativeMeanSquaredError(reference, test, mask), 1e-12);
  EXPECT_GT(scores.meanFlip, 0.0);
}

TEST(FrameScores, NanPixelsAreCountedNotAveraged) {
  const Image reference = constant(8, 8, 0.5f);
  Image test = reference;
  test.at(3, 3).g = std::numeric_limits<float>::quiet_NaN();
  test.at(4, 4).r = std::numeric_limits<float>::infinity();
  const FrameScores scores = scoreFrame(reference, test, {}, ExposureRange{});
  EXPECT_EQ(scores.invalidPixels, 2u);
  EXPECT_EQ(scores.meanFlip, 0.0);
}

TEST(FrameScores, GeometryMaskFromDepth) {
  Image depth(3, 1, glm::vec4(0.0f));
  depth.at(1, 0).r = 2.5f;
  EXPECT_EQ(geometryMask(depth), (std::vector<std::uint8_t>{0, 1, 0}));
}

TEST(FrameScores, ErodeMaskDropsTheRimAndTheBorder) {
  // 5x4: a 3x3 block of ones at x 1..3, y 0..2 (touching the top border).
  const std::vector<std::uint8_t> mask = {0, 1, 1, 1, 0,  //
                                          0, 1, 1, 1, 0,  //
                                          0, 1, 1, 1, 0,  //
                                          0, 0, 0, 0, 0};
  const std::vector<std::uint8_t> expected = {0, 0, 0, 0, 0,  //
                                              0, 0, 1, 0, 0,  //
                                              0, 0, 0, 0, 0,  //
                                              0, 0, 0, 0, 0};
  EXPECT_EQ(erodeMask(mask, 5, 4), expected);
}

}  // namespace
}  // namespace iblkit
