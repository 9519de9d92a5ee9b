// The kinds of map (report/map_kind.h): the rule on synthetic maps of known concentration and on
// the six bundled maps.
#include "report/map_kind.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/environment_map_file.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

constexpr int kWidth = 512, kHeight = 256;

// A sky of radiance 1 with a disk of `radiusDegrees` toward +Y-ish that holds `share` of the
// map's energy.
EnvironmentMap skyWithDisk(float radiusDegrees, double share) {
  EnvironmentMap probe = EnvironmentMap::constant(glm::vec3(1.0f), kWidth);
  const glm::vec3 centre = glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f));
  const float cosRadius = std::cos(radiusDegrees * std::numbers::pi_v<float> / 180.0f);
  double diskSolidAngle = 0.0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      if (glm::dot(probe.texelDirection(x, y), centre) >= cosRadius) diskSolidAngle += probe.texelSolidAngle(y);
  // share = D a / (D a + (4 pi - D)), a the disk's radiance, the rest radiance 1.
  const double rest = 4.0 * std::numbers::pi - diskSolidAngle;
  const float radiance = float(share * rest / ((1.0 - share) * diskSolidAngle));
  Image image(kWidth, kHeight, glm::vec4(1.0f));
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      if (glm::dot(probe.texelDirection(x, y), centre) >= cosRadius) image.at(x, y) = glm::vec4(glm::vec3(radiance), 1.0f);
  return EnvironmentMap::fromImage(std::move(image), "disk.exr");
}

TEST(MapKind, SharesOfKnownMaps) {
  // A constant map: the brightest fraction f of the sphere holds the share f.
  const MapConcentration constant = mapConcentration(EnvironmentMap::constant(glm::vec3(2.0f), kWidth));
  EXPECT_NEAR(constant.sunShare, kSunSolidAngleFraction, 1e-6);
  EXPECT_NEAR(constant.sourceShare, kSourceSolidAngleFraction, 1e-5);
  EXPECT_EQ(classifyMap(constant), MapKind::Soft);
  // One hot texel holds everything.
  const MapConcentration hot = mapConcentration(EnvironmentMap::hotPixel(kWidth, 100, 60, glm::vec3(1e4f)));
  EXPECT_NEAR(hot.sunShare, 1.0, 1e-9);
  EXPECT_EQ(classifyMap(hot), MapKind::Sunny);
  EXPECT_EQ(brightestEnergyShare(EnvironmentMap::constant(glm::vec3(0.0f), kWidth), 0.5), 0.0);
}

TEST(MapKind, SunsSourcesAndSoftMaps) {
  // A 0.5-degree sun with 60% of the energy; a 0.5-degree sun with 20%: not sunny.
  const MapConcentration sun = mapConcentration(skyWithDisk(0.5f, 0.6));
  EXPECT_NEAR(sun.sunShare, 0.6, 0.01);
  EXPECT_EQ(classifyMap(sun), MapKind::Sunny);
  EXPECT_EQ(classifyMap(mapConcentration(skyWithDisk(0.5f, 0.2))), MapKind::Soft);
  // A 5-degree softbox with 80%: its 0.0239 sr hold the brightest 1% of the sphere (0.126 sr), but
  // the brightest 1e-4 of the sphere (1.26e-3 sr) only 0.8 x 1.26e-3 / 0.0239 of the energy.
  const MapConcentration softbox = mapConcentration(skyWithDisk(5.0f, 0.8));
  EXPECT_NEAR(softbox.sunShare, 0.8 * 4e-4 * std::numbers::pi / 0.0239, 0.01);
  EXPECT_GT(softbox.sourceShare, 0.8);
  EXPECT_EQ(classifyMap(softbox), MapKind::Studio);
  // A 30-degree bright region (a sky dome's brighter half) with 50% is soft.
  EXPECT_EQ(classifyMap(mapConcentration(skyWithDisk(30.0f, 0.5))), MapKind::Soft);
}

// The table of docs/report.md "Kinds of map" (printed).
TEST(MapKind, BundledMaps) {
  const std::pair<const char*, MapKind> expected[] = {{"sky", MapKind::Sunny},   {"esplanade", MapKind::Sunny},
                                                      {"studio", MapKind::Studio}, {"city", MapKind::Soft},
                                                      {"forest", MapKind::Soft},   {"sunset", MapKind::Soft}};
  for (const auto& [name, kind] : expected) {
    const MapConcentration shares =
        mapConcentration(loadEnvironmentMap(test::assetsDir() / "hdri" / (std::string(name) + ".exr")));
    std::printf("%-10s sun share %.3f, source share %.3f\n", name, shares.sunShare, shares.sourceShare);
    EXPECT_EQ(mapKindName(classifyMap(shares)), mapKindName(kind))
        << name << ": sunShare " << shares.sunShare << ", sourceShare " << shares.sourceShare;
  }
}

}  // namespace
}  // namespace iblkit
