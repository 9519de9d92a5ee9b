// The repair of negative texels that keeps a lat-long map's integral (energy_preserving_repair.h):
// a synthetic DWAB-like ringing sun, the fallback to the whole map, maps that cannot be repaired,
// the loader's warning, and the real sky.exr against its raw signed sum.
#include "core/energy_preserving_repair.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "core/cube_map.h"
#include "core/environment_map_file.h"
#include "core/image_io.h"
#include "core/latlong.h"
#include "support/test_paths.h"
#include "support/warning_capture.h"

namespace iblkit {
namespace {

// sum L_i Omega_i per channel, in double.
glm::dvec3 signedIntegral(const Image& latLong) {
  glm::dvec3 sum(0.0);
  for (int y = 0; y < latLong.height(); ++y) {
    const double omega = latLongTexelSolidAngle(latLong.width(), latLong.height(), y);
    for (int x = 0; x < latLong.width(); ++x) sum += glm::dvec3(glm::vec3(latLong.at(x, y))) * omega;
  }
  return sum;
}

float smallestValue(const Image& image) {
  float smallest = 0.0f;
  for (const glm::vec4& pixel : image.pixels())
    smallest = std::min({smallest, pixel.r, pixel.g, pixel.b, pixel.a});
  return smallest;
}

// A 128 x 64 sky of (0.5, 0.6, 0.7) with a sun of radius 1.5 texels at texel (kSunX, kSunY) and a
// ring of negative overshoot at 2 to 3 texels from its centre, as DWAB leaves it: the ring takes
// about a fifth of the sun's energy, so clamping it adds that much.
constexpr int kSunX = 3, kSunY = 20;  // near the seam, so the windows wrap in longitude
constexpr float kRingOuterRadius = 3.0f;

float distanceToSun(int x, int y, int width) {
  const int dx = std::min(std::abs(x - kSunX), width - std::abs(x - kSunX));
  return std::hypot(float(dx), float(y - kSunY));
}

Image ringingSun() {
  Image image(128, 64, glm::vec4(0.5f, 0.6f, 0.7f, 1.0f));
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const float r = distanceToSun(x, y, image.width());
      if (r <= 1.5f)
        image.at(x, y) = glm::vec4(2000.0f, 1800.0f, 1500.0f, 1.0f);
      else if (r <= kRingOuterRadius)
        image.at(x, y) = glm::vec4(-150.0f, -130.0f, -110.0f, 1.0f);
    }
  return image;
}

TEST(RepairNegativeRadiance, RingingSunKeepsItsIntegralLocally) {
  const Image original = ringingSun();
  Image repaired = original;
  const NegativeRadianceRepair repair = repairNegativeRadiance(repaired);
  const glm::dvec3 before = signedIntegral(original), after = signedIntegral(repaired);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(after[c], before[c], 1e-6 * before[c]) << c;
    EXPECT_NEAR(repair.signedEnergy[c], before[c], 1e-9 * before[c]);
    EXPECT_LT(repair.negativeEnergy[c], -0.1 * before[c]);  // the ring matters: > 10% of the map
  }
  EXPECT_EQ(smallestValue(repaired), 0.0f);
  EXPECT_TRUE(repair.energyKept);
  EXPECT_EQ(repair.paidByWholeMap, 0u);
  // Each ring texel is paid by a window reaching the sun (radius <= 3 from any ring texel)...
  EXPECT_GE(repair.largestRadius, 1);
  EXPECT_LE(repair.largestRadius, 3);
  std::size_t ringValues = 0;
  for (int y = 0; y < original.height(); ++y)
    for (int x = 0; x < original.width(); ++x) {
      const float r = distanceToSun(x, y, original.width());
      if (r > 1.5f && r <= kRingOuterRadius) ringValues += 3;
      // ...so texels farther than the ring plus that radius are untouched, bit for bit.
      if (r > kRingOuterRadius + float(repair.largestRadius) * std::sqrt(2.0f) + 0.01f) {
        ASSERT_EQ(repaired.at(x, y), original.at(x, y)) << x << " " << y;
      }
    }
  EXPECT_EQ(repair.negativeValues, ringValues);
  // Most of the ring's energy came out of the sun, not the sky around it.
  const Image& image = repaired;
  double sunBefore = 0.0, sunAfter = 0.0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (distanceToSun(x, y, image.width()) <= 1.5f) {
        const double omega = latLongTexelSolidAngle(image.width(), image.height(), y);
        sunBefore += original.at(x, y).r * omega;
        sunAfter += image.at(x, y).r * omega;
      }
  EXPECT_GT(sunBefore - sunAfter, 0.99 * -repair.negativeEnergy.r);
}

