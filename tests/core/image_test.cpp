#include "core/image.h"

#include <gtest/gtest.h>

namespace iblkit {
namespace {

TEST(Image, StatsOfKnownPixels) {
  Image image(2, 1);
  image.at(0, 0) = glm::vec4(1.0f, 2.0f, 3.0f, 1.0f);
  image.at(1, 0) = glm::vec4(3.0f, 0.0f, 1.0f, 1.0f);
  const Image::Stats s = image.stats();
  EXPECT_FLOAT_EQ(s.mean.x, 2.0f);
  EXPECT_FLOAT_EQ(s.mean.y, 1.0f);
  EXPECT_FLOAT_EQ(s.max.z, 3.0f);
  EXPECT_FLOAT_EQ(s.min.y, 0.0f);
  EXPECT_NEAR(s.maxLuminance, luminance(glm::vec3(1, 2, 3)), 1e-6f);
}

TEST(Image, DownsampleAveragesAndHandlesOddSizes) {
  Image image(3, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) image.at(x, y) = glm::vec4(float(x + 3 * y));
  const Image half = downsample2x(image);
  ASSERT_EQ(half.width(), 2);
  ASSERT_EQ(half.height(), 2);
  EXPECT_FLOAT_EQ(half.at(0, 0).x, (0 + 1 + 3 + 4) / 4.0f);
  EXPECT_FLOAT_EQ(half.at(1, 1).x, 8.0f);  // the corner pixel reused four times
}

}  // namespace
}  // namespace iblkit
