#include "reference/median_cut_sampler.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include "core/environment_map_file.h"
#include "core/latlong.h"
#include "core/sampling.h"
#include "reference/environment_sampling_checks.h"
#include "support/chi2.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

constexpr int kChi2Tests = 4;  // Sidak correction over the suite

test::Chi2Result runChi2(const MedianCutSampler& sampler, const std::string& name) {
  return test::latLongChi2(sampler, name, kChi2Tests);
}

using test::spotMap;

TEST(MedianCutSampler, RotatedScaledMapPassesChiSquareWithAndWithoutCompensation) {
  const EnvironmentMap map = spotMap();
  const MedianCutSampler plain(map, 5), compensated(map, 5, true);
  EXPECT_FALSE(plain.misCompensated());
  EXPECT_TRUE(compensated.misCompensated());
  const test::Chi2Result a = runChi2(plain, "mediancut_spot");
  EXPECT_TRUE(a.passed) << a.message;
  const test::Chi2Result b = runChi2(compensated, "mediancut_spot_compensated");
  EXPECT_TRUE(b.passed) << b.message;
}

TEST(MedianCutSampler, RealMapPassesChiSquare) {
  // sky.exr box-downsampled to 128x64 (a sun and sky), 16 regions.
  const std::filesystem::path file = test::assetsDir() / "hdri" / "sky.exr";
  const EnvironmentMap full = loadEnvironmentMap(file);
  EnvironmentMap map = EnvironmentMap::fromImage(downsample2x(downsample2x(full.image())), file);
  map.setRotationDegrees(-60.0f);
  const MedianCutSampler sampler(map, 4);
  const test::Chi2Result r = runChi2(sampler, "mediancut_sky");
  EXPECT_TRUE(r.passed) << r.message;
}

// P(r) p(t | r) = w_t / W: the same density as the environment sampler's, through another warp,
// at every direction (up to float rounding of the two products), for every level count.
TEST(MedianCutSampler, DensityIsTheEnvironmentSamplersAndRegionsArePickedByPower) {
  const EnvironmentMap map = spotMap();
  const EnvironmentSampler env(map);
  PCG32 rng(4, 9);
  for (const int levels : {0, 3, 7}) {
    const MedianCutSampler sampler(map, levels);
    ASSERT_EQ(sampler.regions().size(), medianCutLights(map, levels).size());
    float total = 0.0f;
    for (int i = 0; i < static_cast<int>(sampler.regions().size()); ++i)
      total += sampler.regionProbability(i);
    EXPECT_NEAR(total, 1.0f, 1e-5f);
    for (int i = 0; i < 2000; ++i) {
      const glm::vec3 w = sampleUniformSphere(rng.uniform2D());
      ASSERT_NEAR(sampler.pdf(w), env.pdf(w), 1e-4f * env.pdf(w)) << "levels " << levels;
    }
  }
  // Equal-energy regions of a map with no texel brighter than its neighbourhood allows are picked
  // about equally often: each within a factor 2 of 1/8.
  const MedianCutSampler eight(map, 3);
  for (int i = 0; i < 8; ++i) {
    EXPECT_GT(eight.regionProbability(i), 0.0625f);
    EXPECT_LT(eight.regionProbability(i), 0.25f);
  }
}

TEST(MedianCutSampler, SampledPdfMatchesPdfAndEstimatorIsUnbiased) {
  const EnvironmentMap map = spotMap();
  const MedianCutSampler sampler(map, 6);
  PCG32 rng(3, 5);
  glm::dvec3 estimate(0.0);
  const int n = 200000;
  int mismatches = 0;  // a sample a rounding step from a texel edge may look up the next texel
  for (int i = 0; i < n; ++i) {
    const MedianCutSampler::Sample s = sampler.sample(rng.uniform2D());
    ASSERT_GT(s.pdf, 0.0f);
    ASSERT_NEAR(glm::length(s.direction), 1.0f, 1e-5f);
    mismatches += std::abs(sampler.pdf(s.direction) - s.pdf) > 1e-3f * s.pdf ? 1 : 0;
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(s.radiance[c], map.radiance(s.direction)[c], 1e-3f * (1.0f + map.radiance(s.direction)[c]));
    estimate += glm::dvec3(s.radiance / s.pdf);
  }
  EXPECT_LE(mismatches, n / 10000);
  estimate /= double(n);
  const glm::dvec3 truth =
      test::integrateOverSphere<glm::dvec3>([&](const glm::vec3& d) { return map.radiance(d); }, 512);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(estimate[c], truth[c], 0.005 * truth[c]) << "channel " << c;
}

TEST(MedianCutSampler, OneHotPixelPassesChiSquareAndSamplesOnlyAroundIt) {
  const EnvironmentMap map = EnvironmentMap::hotPixel(32, 9, 5, glm::vec3(100.0f));
  const MedianCutSampler sampler(map, 4);
  const test::Chi2Result r = runChi2(sampler, "mediancut_one_hot");
  EXPECT_TRUE(r.passed) << r.message;
  PCG32 rng(2, 2);
  for (int i = 0; i < 10000; ++i) {
    const glm::vec2 uv = latLongUv(sampler.sample(rng.uniform2D()).direction);
    // The 3x3 texels around (9, 5), where the bilinear lookup spreads its radiance.
    ASSERT_GE(uv.x * 32.0f, 8.0f - 1e-3f);
    ASSERT_LE(uv.x * 32.0f, 11.0f + 1e-3f);
    ASSERT_GE(uv.y * 16.0f, 4.0f - 1e-3f);
    ASSERT_LE(uv.y * 16.0f, 7.0f + 1e-3f);
  }
}

TEST(MedianCutSampler, BlackMapGivesFinitePositiveDensity) {
  const EnvironmentMap map = EnvironmentMap::constant(glm::vec3(0.0f), 16);
  const MedianCutSampler sampler(map, 3);
  const MedianCutSampler::Sample s = sampler.sample(glm::vec2(0.3f, 0.5f));
  EXPECT_TRUE(std::isfinite(s.pdf));
  EXPECT_GT(s.pdf, 0.0f);
  EXPECT_EQ(s.radiance, glm::vec3(0.0f));
}

TEST(MedianCutSampler, LevelsOfPowersOfTwo) {
  EXPECT_EQ(medianCutLevelsOf(1), 0);
  EXPECT_EQ(medianCutLevelsOf(64), 6);
  EXPECT_EQ(medianCutLevelsOf(4096), 12);
  EXPECT_FALSE(medianCutLevelsOf(0));
  EXPECT_FALSE(medianCutLevelsOf(48));
  EXPECT_FALSE(medianCutLevelsOf(8192));
  EXPECT_FALSE(medianCutLevelsOf(-4));
}

}  // namespace
}  // namespace iblkit
