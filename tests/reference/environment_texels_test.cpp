// The texels as the light samplers draw them (reference/environment_texels.h): the mean bilinear
// weights and the point inside a texel drawn by the bilinear luminance.
#include "reference/environment_texels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/constants.hpp>

#include "core/latlong.h"
#include "core/rng.h"
#include "reference/environment_sampling_checks.h"

namespace iblkit {
namespace {

float luminanceOf(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// The (u, v) of point p inside texel (x, y): across its columns, down its solid angle (linear in
// cos(theta), as pointInRow has it).
glm::vec2 uvOf(const EnvironmentMap& map, int x, int y, glm::vec2 p) {
  const float top = std::cos(glm::pi<float>() * y / map.height()), bottom = std::cos(glm::pi<float>() * (y + 1) / map.height());
  const float cosTheta = glm::mix(top, bottom, p.y);
  return {(x + p.x) / map.width(), std::acos(cosTheta) / glm::pi<float>()};
}

TEST(EnvironmentTexels, DensityInsideATexelFollowsTheBilinearLookup) {
  const EnvironmentMap map = test::spotMap(64);
  const EnvironmentTexels texels(map);
  // Rows away from the poles, where the row's cos(theta) is nearly linear in v: where the lookups
  // over a texel vary by more than kFlatRatio the density, a bilinear function of the point
  // through the lookup's values at the texel's centre, edges and corners, is the lookup's luminance
  // over its mean to within 1%; where they vary less it is 1, the uniform point.
  int shaped = 0, flat = 0;
  for (int y = 8; y < 24; y += 2)
    for (int x = 0; x < 64; x += 2) {
      float lo = INFINITY, hi = 0.0f;
      for (const float py : {0.0f, 0.5f, 1.0f})
        for (const float px : {0.0f, 0.5f, 1.0f}) {
          const float lookup = luminanceOf(sampleLatLongBilinear(map.image(), uvOf(map, x, y, {px, py})));
          lo = std::min(lo, lookup);
          hi = std::max(hi, lookup);
        }
      const glm::vec2 points[] = {{0.1f, 0.2f}, {0.9f, 0.5f}, {0.3f, 0.95f}, {0.0f, 0.0f}, {0.5f, 0.5f}};
      if (hi > 1.01f * EnvironmentTexels::kFlatRatio * lo) {
        ++shaped;
        const float mean = luminanceOf(sampleLatLongBilinear(map.image(), uvOf(map, x, y, {0.5f, 0.5f}))) /
                           texels.densityWithin({x, y}, {0.5f, 0.5f});
        for (const glm::vec2 p : points) {
          const float lookup = luminanceOf(sampleLatLongBilinear(map.image(), uvOf(map, x, y, p)));
          EXPECT_NEAR(texels.densityWithin({x, y}, p) * mean, lookup, 0.01f * lookup) << x << "," << y;
        }
      } else if (hi < 0.99f * EnvironmentTexels::kFlatRatio * lo) {
        ++flat;
        for (const glm::vec2 p : points) EXPECT_EQ(texels.densityWithin({x, y}, p), 1.0f) << x << "," << y;
      }
    }
  EXPECT_GT(shaped, 10);
  EXPECT_GT(flat, 10);
}

TEST(EnvironmentTexels, MeanWeightsAreTheMeanBilinearLuminanceTimesSolidAngle) {
  const EnvironmentMap map = test::spotMap(32);
  const EnvironmentTexels texels(map);
  const std::vector<float> weights = texels.meanWeights();
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x) {
      // The midpoint rule on a 16 x 16 grid in (u, v), exact for the bilinear quarters.
      double mean = 0.0;
      for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i)
          mean += map.intensity() * luminanceOf(sampleLatLongBilinear(
              map.image(), {(x + (i + 0.5f) / 16.0f) / map.width(), (y + (j + 0.5f) / 16.0f) / map.height()}));
      mean /= 256.0;
      const double solidAngle = (std::cos(glm::pi<double>() * y / map.height()) -
                                 std::cos(glm::pi<double>() * (y + 1) / map.height())) * 0.5 * map.height();
      EXPECT_NEAR(weights[std::size_t(y) * map.width() + x], mean * solidAngle, 1e-4 * mean * solidAngle + 1e-7)
          << x << "," << y;
    }
}

// Points drawn inside a texel next to a bright one fall into the cells of a 4 x 4 grid as often as
// the density's integral over each cell says (a 5-sigma bound on each count), and each point
// reports its density.
TEST(EnvironmentTexels, SampledPointsFollowTheirDensity) {
  const EnvironmentMap map = EnvironmentMap::hotPixel(16, 5, 4, glm::vec3(50.0f));
  const EnvironmentTexels texels(map);
  PCG32 rng(7, 3);
  for (const glm::ivec2 texel : {glm::ivec2(6, 4), glm::ivec2(6, 5), glm::ivec2(5, 4), glm::ivec2(9, 2)}) {
    int counts[4][4] = {};
    const int n = 64000;
    for (int s = 0; s < n; ++s) {
      const EnvironmentTexels::WithinTexel w = texels.sampleWithin(texel, rng.uniform2D());
      ASSERT_NEAR(w.density, texels.densityWithin(texel, w.point), 1e-4f * w.density);
      ++counts[std::min(int(w.point.y * 4), 3)][std::min(int(w.point.x * 4), 3)];
    }
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        double expected = 0.0;
        for (int b = 0; b < 8; ++b)
          for (int a = 0; a < 8; ++a)
            expected += texels.densityWithin(texel, {(i + (a + 0.5f) / 8.0f) / 4.0f, (j + (b + 0.5f) / 8.0f) / 4.0f});
        expected *= n / (16.0 * 64.0);
        EXPECT_NEAR(counts[j][i], expected, 5.0 * std::sqrt(expected) + 1.0) << texel.x << "," << texel.y << " cell " << i << "," << j;
      }
  }
}

}  // namespace
}  // namespace iblkit
