#include "reference/normal_buckets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/rng.h"
#include "core/sampling.h"

namespace iblkit {
namespace {

float angleBetween(const glm::vec3& a, const glm::vec3& b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f));
}

// What the oriented sampler's unbiasedness rests on: every normal lies inside the cone of its bucket.
TEST(NormalBuckets, EveryNormalLiesInItsBucketsCone) {
  PCG32 rng(3, 7);
  std::set<int> seen;
  float worstFraction = 0.0f;
  for (int i = 0; i < 200000; ++i) {
    const glm::vec3 n = sampleUniformSphere(rng.uniform2D()) * (0.5f + rng.uniformFloat());
    const int b = NormalBuckets::of(n);
    ASSERT_GE(b, 0);
    ASSERT_LT(b, NormalBuckets::kCount);
    seen.insert(b);
    const float angle = angleBetween(n, NormalBuckets::center(b));
    ASSERT_LE(angle, NormalBuckets::coneRadius(b)) << n.x << "," << n.y << "," << n.z;
    worstFraction = std::max(worstFraction, angle / NormalBuckets::coneRadius(b));
  }
  EXPECT_EQ(seen.size(), std::size_t(NormalBuckets::kCellBuckets));  // the axis buckets need exact axes
  EXPECT_GT(worstFraction, 0.95f);  // the cones are tight, not merely large
}

TEST(NormalBuckets, NormalsOnAnAxisGetTheAxisBucketWithANarrowCone) {
  const glm::vec3 axes[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::set<int> buckets;
  for (const glm::vec3& axis : axes) {
    const int b = NormalBuckets::of(axis);
    EXPECT_GE(b, NormalBuckets::kCellBuckets);
    buckets.insert(b);
    EXPECT_LT(angleBetween(NormalBuckets::center(b), axis), 1e-6f);
    EXPECT_LT(NormalBuckets::coneRadius(b), 2e-3f);
    // A ground's normal after a little rounding is still on its axis.
    EXPECT_EQ(NormalBuckets::of(axis * 3.0f + glm::vec3(2e-5f)), b);
  }
  EXPECT_EQ(buckets.size(), 6u);
  // Off the axis by more than the tolerance: a cell bucket, whose cone holds it.
  const glm::vec3 tilted(0.01f, 1.0f, 0.0f);
  EXPECT_LT(NormalBuckets::of(tilted), NormalBuckets::kCellBuckets);
}

TEST(NormalBuckets, CellConesAreAtMostTwentyDegrees) {
  for (int b = 0; b < NormalBuckets::kCellBuckets; ++b) {
    EXPECT_GT(NormalBuckets::coneRadius(b), 0.05f) << b;
    EXPECT_LT(NormalBuckets::coneRadius(b), glm::radians(20.0f)) << b;
    EXPECT_NEAR(glm::length(NormalBuckets::center(b)), 1.0f, 1e-6f);
  }
}

TEST(NormalBuckets, DegenerateNormalsStillGetABucket) {
  for (const glm::vec3 n : {glm::vec3(0.0f), glm::vec3(NAN, 0.0f, 1.0f), glm::vec3(INFINITY, 1.0f, 0.0f)}) {
    const int b = NormalBuckets::of(n);
    EXPECT_GE(b, 0);
    EXPECT_LT(b, NormalBuckets::kCount);
  }
}

}  // namespace
}  // namespace iblkit
