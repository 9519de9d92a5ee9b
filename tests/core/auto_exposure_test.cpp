// The key of an image (core/auto_exposure.h): the log-average luminance, the pixels that count,
// and the exposure that brings the key to middle grey.
#include "core/auto_exposure.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace iblkit {
namespace {

Image grey(int width, int height, float value) {
  Image image(width, height);
  for (glm::vec4& p : image.pixels()) p = glm::vec4(value, value, value, 1.0f);
  return image;
}

TEST(AutoExposure, AConstantImageIsItsOwnKeyAndIsBroughtToMiddleGrey) {
  const Image image = grey(4, 3, 2.5f);
  ASSERT_TRUE(logAverageLuminance(image).has_value());
  EXPECT_NEAR(*logAverageLuminance(image), 2.5f, 1e-5f);
  EXPECT_NEAR(keyExposure(image), std::log2(0.18f / 2.5f), 1e-5f);
  // The exposure applied: the key lands on 0.18.
  EXPECT_NEAR(2.5f * std::exp2(keyExposure(image)), kMiddleGrey, 1e-5f);
}

TEST(AutoExposure, TheKeyIsTheGeometricMeanNotTheArithmeticOne) {
  Image image = grey(2, 1, 0.01f);
  image.pixels()[1] = glm::vec4(100.0f, 100.0f, 100.0f, 1.0f);
  EXPECT_NEAR(*logAverageLuminance(image), 1.0f, 1e-4f);  // sqrt(0.01 * 100); the mean is ~50
}

TEST(AutoExposure, UsesLuminanceWeights) {
  Image image = grey(1, 1, 0.0f);
  image.pixels()[0] = glm::vec4(0.0f, 1.0f, 0.0f, 1.0f);
  EXPECT_NEAR(*logAverageLuminance(image), 0.7152f, 1e-5f);
}

TEST(AutoExposure, BlackAndNonFinitePixelsAndMaskedOnesDoNotCount) {
  Image image = grey(4, 1, 0.5f);
  image.pixels()[0] = glm::vec4(0.0f);  // no sky: black background
  image.pixels()[1] = glm::vec4(std::numeric_limits<float>::quiet_NaN());
  image.pixels()[2] = glm::vec4(8.0f, 8.0f, 8.0f, 1.0f);
  EXPECT_NEAR(*logAverageLuminance(image), 2.0f, 1e-5f);  // sqrt(0.5 * 8)
  const std::vector<std::uint8_t> mask = {1, 1, 0, 1};
  EXPECT_NEAR(*logAverageLuminance(image, mask), 0.5f, 1e-5f);
}

TEST(AutoExposure, NothingThatCountsGivesNoKeyAndExposureZero) {
  EXPECT_FALSE(logAverageLuminance(grey(3, 3, 0.0f)).has_value());
  EXPECT_EQ(keyExposure(grey(3, 3, 0.0f)), 0.0f);
  const std::vector<std::uint8_t> none(9, 0);
  EXPECT_EQ(keyExposure(grey(3, 3, 1.0f), none), 0.0f);
}

TEST(AutoExposure, ExtremeKeysAreClampedTo16Stops) {
  EXPECT_EQ(keyExposure(grey(1, 1, 1e-30f)), 16.0f);
  EXPECT_EQ(keyExposure(grey(1, 1, 1e30f)), -16.0f);
}

}  // namespace
}  // namespace iblkit
