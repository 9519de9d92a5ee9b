#include "raytrace/ray_offset.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/procedural_mesh.h"
#include "raytrace/ray_scene.h"

namespace iblkit {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

TEST(RayOffset, MovesLargeCoordinatesByUlpsAndSmallOnesByAFixedAmount) {
  const glm::vec3 n(0.6f, 0.48f, 0.64f);  // unit length: 256 n = (153.6, 122.88, 163.84)
  const glm::vec3 moved = offsetRayOrigin(glm::vec3(1.0f, -2.0f, 0.01f), n);
  EXPECT_EQ(moved.x, 1.0f + 153.0f * 0x1p-23f);   // 153 ulps of [1, 2) up
  EXPECT_EQ(moved.y, -2.0f + 122.0f * 0x1p-23f);  // towards +n: magnitude down, ulps of [1, 2)
  EXPECT_EQ(moved.z, 0.01f + 0.64f / 65536.0f);   // |z| < 1/32: a float offset
  // At 1e4 an ulp is 2^-10, so a full 256-ulp step against x is a quarter unit.
  EXPECT_EQ(offsetRayOrigin(glm::vec3(1e4f, 0.0f, 0.0f), glm::vec3(-1.0f, 0.0f, 0.0f)),
            glm::vec3(1e4f - 0.25f, 0.0f, 0.0f));
  EXPECT_EQ(offsetRayOrigin(glm::vec3(-1e4f, 0.0f, 0.0f), glm::vec3(-1.0f, 0.0f, 0.0f)),
            glm::vec3(-1e4f - 0.25f, 0.0f, 0.0f));
}

TEST(RayOffset, RayEpsilonScalesWithTheLargestCoordinate) {
  EXPECT_EQ(rayEpsilon(1.0f), 0x1p-16f);
  EXPECT_EQ(rayEpsilon(1e4f), 1e4f * 0x1p-16f);
  EXPECT_EQ(rayEpsilon(0.0f), 0.0f);
}

// A uniformly distributed unit vector in the hemisphere about n (grazing directions included).
glm::vec3 hemisphereDirection(glm::vec3 n, std::mt19937& rng) {
  std::normal_distribution<float> gaussian;
  glm::vec3 d;
  do d = glm::vec3(gaussian(rng), gaussian(rng), gaussian(rng));
  while (glm::length(d) < 1e-3f);
  d = glm::normalize(d);
  return glm::dot(d, n) < 0.0f ? -d : d;
}

struct SelfHits {
  int offset = 0;    // rays from offsetRayOrigin(surfacePoint, n) that hit the triangle again
  int bounded = 0;   // rays from offsetRayOrigin(surfacePosition's point and error, n) that did
  int unoffset = 0;  // rays from the bare surfacePoint that did
  float largestStep = 0.0f;  // the largest distance the bounded offset moved a point
};

// Shoots rays from random points on both sides at one triangle (the only one in the scene), and
// from each hit a second ray into the hemisphere it came from; counts second rays that hit again.
SelfHits countSelfHits(const std::vector<glm::vec3>& triangle, int samples) {
  RayScene scene;
  scene.addTriangleMesh(triangle, std::vector<uint32_t>{0, 1, 2});
  scene.commit();
  const glm::vec3 centre = (triangle[0] + triangle[1] + triangle[2]) / 3.0f;
  const float size = glm::distance(triangle[0], triangle[1]);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  SelfHits count;
  for (int i = 0; i < samples; ++i) {
    // Aim at a random interior point from a random point within a few sizes of the triangle.
    float u = uniform(rng), v = uniform(rng);
    if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
    const glm::vec3 target = (1.0f - u - v) * triangle[0] + u * triangle[1] + v * triangle[2];
    const glm::vec3 origin =
        centre + 2.0f * size * glm::vec3(uniform(rng) - 0.5f, uniform(rng) - 0.5f, uniform(rng) - 0.5f);
    const Ray ray{origin, target - origin};
    const Hit hit = scene.intersect(ray, 0.0f, kInfinity);
    if (!hit.hit) continue;  // the rare origin in the triangle's plane
    // The side the ray came from: the new ray leaves into it.
    const glm::vec3 n =
        glm::dot(ray.direction, hit.geometricNormal) < 0.0f ? hit.geometricNormal : -hit.geometricNormal;
    const glm::vec3 direction = hemisphereDirection(n, rng);
    const glm::vec3 p = scene.surfacePoint(hit);
    count.offset += scene.occluded(offsetRayOrigin(p, n), direction, 0.0f, kInfinity);
    const glm::vec3 bounded = offsetRayOrigin(p, scene.surfacePosition(hit).error, n);
    count.bounded += scene.occluded(bounded, direction, 0.0f, kInfinity);
    count.largestStep = std::max(count.largestStep, glm::distance(bounded, p));
    count.unoffset += scene.occluded(p, direction, 0.0f, kInfinity);
  }
  return count;
}

// A tilted triangle of edge `size` whose corner sits at `corner`.
std::vector<glm::vec3> tiltedTriangle(glm::vec3 corner, float size) {
  return {corner, corner + size * glm::vec3(1.0f, 0.3f, -0.2f), corner + size * glm::vec3(0.1f, 0.7f, 0.9f)};
}

TEST(RayOffset, OffsetOriginsNeverReHitTheirTriangle) {
  for (const glm::vec3 corner : {glm::vec3(0.3f, -0.2f, 0.1f), glm::vec3(1e4f, -1.2e4f, 0.7e4f)})
    for (float size : {1e3f, 1.0f, 1e-2f}) {
      const SelfHits hits = countSelfHits(tiltedTriangle(corner, size), 4000);
      EXPECT_EQ(hits.offset, 0) << "triangle of size " << size << " at " << corner.x;
      // The test can fail: without the offset about half of the same rays re-hit the triangle.
      EXPECT_GT(hits.unoffset, 400) << "triangle of size " << size << " at " << corner.x;
    }
}

TEST(RayOffset, ErrorBoundedOriginsNeverReHitTheirTriangleAndMoveByTheirRounding) {
  // From 1e-6 to 1e3 units, at the origin and up to 1e5 from it, and a large triangle whose points
  // near 0 carry its corners' rounding.
  // (A triangle of 1e-4 at 1e4 is below the float grid there: it is tested near the origin only.)
  for (const glm::vec3 corner : {glm::vec3(0.3f, -0.2f, 0.1f), glm::vec3(1e4f, -1.2e4f, 0.7e4f),
                                 glm::vec3(-3e3f, 2e3f, 1e3f), glm::vec3(1e5f, 1e3f, -1e5f)})
    for (float size : {1e3f, 1.0f, 1e-2f, 1e-4f, 1e-6f}) {
      if (size < 1e-3f && std::abs(corner.x) > 1.0f) continue;
      const SelfHits hits = countSelfHits(tiltedTriangle(corner, size), 20000);
      EXPECT_EQ(hits.bounded, 0) << "triangle of size " << size << " at " << corner.x;
      EXPECT_GT(hits.unoffset, 2000) << "triangle of size " << size << " at " << corner.x;
      // The step is the rounding's extent: a few dozen ulps of the largest corner coordinate
      // (the 256-ulp offset above moves up to 256 of them).
      const float magnitude = std::max({std::abs(corner.x), std::abs(corner.y), std::abs(corner.z)}) + 2.0f * size;
      EXPECT_LT(hits.largestStep, 64.0f * magnitude * 0x1p-23f) << "triangle of size " << size << " at " << corner.x;
    }
  const SelfHits straddling = countSelfHits(tiltedTriangle(glm::vec3(-500.0f, -300.0f, -400.0f), 1e3f), 20000);
  EXPECT_EQ(straddling.bounded, 0);
}

TEST(RayOffset, RayEpsilonKeepsAShadowRayFromHittingItsTarget) {
  // Visibility rays from a floor to points on a tilted triangle above it, with nothing between.
  for (const glm::vec3 shift : {glm::vec3(0.0f), glm::vec3(1e4f, -1.2e4f, 0.7e4f)}) {
    const ProceduralMesh floor = plane(shift, 2.0f);
    const std::vector<glm::vec3> target = tiltedTriangle(shift + glm::vec3(-1.0f, 1.0f, -1.0f), 1.5f);
    RayScene scene;
    scene.addTriangleMesh(floor.positions, floor.indices);
    scene.addTriangleMesh(target, std::vector<uint32_t>{0, 1, 2});
    scene.commit();
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    int blockedAtFullLength = 0, blockedShortened = 0;
    for (int i = 0; i < 4000; ++i) {
      const glm::vec3 p =
          offsetRayOrigin(shift + glm::vec3(2.0f * uniform(rng) - 1.0f, 0.0f, 2.0f * uniform(rng) - 1.0f),
                          glm::vec3(0.0f, 1.0f, 0.0f));
      float u = uniform(rng), v = uniform(rng);
      if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
      const glm::vec3 q = (1.0f - u - v) * target[0] + u * target[1] + v * target[2];
      const glm::vec3 d = q - p;
      blockedAtFullLength += scene.occluded(p, d, 0.0f, 1.0f);
      blockedShortened += scene.occluded(p, d, 0.0f, 1.0f - scene.rayEpsilon() / glm::length(d));
    }
    EXPECT_EQ(blockedShortened, 0) << shift.x;
    // The test can fail: at full length the rounded target point lies on or behind its surface
    // for a good part of the rays.
    EXPECT_GT(blockedAtFullLength, 400) << shift.x;
  }
}

TEST(RayOffset, GroundUnderABoxIsOccludedTowardsItOnly) {
  // A unit box standing on a large ground plane: its bottom face lies in the ground's plane.
  const ProceduralMesh ground = plane(glm::vec3(0.0f), 100.0f);
  const ProceduralMesh crate = box(glm::vec3(0.0f, 0.5f, 0.0f), glm::vec3(1.0f));
  RayScene scene;
  scene.addTriangleMesh(ground.positions, ground.indices);
  scene.addTriangleMesh(crate.positions, crate.indices);
  scene.commit();
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  // Under the box, every upward ray is blocked (by the box's top from inside at the latest).
  for (const glm::vec3 p : {glm::vec3(0.0f), glm::vec3(0.49f, 0.0f, -0.3f), glm::vec3(-0.2f, 0.0f, 0.45f)})
    for (const glm::vec3 d : {up, glm::vec3(1.0f, 0.01f, 0.0f), glm::vec3(-0.3f, 0.2f, 0.9f)})
      EXPECT_TRUE(scene.occluded(offsetRayOrigin(p, up), d, 0.0f, kInfinity)) << p.x << " " << d.x;
  // Just outside the contact edge x = 0.5: grazing rays towards the box hit its side, rays
  // away from it and straight up see the sky, and no ray hits the ground it starts on.
  for (float gap : {1e-3f, 1e-2f, 0.3f}) {
    const glm::vec3 origin = offsetRayOrigin(glm::vec3(0.5f + gap, 0.0f, 0.1f), up);
    EXPECT_TRUE(scene.occluded(origin, glm::vec3(-1.0f, 0.01f, 0.0f), 0.0f, kInfinity)) << gap;
    EXPECT_TRUE(scene.occluded(origin, glm::vec3(-1.0f, 0.5f, 0.2f), 0.0f, kInfinity)) << gap;
    EXPECT_FALSE(scene.occluded(origin, glm::vec3(1.0f, 0.01f, 0.0f), 0.0f, kInfinity)) << gap;
    EXPECT_FALSE(scene.occluded(origin, up, 0.0f, kInfinity)) << gap;
    EXPECT_FALSE(scene.occluded(origin, glm::vec3(0.2f, 0.001f, -1.0f), 0.0f, kInfinity)) << gap;
  }
}

}  // namespace
}  // namespace iblkit
