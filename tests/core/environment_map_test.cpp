#include "core/environment_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>

#include "core/error.h"
#include "core/latlong.h"
#include "support/error_capture.h"
#include "support/expect_near.h"

namespace iblkit {
namespace {

constexpr double kPi = std::numbers::pi;

using test::expectNear;

// A smooth, non-symmetric radiance pattern, as a 128 x 64 lat-long image and as a map.
Image patternImage() {
  return latLongFromRadiance(128, 64, 1, [](const glm::vec3& d) {
    return glm::vec3(1.0f + d.x, 1.0f + 0.5f * d.y, 2.0f + d.z * d.x);
  });
}
EnvironmentMap patternMap() { return EnvironmentMap::fromImage(patternImage(), "pattern.exr"); }

TEST(EnvironmentMap, FromImageChecksTheImage) {
  EXPECT_EQ(test::errorMessage([] { EnvironmentMap::fromImage(Image(3, 2), "sky.exr"); }),
            "sky.exr: lat-long map is 3x2, expected a 2:1 aspect ratio");
  EXPECT_EQ(test::errorMessage([] { EnvironmentMap::fromImage(Image(4, 4), "sky.exr"); }),
            "sky.exr: lat-long map is 4x4, expected a 2:1 aspect ratio");
  EXPECT_EQ(test::errorMessage([] { EnvironmentMap::fromImage(Image(), "empty.exr"); }),
            "empty.exr: lat-long map is 0x0, expected at least 2x1");
  Image bad(8, 4, glm::vec4(1.0f));
  bad.at(1, 1).g = NAN;
  bad.at(2, 3).b = -0.5f;
  bad.at(3, 0).r = INFINITY;
  bad.at(4, 0).a = NAN;  // alpha is not radiance
  EXPECT_EQ(test::errorMessage([&] { EnvironmentMap::fromImage(bad, "bad.hdr"); }),
            "bad.hdr: lat-long map has 3 pixels that are NaN, infinite, negative or above 1e18");
  const EnvironmentMap smallest = EnvironmentMap::fromImage(Image(2, 1, glm::vec4(0.5f)), "tiny.exr");
  EXPECT_EQ(smallest.width(), 2);
  EXPECT_EQ(smallest.height(), 1);
  expectNear(smallest.radiance({0, 1, 0}), glm::vec3(0.5f), 0.0f);
}

TEST(EnvironmentMap, ExposesTheImageUnchanged) {
  EnvironmentMap map = patternMap();
  map.setIntensity(3.0f);
  map.setRotationDegrees(40.0f);
  EXPECT_EQ(map.image().pixels(), patternImage().pixels());
  EXPECT_EQ(map.texelRadiance(17, 9), 3.0f * glm::vec3(map.image().at(17, 9)));
  EXPECT_FLOAT_EQ(map.texelLuminance(17, 9), luminance(3.0f * glm::vec3(map.image().at(17, 9))));
}

TEST(EnvironmentMap, PositiveRotationTurnsZTowardsX) {
  const EnvironmentMap unrotated = patternMap();
  EnvironmentMap rotated = patternMap();
  rotated.setRotationDegrees(90.0f);
  EXPECT_EQ(rotated.rotationDegrees(), 90.0f);
  // With +90 degrees, what the map shows at +Z (its image centre) is seen looking along +X,
  // what it shows at -X is seen along +Z, and +Y stays.
  expectNear(rotated.radiance({1, 0, 0}), unrotated.radiance({0, 0, 1}), 1e-5f);
  expectNear(rotated.radiance({0, 0, 1}), unrotated.radiance({-1, 0, 0}), 1e-5f);
  expectNear(rotated.radiance({0, 0, -1}), unrotated.radiance({1, 0, 0}), 1e-5f);
  expectNear(rotated.radiance({0, 1, 0}), unrotated.radiance({0, 1, 0}), 1e-5f);
  expectNear(rotated.toMapDirection({1, 0, 0}), {0, 0, 1}, 1e-7f);
  expectNear(rotated.toWorldDirection({0, 0, 1}), {1, 0, 0}, 1e-7f);
  // In the image: the environment slides left by a quarter of the width.
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> uniform(0.05f, 0.95f);
  for (int i = 0; i < 200; ++i) {
    const glm::vec2 uv(uniform(rng), uniform(rng));
    expectNear(rotated.radiance(latLongDirection(uv)),
               unrotated.radiance(latLongDirection(uv + glm::vec2(0.25f, 0))), 1e-4f);
  }
  // Any angle: a feature at map direction m is seen at world direction R_y(angle) m.
  rotated.setRotationDegrees(-30.0f);
  const double a = -30.0 * kPi / 180.0;
  const glm::vec3 m = glm::normalize(glm::vec3(0.3f, 0.4f, -0.8f));
  const glm::vec3 world(static_cast<float>(std::cos(a) * m.x + std::sin(a) * m.z), m.y,
                        static_cast<float>(-std::sin(a) * m.x + std::cos(a) * m.z));
  expectNear(rotated.radiance(world), unrotated.radiance(m), 1e-5f);
}

TEST(EnvironmentMap, HotPixelIsSeenAtItsTexelDirection) {
  EnvironmentMap map = EnvironmentMap::hotPixel(16, 3, 2, glm::vec3(5.0f, 4.0f, 3.0f));
  map.setRotationDegrees(90.0f);
  map.setIntensity(2.0f);
  const glm::vec3 direction = map.texelDirection(3, 2);
  // Texel 3 of 16 has longitude 2 pi (0.5 - 3.5/16) = 101.25 degrees; +90 makes it 191.25.
  const double longitude = (101.25 + 90.0) * kPi / 180.0, latitude = kPi * (0.5 - 2.5 / 8.0);
  expectNear(direction,
             glm::vec3(static_cast<float>(std::cos(latitude) * std::sin(longitude)),
                       static_cast<float>(std::sin(latitude)),
                       static_cast<float>(std::cos(latitude) * std::cos(longitude))),
             1e-6f);
  expectNear(map.radiance(direction), glm::vec3(10.0f, 8.0f, 6.0f), 1e-4f);
  expectNear(map.radianceNearest(direction * 7.0f), glm::vec3(10.0f, 8.0f, 6.0f), 0.0f);
  expectNear(map.radianceNearest(-direction), glm::vec3(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(map.texelLuminance(3, 2), luminance(glm::vec3(10.0f, 8.0f, 6.0f)));
  EXPECT_EQ(map.texelLuminance(4, 2), 0.0f);
  EXPECT_THROW(EnvironmentMap::hotPixel(16, 16, 2, glm::vec3(1.0f)), std::invalid_argument);
}

TEST(EnvironmentMap, ConstantIsConstantEverywhere) {
  EnvironmentMap map = EnvironmentMap::constant(glm::vec3(0.25f, 0.5f, 1.0f));
  map.setIntensity(4.0f);
  map.setRotationDegrees(33.0f);
  std::mt19937 rng(4);
  std::normal_distribution<float> normal;
  for (int i = 0; i < 1000; ++i)
    EXPECT_EQ(map.radiance({normal(rng), normal(rng), normal(rng)}), glm::vec3(1.0f, 2.0f, 4.0f));
  EXPECT_EQ(map.radiance({0, 1, 0}), glm::vec3(1.0f, 2.0f, 4.0f));
  EXPECT_EQ(map.radiance({0, 0, -1}), glm::vec3(1.0f, 2.0f, 4.0f));
  EXPECT_THROW(EnvironmentMap::constant(glm::vec3(1.0f), 7), std::invalid_argument);
}

TEST(EnvironmentMap, TexelSolidAnglesSumToTheSphere) {
  const EnvironmentMap map = patternMap();
  double sum = 0.0;
  for (int y = 0; y < map.height(); ++y) sum += map.width() * map.texelSolidAngle(y);
  EXPECT_NEAR(sum / (4.0 * kPi), 1.0, 1e-4);
  EXPECT_FLOAT_EQ(map.texelSolidAngle(5), latLongTexelSolidAngle(128, 64, 5));
}

TEST(EnvironmentMap, IntensityScalesAndIsChecked) {
  EnvironmentMap map = patternMap();
  const glm::vec3 d(0.2f, -0.4f, 0.7f);
  const glm::vec3 before = map.radiance(d);
  map.setIntensity(0.5f);
  EXPECT_EQ(map.intensity(), 0.5f);
  expectNear(map.radiance(d), 0.5f * before, 1e-6f);
  EXPECT_THROW(map.setIntensity(-1.0f), std::invalid_argument);
  EXPECT_THROW(map.setIntensity(NAN), std::invalid_argument);
  EXPECT_THROW(map.setRotationDegrees(INFINITY), std::invalid_argument);
  EXPECT_EQ(map.intensity(), 0.5f);
}

}  // namespace
}  // namespace iblkit
