// SH9's own error on a view, and what a frame adds to it (report/sh9_truncation.h).
#include "report/sh9_truncation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/environment_sh.h"
#include "core/error.h"
#include "core/latlong.h"

namespace iblkit {
namespace {

// A normal layer: a hemisphere of directions facing +Z over a w x h image, every pixel scored.
Image hemisphereNormals(int w, int h) {
  Image normals(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float u = 2.0f * (x + 0.5f) / w - 1.0f, v = 1.0f - 2.0f * (y + 0.5f) / h;
      const float z = std::sqrt(std::max(0.0f, 1.0f - 0.5f * (u * u + v * v)));
      normals.at(x, y) = glm::vec4(glm::normalize(glm::vec3(u * 0.7f, v * 0.7f, z)), 0.0f);
    }
  return normals;
}

TEST(Sh9Truncation, AveragingDownKeepsEveryBlocksPower) {
  const EnvironmentMap sun = EnvironmentMap::hotPixel(64, 20, 9, glm::vec3(1000.0f));
  const Image coarse = averageLatLongDown(sun.image(), 16);
  ASSERT_EQ(coarse.width(), 16);
  ASSERT_EQ(coarse.height(), 8);
  double fine = 0.0, reduced = 0.0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) fine += sun.image().at(x, y).r * latLongTexelSolidAngle(64, 32, y);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x) reduced += coarse.at(x, y).r * latLongTexelSolidAngle(16, 8, y);
  EXPECT_NEAR(reduced / fine, 1.0, 1e-4);
  EXPECT_GT(coarse.at(5, 2).r, 0.0f);  // the block holding texel (20, 9)
}

TEST(Sh9Truncation, SmoothLightIsExactAndASunIsNot) {
  const Image normals = hemisphereNormals(24, 16);
  const std::vector<std::uint8_t> mask(normals.pixelCount(), 1);
  // A constant map is band 0 only: SH9 holds it exactly.
  const EnvironmentMap constant = EnvironmentMap::constant(glm::vec3(0.7f), 64);
  const Sh9Truncation exact = sh9Truncation(constant, projectEnvironmentSh9(constant), normals, mask);
  EXPECT_LT(exact.meanRelativeError, 2e-3);
  for (float r : exact.ratio) EXPECT_NEAR(r, 1.0f, 5e-3f);
  // One bright texel (a sun) is all high frequencies: SH9 is far off, in both directions.
  const EnvironmentMap sun = EnvironmentMap::hotPixel(64, 16, 10, glm::vec3(5000.0f));
  const Sh9Truncation truncated = sh9Truncation(sun, projectEnvironmentSh9(sun), normals, mask);
  EXPECT_GT(truncated.meanRelativeError, 0.1);
  float lowest = 10.0f, highest = 0.0f;
  for (float r : truncated.ratio) lowest = std::min(lowest, r), highest = std::max(highest, r);
  EXPECT_LT(lowest, 0.95f);
  EXPECT_GT(highest, 1.05f);
  // Unscored pixels keep ratio 1 and do not count.
  std::vector<std::uint8_t> none(normals.pixelCount(), 0);
  const Sh9Truncation empty = sh9Truncation(sun, projectEnvironmentSh9(sun), normals, none);
  EXPECT_EQ(empty.meanRelativeError, 0.0);
  EXPECT_THROW(sh9Truncation(sun, projectEnvironmentSh9(sun), normals, std::vector<std::uint8_t>(3, 1)), Error);
}

TEST(Sh9Truncation, ErrorBeyondSh9IsZeroForSh9ItselfAndSeesACoherentError) {
  Sh9Truncation truncation;
  const int w = 32, h = 32;
  Image reference(w, h), frame(w, h), brighter(w, h), noisy(w, h);
  truncation.ratio.assign(std::size_t(w) * h, 1.0f);
  std::uint32_t state = 12345;
  auto uniform = [&] {
    state = state * 1664525u + 1013904223u;
    return float(state >> 8) / float(1u << 24);
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      const float truth = 1.0f + 0.5f * std::sin(0.2f * x);
      truncation.ratio[i] = 0.9f + 0.2f * float(y) / h;
      reference.pixels()[i] = glm::vec4(glm::vec3(truth), 1.0f);
      frame.pixels()[i] = glm::vec4(glm::vec3(truth * truncation.ratio[i]), 1.0f);
      brighter.pixels()[i] = glm::vec4(glm::vec3(1.05f * truth * truncation.ratio[i]), 1.0f);
      // The same reference with zero-mean noise of 10% per pixel.
      noisy.pixels()[i] = glm::vec4(glm::vec3(truth * (1.0f + 0.2f * (uniform() - 0.5f) * std::sqrt(3.0f))), 1.0f);
    }
  const std::vector<std::uint8_t> mask(std::size_t(w) * h, 1);
  EXPECT_NEAR(errorBeyondSh9(reference, frame, truncation, mask), 0.0, 1e-6);
  EXPECT_NEAR(errorBeyondSh9(reference, brighter, truncation, mask), 0.05, 2e-3);  // 5% too bright
  // A noisy reference: the 16x16 blocks average most of its 10% per-pixel noise away.
  EXPECT_LT(errorBeyondSh9(noisy, frame, truncation, mask), 0.02);
}

}  // namespace
}  // namespace iblkit
