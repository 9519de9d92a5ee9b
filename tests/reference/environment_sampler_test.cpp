#include "reference/environment_sampler.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <thread>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "core/environment_map_file.h"
#include "core/latlong.h"
#include "core/sampling.h"
#include "reference/environment_sampling_checks.h"
#include "support/chi2.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

constexpr int kChi2Tests = 5;  // Sidak correction over the suite

test::Chi2Result runChi2(const EnvironmentSampler& sampler, const std::string& name) {
  return test::latLongChi2(sampler, name, kChi2Tests);
}

using test::integrateOverSphere;
using test::spotMap;

TEST(EnvironmentSampler, OneHotPixelPassesChiSquare) {
  const EnvironmentMap map = EnvironmentMap::hotPixel(32, 9, 5, glm::vec3(100.0f));
  const EnvironmentSampler sampler(map);
  const test::Chi2Result r = runChi2(sampler, "env_one_hot");
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(EnvironmentSampler, ConstantMapPassesChiSquareAndIsUniformOverSolidAngle) {
  const EnvironmentMap map = EnvironmentMap::constant(glm::vec3(1.0f), 32);
  const EnvironmentSampler sampler(map);
  const test::Chi2Result r = runChi2(sampler, "env_constant");
  EXPECT_TRUE(r.passed) << r.message;
  // Each texel is sampled uniformly over its solid angle: exactly 1/(4 pi) everywhere, the rows
  // at the poles included (a uniform-in-theta row is off by 2x and more there), for samples too.
  const float uniform = 1.0f / (4.0f * glm::pi<float>());
  for (const glm::vec3 w :
       {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), glm::vec3(0.01f, 1, 0),
        glm::vec3(0.3f, -0.9f, 0.2f), glm::vec3(-0.5f, 0.5f, 0.7f)})
    EXPECT_NEAR(sampler.pdf(w), uniform, 1e-5f * uniform) << w.x << "," << w.y << "," << w.z;
  PCG32 rng(1, 2);
  for (int i = 0; i < 1000; ++i) ASSERT_NEAR(sampler.sample(rng.uniform2D()).pdf, uniform, 1e-5f * uniform);
}

TEST(EnvironmentSampler, RotatedScaledMapPassesChiSquareWithAndWithoutCompensation) {
  const EnvironmentMap map = spotMap();
  const EnvironmentSampler plain(map), compensated(map, true);
  EXPECT_FALSE(plain.misCompensated());
  EXPECT_TRUE(compensated.misCompensated());
  const test::Chi2Result a = runChi2(plain, "env_spot");
  EXPECT_TRUE(a.passed) << a.message;
  const test::Chi2Result b = runChi2(compensated, "env_spot_compensated");
  EXPECT_TRUE(b.passed) << b.message;
}

