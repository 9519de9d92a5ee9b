// The environment sampler's oriented distributions (reference/oriented_environment.h): for each
// bucket of normals a density proportional to the texel weights times a bound of the cosine.
#include "reference/oriented_environment.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include "core/environment_map_file.h"
#include "core/image.h"
#include "core/rng.h"
#include "core/sampling.h"
#include "reference/environment_sampler.h"
#include "reference/environment_sampling_checks.h"
#include "support/chi2.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

constexpr int kChi2Tests = 5;  // Sidak correction over the suite

using test::integrateOverSphere;
using test::spotMap;

// One bucket of an oriented sampler as a sampler of its own, for the shared chi-square harness.
struct BucketSampler {
  const EnvironmentSampler& sampler;
  int bucket;
  EnvironmentSampler::Sample sample(glm::vec2 u) const { return sampler.sample(bucket, u); }
  float pdf(const glm::vec3& w) const { return sampler.pdf(bucket, w); }
};

test::Chi2Result runChi2(const EnvironmentSampler& sampler, const glm::vec3& normal, const std::string& name) {
  return test::latLongChi2(BucketSampler{sampler, sampler.bucketOf(normal)}, name, kChi2Tests);
}

const glm::vec3 kSpot = glm::normalize(glm::vec3(0.3f, 0.6f, -0.7f));

TEST(OrientedEnvironment, BucketsPassChiSquareOnARotatedPeakedMap) {
  const EnvironmentMap map = spotMap();
  const EnvironmentSampler sampler(map);
  ASSERT_TRUE(sampler.oriented());
  // The ground's axis bucket, a cell bucket facing the spot (in map space it is turned by 35
  // degrees), and one facing away from it, which sees only the dim gradient.
  for (const auto& [normal, name] : {std::pair{glm::vec3(0, 1, 0), "oriented_up"},
                                     std::pair{glm::vec3(0.2f, 0.5f, -0.8f), "oriented_spot"},
                                     std::pair{glm::vec3(-0.4f, -0.3f, 0.85f), "oriented_away"}}) {
    const test::Chi2Result r = runChi2(sampler, normal, name);
    EXPECT_TRUE(r.passed) << r.message;
  }
}

TEST(OrientedEnvironment, RealMapBucketPassesChiSquare) {
  const std::optional<EnvironmentMap> map = test::downsampledSky();
  if (!map) GTEST_SKIP() << "assets not fetched";
  const EnvironmentSampler sampler(*map);
  const test::Chi2Result r = runChi2(sampler, glm::vec3(0.3f, 0.9f, 0.1f), "oriented_sky");
  EXPECT_TRUE(r.passed) << r.message;
}

// Each bucket's density is a density (it integrates to 1), and what a sample reports is what the
// lookup of its direction finds, which the MIS weight of an escaping ray uses.
TEST(OrientedEnvironment, PdfIntegratesToOneAndSamplesReportTheirLookup) {
  const EnvironmentMap map = spotMap();
  const EnvironmentSampler sampler(map);
  const OrientedEnvironment& tables = *sampler.orientedTables();
  const EnvironmentTexels texels(map);
  PCG32 rng(5, 9);
  for (int i = 0; i < 12; ++i) {
    const glm::vec3 normal = i < 6 ? glm::vec3(0.0f, i % 2 ? -1.0f : 1.0f, 0.0f) * 1.0f
                                   : sampleUniformSphere(rng.uniform2D());
    const int bucket = sampler.bucketOf(normal);
    // Exactly, texel by texel: each texel's probability times its density's mean inside it (a
    // bilinear function on each quarter, so a midpoint grid aligned with the quarters is exact).
    double total = 0.0;
    for (int y = 0; y < map.height(); ++y)
      for (int x = 0; x < map.width(); ++x) {
        double mean = 0.0;
        for (int j = 0; j < 8; ++j)
          for (int i = 0; i < 8; ++i) mean += texels.densityWithin({x, y}, {(i + 0.5f) / 8.0f, (j + 0.5f) / 8.0f});
        total += double(tables.pdfUv(bucket, {x, y})) / (map.width() * map.height()) * mean / 64.0;
      }
    EXPECT_NEAR(total, 1.0, 1e-5) << "bucket " << bucket;
    // And through the directions' lookups (the quadrature's error is the cells' steps in density).
    const double integral = integrateOverSphere<double>([&](const glm::vec3& d) { return sampler.pdf(bucket, d); }, 256);
    EXPECT_NEAR(integral, 1.0, 5e-3) << "bucket " << bucket;
    int mismatches = 0;
    const int n = 20000;
    for (int s = 0; s < n; ++s) {
      const EnvironmentSampler::Sample sample = sampler.sample(bucket, rng.uniform2D());
      ASSERT_GT(sample.pdf, 0.0f);
      ASSERT_NEAR(glm::length(sample.direction), 1.0f, 1e-5f);
      mismatches += std::abs(sampler.pdf(bucket, sample.direction) - sample.pdf) > 1e-3f * sample.pdf;
      const EnvironmentSampler::Lookup seen = sampler.lookupAt(bucket, sampler.mapUv(sample.direction));
      ASSERT_EQ(seen.pdf, sampler.pdf(bucket, sample.direction));
    }
    EXPECT_LE(mismatches, n / 1000) << "bucket " << bucket;  // a rounding step from a texel edge
  }
}