TEST(RepairNegativeRadiance, DebtNoNeighbourhoodCanPayComesFromTheWholeMap) {
  // One negative texel in a black region; the only positive texel is 40 texels away.
  Image image(128, 64, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  image.at(10, 32) = glm::vec4(-1.0f, -1.0f, -1.0f, 1.0f);
  image.at(60, 32) = glm::vec4(10.0f, 10.0f, 10.0f, 1.0f);
  const glm::dvec3 before = signedIntegral(image);
  const NegativeRadianceRepair repair = repairNegativeRadiance(image);
  EXPECT_EQ(repair.paidByWholeMap, 3u);
  EXPECT_EQ(repair.largestRadius, 0);
  EXPECT_FLOAT_EQ(image.at(60, 32).r, 9.0f);
  EXPECT_EQ(image.at(10, 32), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  EXPECT_NEAR(signedIntegral(image).g, before.g, 1e-6 * before.g);
}

TEST(RepairNegativeRadiance, MapWithMoreNegativeThanPositiveEnergyIsClamped) {
  Image image(16, 8, glm::vec4(-1.0f, 1.0f, 1.0f, 1.0f));
  image.at(3, 3).r = 2.0f;
  image.at(0, 0).a = -1.0f;
  const NegativeRadianceRepair repair = repairNegativeRadiance(image);
  EXPECT_FALSE(repair.energyKept);
  EXPECT_EQ(repair.negativeValues, 16u * 8u - 1u + 1u);  // the red values and one alpha
  EXPECT_EQ(smallestValue(image), 0.0f);
  EXPECT_EQ(image.at(3, 3).r, 2.0f);
  EXPECT_EQ(environmentRepairSummary({}, repair),
            "128 negative pixel values set to 0; the map's energy is not kept (its negative values outweigh "
            "the positive ones)");
}

TEST(RepairNegativeRadiance, LoaderWarnsOnceWithTheEnergyMoved) {
  const std::filesystem::path file = test::scratchDir() / "ringing.exr";
  const Image signedMap = ringingSun();
  writeExr(file, signedMap, {.pixelType = PixelType::Float});
  std::size_t negativeValues = 0;
  for (const glm::vec4& pixel : signedMap.pixels())
    negativeValues += (pixel.r < 0) + (pixel.g < 0) + (pixel.b < 0);
  test::WarningCapture capture;
  const EnvironmentMap map = loadEnvironmentMap(file);
  ASSERT_EQ(capture.lines().size(), 1u);
  const std::string& line = capture.lines().front();
  const std::string head = file.string() + ": warning: " + std::to_string(negativeValues) +
                           " negative pixel values set to 0; the negative values' -";
  ASSERT_EQ(line.substr(0, head.size()), head) << line;
  EXPECT_NE(line.find("% of the map's energy (luminance) taken from positive texels within "),
            std::string::npos);
  EXPECT_EQ(line.substr(line.size() - 7), " texels") << line;
  // The percentage is the ring's share of the signed map's luminance integral.
  double negative = 0.0;
  for (int y = 0; y < signedMap.height(); ++y)
    for (int x = 0; x < signedMap.width(); ++x) {
      const float value = luminance(glm::vec3(signedMap.at(x, y)));
      if (value < 0.0f) negative += value * latLongTexelSolidAngle(signedMap.width(), signedMap.height(), y);
    }
  const double total = glm::dot(signedIntegral(signedMap), glm::dvec3(0.2126, 0.7152, 0.0722));
  const double shown = std::strtod(line.c_str() + head.size() - 1, nullptr);
  EXPECT_NEAR(shown, 100.0 * negative / total, 0.01 * std::abs(shown)) << line;
  const glm::dvec3 loaded = signedIntegral(map.image()), expected = signedIntegral(signedMap);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(loaded[c], expected[c], 1e-6 * expected[c]);
}

TEST(RepairNegativeRadiance, NanAndInfBecomeZeroInTheSameWarning) {
  const std::filesystem::path file = test::dataDir() / "bad" / "nan_pixels.exr";
  test::WarningCapture capture;
  const EnvironmentMap map = loadEnvironmentMap(file);
  EXPECT_EQ(smallestValue(map.image()), 0.0f);
  ASSERT_EQ(capture.lines().size(), 1u);
  const std::string head =
      file.string() + ": warning: 3 NaN, 1 Inf and 2 negative pixel values set to 0; the negative values' -";
  EXPECT_EQ(capture.lines().front().substr(0, head.size()), head) << capture.lines().front();
}

TEST(RepairNegativeRadiance, CubeMapsAreRepairedAfterTheirConversion) {
  // The conversion sees the negative values as stored: a cube face texel of -1 next to positive
  // ones ends as a lat-long map with no negative texel and one warning.
  CubeMap cube = cubeFromRadiance(8, 1, [](const glm::vec3&) { return glm::vec3(1.0f); });
  cube.faces[0].at(4, 4) = glm::vec4(-5.0f, -5.0f, -5.0f, 1.0f);
  const std::filesystem::path file = test::scratchDir() / "cube.exr";
  writeExr(file, cubeToExrStrip(cube), {.pixelType = PixelType::Float, .envmap = EnvmapLayout::Cube});
  test::WarningCapture capture;
  const EnvironmentMap map = loadEnvironmentMap(file);
  EXPECT_EQ(smallestValue(map.image()), 0.0f);
  ASSERT_EQ(capture.lines().size(), 1u);
  EXPECT_NE(capture.lines().front().find("negative pixel values set to 0; the negative values' -"),
            std::string::npos)
      << capture.lines().front();
}

// The real DWAB-compressed sky.exr (assets/hdri): the loaded map keeps the integral of the raw
// file's signed values, where clamping added about 12.7%.
TEST(RepairNegativeRadiance, SkyExrKeepsTheRawSignedIntegral) {
  const std::filesystem::path file = test::assetsDir() / "hdri" / "sky.exr";
  if (!std::filesystem::is_regular_file(file)) GTEST_SKIP() << "no asset " << file;
  const Image raw = readExr(file, nullptr, 0, PixelRepair::Keep);
  Image clamped = raw;
  for (glm::vec4& pixel : clamped.pixels()) pixel = glm::max(pixel, glm::vec4(0.0f));
  test::WarningCapture capture;
  const EnvironmentMap map = loadEnvironmentMap(file);
  const glm::dvec3 expected = signedIntegral(raw), loaded = signedIntegral(map.image()),
                   clampedSum = signedIntegral(clamped);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(loaded[c], expected[c], 1e-4 * expected[c]) << c;
    EXPECT_GT(clampedSum[c], 1.1 * expected[c]) << c;  // what the clamp did
  }
  EXPECT_EQ(smallestValue(map.image()), 0.0f);
  ASSERT_EQ(capture.lines().size(), 1u);
  EXPECT_NE(
      capture.lines().front().find("% of the map's energy (luminance) taken from positive texels within"),
      std::string::npos)
      << capture.lines().front();
}

}  // namespace
}  // namespace iblkit