TEST(EnvironmentSampler, RealMapPassesChiSquare) {
  const std::optional<EnvironmentMap> map = test::downsampledSky();
  if (!map) GTEST_SKIP() << "assets not fetched";
  const EnvironmentSampler sampler(*map);
  const test::Chi2Result r = runChi2(sampler, "env_sky");
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(EnvironmentSampler, SampledPdfMatchesPdfAndEstimatorIsUnbiased) {
  const EnvironmentMap map = spotMap();
  const EnvironmentSampler sampler(map);
  PCG32 rng(3, 5);
  glm::dvec3 estimate(0.0);
  const int n = 200000;
  int mismatches = 0;  // a sample a rounding step from a texel edge may look up the next texel
  for (int i = 0; i < n; ++i) {
    const EnvironmentSampler::Sample s = sampler.sample(rng.uniform2D());
    ASSERT_GT(s.pdf, 0.0f);
    ASSERT_NEAR(glm::length(s.direction), 1.0f, 1e-5f);
    mismatches += std::abs(sampler.pdf(s.direction) - s.pdf) > 1e-3f * s.pdf ? 1 : 0;
    estimate += glm::dvec3(s.radiance / s.pdf);
  }
  EXPECT_LE(mismatches, n / 10000);
  estimate /= double(n);
  const glm::dvec3 truth =
      integrateOverSphere<glm::dvec3>([&](const glm::vec3& d) { return map.radiance(d); }, 512);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(estimate[c], truth[c], 0.005 * truth[c]) << "channel " << c;
}

// lookup(w) is map.radiance(w) and pdf(w) from one lat-long lookup; a sample's radiance, looked
// up at its own (u, v), is the map's radiance in its direction (to a float rounding of u, v).
TEST(EnvironmentSampler, LookupAndSampleRadianceAgreeWithTheMap) {
  const EnvironmentMap map = spotMap();  // rotated and scaled
  const EnvironmentSampler sampler(map);
  PCG32 rng(8, 1);
  for (int i = 0; i < 20000; ++i) {
    const glm::vec3 w = sampleUniformSphere(rng.uniform2D());
    const EnvironmentSampler::Lookup seen = sampler.lookup(w);
    ASSERT_EQ(seen.pdf, sampler.pdf(w));
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(seen.radiance[c], map.radiance(w)[c], 1e-4f * (1.0f + map.radiance(w)[c]));
    const EnvironmentSampler::Sample s = sampler.sample(rng.uniform2D());
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(s.radiance[c], map.radiance(s.direction)[c], 1e-3f * (1.0f + map.radiance(s.direction)[c]));
  }
}

TEST(EnvironmentSampler, PdfIntegratesToOne) {
  const EnvironmentMap map = spotMap();
  for (const bool compensated : {false, true}) {
    const EnvironmentSampler sampler(map, compensated);
    const double integral =
        integrateOverSphere<double>([&](const glm::vec3& d) { return sampler.pdf(d); }, 512);
    EXPECT_NEAR(integral, 1.0, 2e-3) << (compensated ? "compensated" : "plain");
  }
}

TEST(EnvironmentSampler, OneHotWeightIsBounded) {
  // With the whole pdf on the hot texel and its neighbours, L/pdf never exceeds the texel's
  // power by more than the bilinear spread allows: no fireflies from the sampler itself.
  const glm::vec3 radiance(100.0f);
  const EnvironmentMap map = EnvironmentMap::hotPixel(32, 9, 5, radiance);
  const EnvironmentSampler sampler(map);
  const float power = radiance.x * map.texelSolidAngle(5);
  PCG32 rng(11, 1);
  float maxWeight = 0.0f;
  for (int i = 0; i < 100000; ++i) {
    const EnvironmentSampler::Sample s = sampler.sample(rng.uniform2D());
    maxWeight = std::max(maxWeight, s.radiance.x / s.pdf);
  }
  EXPECT_GT(maxWeight, 0.0f);
  EXPECT_LT(maxWeight, 12.0f * power);
}

// sampleWithin is sample's draw, stopped early only where the oriented sampler's cell lies outside
// the cone: on a rotated map, for cones of 2 to 120 degrees about several axes and the buckets of
// an upward and a sideways normal, every draw it returns is sample's exactly, and every one it
// leaves empty is outside the cone. It does stop early (most draws, for the small cones), and a
// test of the cell against the cone without the cell's radius would cut draws inside it.
TEST(EnvironmentSampler, SampleWithinIsTheSameDrawStoppedOutsideTheCone) {
  EnvironmentMap map = spotMap(128);
  map.setRotationDegrees(31.0f);
  const EnvironmentSampler sampler(map, false, LightOrientation::ByNormal);
  int empty = 0, total = 0;
  for (const glm::vec3 normal : {glm::vec3(0.0f, 1.0f, 0.0f), glm::normalize(glm::vec3(1.0f, 0.2f, 0.3f))})
    for (const glm::vec3 axis : {glm::normalize(glm::vec3(0.2f, 0.3f, -0.9f)), glm::normalize(glm::vec3(-0.5f, 0.8f, 0.1f)),
                                 glm::vec3(0.0f, 1.0f, 0.0f)})
      for (const float degrees : {2.0f, 15.0f, 45.0f, 120.0f}) {
        const float cosRadius = std::cos(glm::radians(degrees));
        const int bucket = sampler.bucketOf(normal);
        for (int i = 0; i < 4000; ++i) {
          const glm::vec2 u((i + 0.5f) / 4000.0f, std::fmod(i * 0.6180339887f, 1.0f));
          const EnvironmentSampler::Sample whole = sampler.sample(bucket, u);
          const EnvironmentSampler::Sample cut = sampler.sampleWithin(bucket, u, axis, cosRadius);
          ++total;
          if (cut.pdf <= 0.0f && whole.pdf > 0.0f) {
            ++empty;
            ASSERT_LT(glm::dot(whole.direction, axis), cosRadius) << degrees << " degrees, draw " << i;
          } else {
            ASSERT_EQ(cut.direction, whole.direction);
            ASSERT_EQ(cut.radiance, whole.radiance);
            ASSERT_EQ(cut.pdf, whole.pdf);
          }
        }
      }
  std::printf("stopped early: %d of %d draws\n", empty, total);
  EXPECT_GT(empty, total / 4);
}

// An oriented sampler builds the plain distribution only when it is first used (its integrator
// never does): its plain samples and lookups are then those of a sampler built without
// orientation, bit for bit, also when several threads use it first at once.
TEST(EnvironmentSampler, AnOrientedSamplersPlainDistributionIsBuiltOnFirstUse) {
  EnvironmentMap map = spotMap(128);
  map.setRotationDegrees(31.0f);
  const EnvironmentSampler plain(map, false, LightOrientation::None);
  const EnvironmentSampler oriented(map, false, LightOrientation::ByNormal);
  ASSERT_FALSE(plain.oriented());
  ASSERT_TRUE(oriented.oriented());
  std::vector<std::thread> threads;
  std::atomic<int> mismatches{0};
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      PCG32 rng(9, static_cast<std::uint64_t>(t));
      for (int i = 0; i < 2000; ++i) {
        const glm::vec2 u = rng.uniform2D();
        const EnvironmentSampler::Sample a = plain.sample(u), b = oriented.sample(u);
        const EnvironmentSampler::Lookup la = plain.lookup(a.direction), lb = oriented.lookup(a.direction);
        if (a.direction != b.direction || a.radiance != b.radiance || a.pdf != b.pdf || la.pdf != lb.pdf ||
            la.radiance != lb.radiance)
          ++mismatches;
      }
    });
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(mismatches.load(), 0);
}

TEST(EnvironmentSampler, BlackMapSamplesUniformlyInUv) {
  const EnvironmentMap map = EnvironmentMap::constant(glm::vec3(0.0f), 16);
  const EnvironmentSampler sampler(map);
  EXPECT_TRUE(sampler.isBlack());
  const EnvironmentSampler::Sample s = sampler.sample(glm::vec2(0.3f, 0.5f));
  EXPECT_TRUE(std::isfinite(s.pdf));
  EXPECT_GT(s.pdf, 0.0f);
  EXPECT_EQ(s.radiance, glm::vec3(0.0f));
}

}  // namespace
}  // namespace iblkit
