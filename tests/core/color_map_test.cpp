#include "core/color_map.h"

#include <gtest/gtest.h>

#include "core/image.h"
#include "core/tone_curve.h"

namespace iblkit {
namespace {

glm::vec3 encoded(const glm::vec3& linear) {
  return {srgbEncode(linear.r), srgbEncode(linear.g), srgbEncode(linear.b)};
}

TEST(ColorMap, MagmaEndsAreThePublishedColours) {
  const glm::vec3 black = encoded(magma(0.0f)) * 255.0f, pale = encoded(magma(1.0f)) * 255.0f;
  EXPECT_NEAR(black.b, 4.0f, 1e-3f);
  EXPECT_NEAR(pale.r, 252.0f, 1e-3f);
  EXPECT_NEAR(pale.g, 253.0f, 1e-3f);
  EXPECT_NEAR(pale.b, 191.0f, 1e-3f);
  // Lightness grows along the map (perceptually ordered).
  float previous = -1.0f;
  for (int i = 0; i <= 20; ++i) {
    const float y = luminance(magma(i / 20.0f));
    EXPECT_GT(y, previous) << i;
    previous = y;
  }
  EXPECT_EQ(magma(-1.0f), magma(0.0f));
  EXPECT_EQ(magma(2.0f), magma(1.0f));
}

}  // namespace
}  // namespace iblkit
