#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/environment_lights.h"
#include "core/environment_map_file.h"
#include "core/environment_sh.h"
#include "core/latlong.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

// Energy of the texels [x0, x1) x [y0, y1): luminance x solid angle, intensity applied.
double energyOf(const EnvironmentMap& map, int x0, int y0, int x1, int y1) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      sum += static_cast<double>(map.texelLuminance(x, y)) * map.texelSolidAngle(y);
  return sum;
}

double mapEnergy(const EnvironmentMap& map) { return energyOf(map, 0, 0, map.width(), map.height()); }

// Every texel in exactly one region, and the lights' irradiance, solid angle and energy add up to
// the map's.
void expectRegionsTileTheMap(const EnvironmentMap& map, const std::vector<EnvironmentLight>& lights) {
  std::vector<int> cover(static_cast<std::size_t>(map.width()) * map.height(), 0);
  glm::dvec3 irradiance(0.0), expectedIrradiance(0.0);
  double solidAngle = 0.0, energy = 0.0;
  for (const EnvironmentLight& light : lights) {
    EXPECT_EQ(light.kind, EnvironmentLightKind::MedianCut);
    ASSERT_TRUE(light.x0 >= 0 && light.x0 < light.x1 && light.x1 <= map.width());
    ASSERT_TRUE(light.y0 >= 0 && light.y0 < light.y1 && light.y1 <= map.height());
    for (int y = light.y0; y < light.y1; ++y)
      for (int x = light.x0; x < light.x1; ++x) ++cover[static_cast<std::size_t>(y) * map.width() + x];
    irradiance += glm::dvec3(light.irradiance);
    solidAngle += light.solidAngle;
    energy += luminance(light.irradiance);
    EXPECT_NEAR(glm::length(light.direction), 1.0f, 1e-5f);
    EXPECT_NEAR(2.0 * glm::pi<double>() * (1.0 - std::cos(light.angularRadius)), light.solidAngle, 1e-5);
    if (light.solidAngle > 0.0f) {
      const glm::vec3 r = light.radiance * light.solidAngle;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(r[c], light.irradiance[c], 1e-5f * std::abs(light.irradiance[c]) + 1e-30f);
    }
  }
  EXPECT_EQ(std::count(cover.begin(), cover.end(), 1), static_cast<std::ptrdiff_t>(cover.size()))
      << "texels outside every region or in two";
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x)
      expectedIrradiance += glm::dvec3(map.texelRadiance(x, y)) * static_cast<double>(map.texelSolidAngle(y));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(irradiance[c], expectedIrradiance[c], 1e-5 * expectedIrradiance[c]);
  EXPECT_NEAR(solidAngle, 4.0 * glm::pi<double>(), 1e-4);
  EXPECT_NEAR(energy, mapEnergy(map), 1e-5 * mapEnergy(map));
}

// A map with a small bright sun and a sky gradient, turned and scaled.
EnvironmentMap sunnyMap() {
  const glm::vec3 sun = glm::normalize(glm::vec3(0.4f, 0.6f, -0.7f));
  EnvironmentMap map = EnvironmentMap::fromImage(
      latLongFromRadiance(128, 64, 2,
                          [&](const glm::vec3& d) {
                            const float peak = 2000.0f * std::pow(std::max(0.0f, glm::dot(d, sun)), 400.0f);
                            return glm::vec3(0.5f + 0.4f * d.y + peak, 0.6f + 0.3f * d.y + peak,
                                             0.9f + 0.8f * peak);
                          }),
      "sunny");
  map.setRotationDegrees(35.0f);
  map.setIntensity(1.7f);
  return map;
}

TEST(MedianCut, ConstantMapGivesRegionsOfEqualPower) {
  const EnvironmentMap map = EnvironmentMap::constant(glm::vec3(1.0f, 2.0f, 3.0f), 128);
  for (const int levels : {1, 2, 4, 6}) {
    const std::vector<EnvironmentLight> lights = medianCutLights(map, levels);
    ASSERT_EQ(lights.size(), std::size_t{1} << levels);
    expectRegionsTileTheMap(map, lights);
    const double mean = mapEnergy(map) / static_cast<double>(lights.size());
    for (const EnvironmentLight& light : lights) {
      // Within one texel row's or column's worth of the region: the energy of its largest row or
      // of one of its columns, the granularity a cut can move by.
      double strip = energyOf(map, light.x0, light.y0, light.x0 + 1, light.y1);
      for (int y = light.y0; y < light.y1; ++y)
        strip = std::max(strip, energyOf(map, light.x0, y, light.x1, y + 1));
      EXPECT_NEAR(luminance(light.irradiance), mean, strip)
          << "levels " << levels << " region [" << light.x0 << "," << light.x1 << ")x[" << light.y0 << ","
          << light.y1 << ")";
    }
  }
}

TEST(MedianCut, FirstCutOfAConstantMapHalvesItsLongerSide) {
  // The whole map is 2 pi wide at the equator and pi high: the first cut is along the columns.
  // Each half is as wide (pi at its centre, the equator) as it is high, and is cut along the rows
  // (a tie is cut along the rows), at the equator; each quarter is then pi cos(45 degrees) wide at
  // its centre and pi / 2 high, so it is cut along the columns: no region crosses the equator.
  const EnvironmentMap map = EnvironmentMap::constant(glm::vec3(1.0f), 64);
  const std::vector<EnvironmentLight> halves = medianCutLights(map, 1);
  ASSERT_EQ(halves.size(), 2u);
  EXPECT_EQ(halves[0].x1, 32);
  EXPECT_EQ(halves[1].x0, 32);
  EXPECT_EQ(halves[0].y1 - halves[0].y0, 32);
  const std::vector<EnvironmentLight> quarters = medianCutLights(map, 3);
  ASSERT_EQ(quarters.size(), 8u);
  for (const EnvironmentLight& light : quarters) EXPECT_TRUE(light.y1 == 16 || light.y0 == 16);
}

