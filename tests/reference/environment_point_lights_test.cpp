#include "reference/environment_point_lights.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <glm/gtc/constants.hpp>
#include <vector>

#include "core/environment_sh.h"
#include "core/latlong.h"
#include "reference/environment_sampling_checks.h"

namespace iblkit {
namespace {

EnvironmentMap spotMap() { return test::spotMap(128); }

TEST(EnvironmentPointLights, LightsArePickedByPowerAndTheWeightedSampleIsTheirSum) {
  const EnvironmentMap map = spotMap();
  const EnvironmentPointLights lights(map, 4);
  ASSERT_EQ(lights.lights().size(), 16u);
  double total = 0.0;
  glm::dvec3 sum(0.0);
  for (const EnvironmentLight& light : lights.lights()) {
    total += luminance(light.irradiance);
    sum += glm::dvec3(light.irradiance);
  }
  for (int i = 0; i < 16; ++i)
    EXPECT_NEAR(lights.probability(i),
                luminance(lights.lights()[static_cast<std::size_t>(i)].irradiance) / total, 1e-5);
  // E_i / p_i averaged over u is the sum of the E_i: a stratified u visits each light in proportion.
  const int n = 1 << 16;
  glm::dvec3 mean(0.0);
  for (int k = 0; k < n; ++k)
    mean += glm::dvec3(lights.sample((static_cast<float>(k) + 0.5f) / n).irradiance);
  mean /= double(n);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], sum[c], 1e-3 * sum[c]);
}

// The N-light irradiance approaches the map's as N grows (each light stands for a region that
// shrinks), but with few lights a normal whose horizon passes near a light gets all or none of
// that region's light (the aliasing the point lights trade for their speed).
TEST(EnvironmentPointLights, IrradianceApproachesTheMapsWithMoreLights) {
  const EnvironmentMap map = spotMap();
  const std::vector<glm::vec3> normals = fibonacciSphere(200);
  const std::vector<glm::vec3> exact = bruteForceIrradiance(map, normals);
  auto worstError = [&](int levels) {
    const EnvironmentPointLights lights(map, levels);
    double worst = 0.0;
    for (std::size_t i = 0; i < normals.size(); ++i)
      worst =
          std::max(worst, double(std::abs(luminance(lights.irradiance(normals[i])) - luminance(exact[i])) /
                                 luminance(exact[i])));
    return worst;
  };
  const double four = worstError(2), sixteen = worstError(4), many = worstError(8);
  // Worst relative error over 200 normals: 100% with 4 lights (a normal that none of them lights),
  // 19% with 16, 5.5% with 64, 0.9% with 256.
  EXPECT_GT(four, 0.5);
  EXPECT_LT(sixteen, 0.3);
  EXPECT_LT(many, 0.02);
}

TEST(EnvironmentPointLights, BlackMapPicksUniformly) {
  const EnvironmentPointLights lights(EnvironmentMap::constant(glm::vec3(0.0f), 16), 2);
  for (int i = 0; i < 4; ++i) EXPECT_FLOAT_EQ(lights.probability(i), 0.25f);
  EXPECT_EQ(lights.sample(0.6f).irradiance, glm::vec3(0.0f));
}

}  // namespace
}  // namespace iblkit