// Unbiasedness: wherever a normal of a bucket can receive light (n . w > 0 and the plain sampler
// has density, i.e. the lookups can return radiance), the bucket's density is positive, because
// the cell's cosine bound is at least n . w.
TEST(OrientedEnvironment, DensityIsPositiveWhereverTheNormalSeesLight) {
  EnvironmentMap map = spotMap(96);
  map.setRotationDegrees(-70.0f);
  const EnvironmentSampler sampler(map);
  const OrientedEnvironment& tables = *sampler.orientedTables();
  const EnvironmentTexels texels(map);
  PCG32 rng(21, 4);
  int checked = 0;
  for (int i = 0; i < 400000; ++i) {
    glm::vec3 n = sampleUniformSphere(rng.uniform2D());
    if (i % 4 == 0) n = glm::vec3(0.0f, 1.0f, 0.0f);  // the ground
    const glm::vec3 w = sampleUniformSphere(rng.uniform2D());
    const float cosine = glm::dot(n, w);
    if (cosine <= 0.0f || sampler.pdf(w) <= 0.0f) continue;
    const int bucket = sampler.bucketOf(n);
    const glm::ivec2 texel = texels.texelAt(sampler.mapUv(w));
    const int cell = tables.cellOf(texel);
    const glm::ivec2 grid = tables.cells();
    ASSERT_GE(tables.cosineBound(bucket, {cell % grid.x, cell / grid.x}), cosine)
        << "normal " << n.x << "," << n.y << "," << n.z << " direction " << w.x << "," << w.y << "," << w.z;
    ASSERT_GT(sampler.pdf(bucket, w), 0.0f);
    ++checked;
  }
  EXPECT_GT(checked, 100000);
}

// The ground's bucket spends nothing below its horizon, farther down than a cell's size, and
// estimates the ground's irradiance from the map without bias.
TEST(OrientedEnvironment, GroundBucketSkipsTheLowerHemisphereAndEstimatesItsIrradiance) {
  const EnvironmentMap map = spotMap(128);
  const EnvironmentSampler sampler(map);
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  const int bucket = sampler.bucketOf(up);
  PCG32 rng(2, 2);
  for (int i = 0; i < 20000; ++i) {
    const glm::vec3 w = sampleUniformSphere(rng.uniform2D());
    if (w.y < -0.1f) {
      ASSERT_EQ(sampler.pdf(bucket, w), 0.0f) << w.y;
    }
  }
  const int n = 200000;
  glm::dvec3 oriented(0.0), plain(0.0);
  for (int i = 0; i < n; ++i) {
    const glm::vec2 u = rng.uniform2D();
    const EnvironmentSampler::Sample a = sampler.sample(bucket, u), b = sampler.sample(u);
    ASSERT_GE(a.direction.y, -0.1f);
    oriented += glm::dvec3(a.radiance * std::max(0.0f, a.direction.y) / a.pdf);
    plain += glm::dvec3(b.radiance * std::max(0.0f, b.direction.y) / b.pdf);
  }
  const glm::dvec3 truth = integrateOverSphere<glm::dvec3>(
      [&](const glm::vec3& d) { return glm::dvec3(map.radiance(d)) * double(std::max(0.0f, d.y)); }, 512);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(oriented[c] / n, truth[c], 0.005 * truth[c]) << "channel " << c;
    EXPECT_NEAR(plain[c] / n, truth[c], 0.01 * truth[c]) << "channel " << c;
  }
}

TEST(OrientedEnvironment, BlackMapsAndUnorientedSamplersUseThePlainSampler) {
  const EnvironmentMap black = EnvironmentMap::constant(glm::vec3(0.0f), 16);
  const EnvironmentSampler blackSampler(black);
  EXPECT_FALSE(blackSampler.oriented());
  EXPECT_EQ(blackSampler.bucketOf(glm::vec3(0, 1, 0)), EnvironmentSampler::kNoBucket);
  const EnvironmentMap map = spotMap();
  const EnvironmentSampler plain(map, false, LightOrientation::None);
  EXPECT_FALSE(plain.oriented());
  const glm::vec3 w = glm::normalize(glm::vec3(0.2f, 0.4f, 0.5f));
  EXPECT_EQ(plain.pdf(EnvironmentSampler::kNoBucket, w), plain.pdf(w));
  EXPECT_EQ(plain.sample(EnvironmentSampler::kNoBucket, glm::vec2(0.3f, 0.6f)).direction,
            plain.sample(glm::vec2(0.3f, 0.6f)).direction);
}

// A bucket whose normals see no light (a map lit only from below, the ground's normal) has no
// density anywhere: its samples are refused, not drawn from black texels.
TEST(OrientedEnvironment, BucketThatSeesNoLightGivesNoSamples) {
  const EnvironmentMap map = EnvironmentMap::fromImage(
      latLongFromRadiance(64, 32, 2, [](const glm::vec3& d) { return glm::vec3(d.y < -0.5f ? 3.0f : 0.0f); }),
      "below");
  const EnvironmentSampler sampler(map);
  const int up = sampler.bucketOf(glm::vec3(0, 1, 0)), down = sampler.bucketOf(glm::vec3(0, -1, 0));
  EXPECT_EQ(sampler.sample(up, glm::vec2(0.4f, 0.7f)).pdf, 0.0f);
  EXPECT_EQ(sampler.pdf(up, glm::vec3(0, -1, 0)), 0.0f);
  EXPECT_GT(sampler.sample(down, glm::vec2(0.4f, 0.7f)).pdf, 0.0f);
}

}  // namespace
}  // namespace iblkit