TEST(MedianCut, OneHotPixelIsOneLightWithItsExactPowerAndDirection) {
  for (const float rotation : {0.0f, 70.0f}) {
    EnvironmentMap map = EnvironmentMap::hotPixel(64, 41, 9, glm::vec3(3.0f, 5.0f, 7.0f));
    map.setRotationDegrees(rotation);
    map.setIntensity(2.0f);
    // The cuts close in on the pixel, whose region stops being cut once it is that single texel.
    const std::vector<EnvironmentLight> lights = medianCutLights(map, 5);
    ASSERT_TRUE(lights.size() > 16u && lights.size() <= 32u) << lights.size();
    expectRegionsTileTheMap(map, lights);
    int lit = 0;
    for (const EnvironmentLight& light : lights) {
      const bool holdsPixel = light.x0 <= 41 && 41 < light.x1 && light.y0 <= 9 && 9 < light.y1;
      if (!holdsPixel) {
        EXPECT_EQ(light.irradiance, glm::vec3(0.0f));
        continue;
      }
      ++lit;
      const glm::vec3 power = map.texelRadiance(41, 9) * map.texelSolidAngle(9);
      EXPECT_EQ(light.irradiance, power);
      const glm::vec3 expected = map.texelDirection(41, 9);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(light.direction[c], expected[c], 1e-6f) << "rotation " << rotation;
      for (int k = 0; k < kShCoefficients; ++k) {
        const glm::vec3 expectedSh = power * shBasis9(expected)[static_cast<std::size_t>(k)];
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(light.sh9.coefficients[static_cast<std::size_t>(k)][c], expectedSh[c],
                      1e-5f * power[c]);
      }
    }
    EXPECT_EQ(lit, 1);
  }
}

TEST(MedianCut, RegionsTileAPeakedMapAndTheirShAddUpToTheMaps) {
  const EnvironmentMap map = sunnyMap();
  // The sun's texels stop being cut when they are single texels: fewer than 64 regions.
  const std::vector<EnvironmentLight> lights = medianCutLights(map, 6);
  ASSERT_TRUE(lights.size() > 32u && lights.size() <= 64u) << lights.size();
  expectRegionsTileTheMap(map, lights);
  SphericalHarmonics9 sum;
  for (const EnvironmentLight& light : lights) sum += light.sh9;
  const SphericalHarmonics9 whole = projectEnvironmentSh9(map);
  for (int k = 0; k < kShCoefficients; ++k)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(sum.coefficients[static_cast<std::size_t>(k)][c],
                  whole.coefficients[static_cast<std::size_t>(k)][c], 1e-4f * whole.coefficients[0][c])
          << "k=" << k;
  // Equal energy concentrates the regions on the sun: the region holding it is the smallest.
  const auto smallest = std::min_element(
      lights.begin(), lights.end(), [](const auto& a, const auto& b) { return a.solidAngle < b.solidAngle; });
  const glm::vec3 sun = map.toWorldDirection(glm::normalize(glm::vec3(0.4f, 0.6f, -0.7f)));
  EXPECT_GT(glm::dot(smallest->direction, sun), 0.99f);
}

TEST(MedianCut, RealSunnyMapRegionsTileItAndCloseInOnTheSun) {
  const EnvironmentMap map = loadEnvironmentMap(test::assetsDir() / "hdri" / "sky.exr");
  const std::vector<EnvironmentLight> lights = medianCutLights(map, 4);
  ASSERT_EQ(lights.size(), 16u);
  expectRegionsTileTheMap(map, lights);
  int sunX = 0, sunY = 0;
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x)
      if (map.texelLuminance(x, y) > map.texelLuminance(sunX, sunY)) {
        sunX = x;
        sunY = y;
      }
  // The sun's texel carries more than a sixteenth of the map's energy, so the cuts of every level
  // pass next to it: its region is a single column a few texels high.
  ASSERT_GT(energyOf(map, sunX, sunY, sunX + 1, sunY + 1), mapEnergy(map) / 16.0);
  int holding = 0;
  for (const EnvironmentLight& light : lights) {
    if (!(light.x0 <= sunX && sunX < light.x1 && light.y0 <= sunY && sunY < light.y1)) continue;
    ++holding;
    EXPECT_EQ(light.x1 - light.x0, 1);
    EXPECT_LE(light.y1 - light.y0, 4);
    EXPECT_GT(glm::dot(light.direction, map.texelDirection(sunX, sunY)), 0.9999f);
  }
  EXPECT_EQ(holding, 1);
}

TEST(MedianCut, SingleTexelRegionsAreNotCut) {
  const EnvironmentMap map = EnvironmentMap::constant(glm::vec3(1.0f), 8);  // 8 x 4: 32 texels
  const std::vector<EnvironmentLight> lights = medianCutLights(map, 12);
  ASSERT_EQ(lights.size(), 32u);
  expectRegionsTileTheMap(map, lights);
  EXPECT_EQ(medianCutLights(map, 0).size(), 1u);
}

TEST(MedianCut, LevelsOutsideZeroToTwelveThrow) {
  const EnvironmentMap map = EnvironmentMap::constant(glm::vec3(1.0f), 8);
  EXPECT_THROW(medianCutLights(map, -1), std::invalid_argument);
  EXPECT_THROW(medianCutLights(map, 13), std::invalid_argument);
}

}  // namespace
}  // namespace iblkit
