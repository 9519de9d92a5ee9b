#include "raytrace/ray_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <thread>

#include "core/error.h"
#include "core/procedural_mesh.h"

namespace iblkit {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// The unit square in the plane z = 0, counter-clockwise seen from +z, as two triangles:
// 0 = (v0, v1, v2) covers x > y, 1 = (v0, v2, v3) covers y > x.
const std::vector<glm::vec3> kQuadPositions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const std::vector<uint32_t> kQuadIndices = {0, 1, 2, 0, 2, 3};

RayScene quadScene() {
  RayScene scene;
  EXPECT_EQ(scene.addTriangleMesh(kQuadPositions, kQuadIndices), 0u);
  scene.commit();
  return scene;
}

RayScene unitCubeScene() {
  const ProceduralMesh cube = box(glm::vec3(0.5f), glm::vec3(1.0f));
  RayScene scene;
  scene.addTriangleMesh(cube.positions, cube.indices);
  scene.commit();
  return scene;
}

void expectErrorMessage(const std::function<void()>& action, const std::string& message) {
  try {
    action();
    ADD_FAILURE() << "no error, expected: " << message;
  } catch (const Error& e) {
    EXPECT_EQ(e.what(), message);
  }
}

TEST(RayScene, QuadHitDistancePrimitiveAndBarycentrics) {
  const RayScene scene = quadScene();
  // Direction of length 2: t counts direction lengths, so the plane 2 units away is at t = 1.
  const Hit first = scene.intersect({{0.75f, 0.25f, 2.0f}, {0.0f, 0.0f, -2.0f}}, 0.0f, kInfinity);
  ASSERT_TRUE(first.hit);
  EXPECT_FLOAT_EQ(first.t, 1.0f);
  EXPECT_EQ(first.geomId, 0u);
  EXPECT_EQ(first.primId, 0u);
  // (0.75, 0.25) = (1 - u - v) v0 + u v1 + v v2 = (u + v, v): u = 0.5, v = 0.25.
  EXPECT_NEAR(first.barycentrics.x, 0.5f, 1e-6f);
  EXPECT_NEAR(first.barycentrics.y, 0.25f, 1e-6f);
  EXPECT_NEAR(glm::distance(scene.surfacePoint(first), glm::vec3(0.75f, 0.25f, 0.0f)), 0.0f, 1e-6f);

  const Hit second = scene.intersect({{0.25f, 0.75f, -3.0f}, {0.0f, 0.0f, 1.0f}}, 0.0f, kInfinity);
  ASSERT_TRUE(second.hit);
  EXPECT_FLOAT_EQ(second.t, 3.0f);
  EXPECT_EQ(second.primId, 1u);
  // (0.25, 0.75) = u v2 + v v3 = (u, u + v): u = 0.25, v = 0.5.
  EXPECT_NEAR(second.barycentrics.x, 0.25f, 1e-6f);
  EXPECT_NEAR(second.barycentrics.y, 0.5f, 1e-6f);
}

TEST(RayScene, GeometricNormalIsRightHandedWhicheverSideIsHit) {
  const RayScene scene = quadScene();
  // Counter-clockwise seen from +z: the normal is +z from the front and from the back.
  for (float side : {1.0f, -1.0f}) {
    const Hit hit = scene.intersect({{0.3f, 0.6f, side}, {0.2f, 0.1f, -side}}, 0.0f, kInfinity);
    ASSERT_TRUE(hit.hit);
    EXPECT_EQ(hit.geometricNormal, glm::vec3(0.0f, 0.0f, 1.0f));
  }
  // A triangle wound the other way reports the opposite normal, unit length though it is large.
  RayScene flipped;
  const std::vector<glm::vec3> big = {{0, 0, 0}, {0, 1000, 0}, {1000, 0, 0}};
  flipped.addTriangleMesh(big, std::vector<uint32_t>{0, 1, 2});
  flipped.commit();
  const Hit hit = flipped.intersect({{1.0f, 1.0f, 5.0f}, {0.0f, 0.0f, -1.0f}}, 0.0f, kInfinity);
  ASSERT_TRUE(hit.hit);
  EXPECT_EQ(hit.geometricNormal, glm::vec3(0.0f, 0.0f, -1.0f));
}

TEST(RayScene, UnitCubeFacesFromOutsideAndInside) {
  const RayScene scene = unitCubeScene();
  // From outside along each axis: the near face, its outward normal, at the known distance.
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {1.0f, -1.0f}) {
      glm::vec3 origin(0.4f, 0.55f, 0.6f), direction(0.0f);
      origin[axis] = 0.5f + sign * 3.0f;
      direction[axis] = -sign;
      const Hit hit = scene.intersect({origin, direction}, 0.0f, kInfinity);
      ASSERT_TRUE(hit.hit);
      EXPECT_FLOAT_EQ(hit.t, 2.5f);
      glm::vec3 outward(0.0f);
      outward[axis] = sign;
      EXPECT_EQ(hit.geometricNormal, outward);
      EXPECT_LT(glm::dot(direction, hit.geometricNormal), 0.0f);  // front face
    }
  // From the centre: the far face's back, at half the diagonal for a ray to a corner.
  const glm::vec3 diagonal = glm::normalize(glm::vec3(1.0f, 1.0f, 1.0f) + glm::vec3(0.0f, 0.001f, 0.002f));
  const Hit inside = scene.intersect({glm::vec3(0.5f), diagonal}, 0.0f, kInfinity);
  ASSERT_TRUE(inside.hit);
  EXPECT_NEAR(inside.t, 0.5f / diagonal.z, 1e-5f);              // leaves through z = 1, the largest component
  EXPECT_GT(glm::dot(diagonal, inside.geometricNormal), 0.0f);  // back face
}

TEST(RayScene, RayIntervalSelectsHits) {
  const RayScene scene = unitCubeScene();
  const Ray ray{{0.5f, 0.5f, 3.0f}, {0.0f, 0.0f, -1.0f}};  // enters at t = 2, leaves at t = 3
  EXPECT_FLOAT_EQ(scene.intersect(ray, 0.0f, kInfinity).t, 2.0f);
  EXPECT_FLOAT_EQ(scene.intersect(ray, 2.5f, kInfinity).t, 3.0f);
  EXPECT_FALSE(scene.intersect(ray, 0.0f, 1.9f).hit);
  EXPECT_FALSE(scene.intersect(ray, 3.1f, kInfinity).hit);

  EXPECT_TRUE(scene.occluded(ray.origin, ray.direction, 0.0f, kInfinity));
  EXPECT_TRUE(scene.occluded(ray.origin, ray.direction, 2.5f, 3.1f));
  EXPECT_FALSE(scene.occluded(ray.origin, ray.direction, 0.0f, 1.9f));
  EXPECT_FALSE(scene.occluded(ray.origin, ray.direction, 2.1f, 2.9f));  // between the faces
}

TEST(RayScene, MissesReportNothing) {
  const RayScene scene = unitCubeScene();
  for (const Ray& ray :
       {Ray{{0.5f, 0.5f, 3.0f}, {0.0f, 0.0f, 1.0f}}, Ray{{2.0f, 0.5f, 3.0f}, {0.0f, 0.0f, -1.0f}},
        Ray{{0.5f, 1.5f, 3.0f}, {0.0f, 0.3f, -1.0f}}}) {
    const Hit hit = scene.intersect(ray, 0.0f, kInfinity);
    EXPECT_FALSE(hit.hit);
    EXPECT_EQ(hit.t, kInfinity);
    EXPECT_EQ(hit.geomId, RTC_INVALID_GEOMETRY_ID);
    EXPECT_EQ(hit.primId, RTC_INVALID_GEOMETRY_ID);
    EXPECT_FALSE(scene.occluded(ray.origin, ray.direction, 0.0f, kInfinity));
  }
}

TEST(RayScene, EmptySceneMissesAndHasNoSize) {
  RayScene scene;
  scene.commit();
  EXPECT_FALSE(scene.intersect({{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}}, 0.0f, kInfinity).hit);
  EXPECT_FALSE(scene.occluded(glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), 0.0f, kInfinity));
  EXPECT_EQ(scene.meshCount(), 0u);
  EXPECT_EQ(scene.bounds().lower, glm::vec3(0.0f));
  EXPECT_EQ(scene.bounds().upper, glm::vec3(0.0f));
  EXPECT_EQ(scene.scale(), 0.0f);
}

TEST(RayScene, MeshesGetSequentialIdsAndBoundsCoverThem) {
  RayScene scene;
  const ProceduralMesh ground = plane(glm::vec3(0.0f), 4.0f);
  const ProceduralMesh ball = uvSphere(glm::vec3(0.0f, 1.0f, 0.0f), 1.0f, 8, 16);
  const ProceduralMesh crate = box(glm::vec3(3.0f, 0.5f, 0.0f), glm::vec3(1.0f, 1.0f, 6.0f));
  EXPECT_EQ(scene.addTriangleMesh(ground.positions, ground.indices), 0u);
  EXPECT_EQ(scene.addTriangleMesh(ball.positions, ball.indices), 1u);
  EXPECT_EQ(scene.addTriangleMesh(crate.positions, crate.indices), 2u);
  scene.commit();
  EXPECT_EQ(scene.meshCount(), 3u);
  EXPECT_EQ(scene.intersect({{0.0f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}}, 0.0f, kInfinity).geomId, 1u);
  EXPECT_EQ(scene.intersect({{1.0f, 5.0f, 1.5f}, {0.0f, -1.0f, 0.0f}}, 0.0f, kInfinity).geomId, 0u);
  EXPECT_EQ(scene.intersect({{3.0f, 5.0f, 2.5f}, {0.0f, -1.0f, 0.0f}}, 0.0f, kInfinity).geomId, 2u);
  EXPECT_EQ(scene.bounds().lower, glm::vec3(-2.0f, 0.0f, -3.0f));
  EXPECT_EQ(scene.bounds().upper, glm::vec3(3.5f, 2.0f, 3.0f));
  EXPECT_FLOAT_EQ(scene.scale(), std::sqrt(5.5f * 5.5f + 2.0f * 2.0f + 6.0f * 6.0f));
  EXPECT_FLOAT_EQ(scene.rayEpsilon(), 3.5f * 0x1p-16f);  // the largest coordinate is x = 3.5
}

TEST(RayScene, DegenerateTrianglesAreNeverHit) {
  // Triangle 0 is fine; 1 has two equal corners, 2 three collinear corners, 3 all corners equal:
  // all of 1-3 lie across the ray paths below.
  const std::vector<glm::vec3> positions = {{0, 0, 0},     {1, 0, 0},    {0, 1, 0},      {0.5f, 0.5f, 1},
                                            {-1, 0.2f, 1}, {2, 0.2f, 1}, {0.5f, 0.2f, 1}};
  const std::vector<uint32_t> indices = {0, 1, 2, 4, 5, 5, 4, 6, 5, 3, 3, 3};
  RayScene scene;
  scene.addTriangleMesh(positions, indices);
  scene.commit();
  for (float x : {0.1f, 0.2f, 0.5f, 0.8f}) {
    const Hit hit = scene.intersect({{x, 0.2f, 2.0f}, {0.0f, 0.0f, -1.0f}}, 0.0f, kInfinity);
    ASSERT_TRUE(hit.hit) << x;
    EXPECT_EQ(hit.primId, 0u);
    EXPECT_FLOAT_EQ(hit.t, 2.0f);
  }
  const Hit through = scene.intersect({{0.5f, 0.5f, 2.0f}, {0.0f, 0.0f, -1.0f}}, 0.0f, kInfinity);
  ASSERT_TRUE(through.hit);  // the point (0.5, 0.5) is on triangle 0's hypotenuse
  EXPECT_EQ(through.primId, 0u);
  EXPECT_FALSE(scene.occluded({0.5f, 0.2f, 2.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 1.5f));
}

TEST(RayScene, BadMeshesThrowNamingTheMesh) {
  RayScene scene;
  scene.addTriangleMesh(kQuadPositions, kQuadIndices);
  const std::vector<uint32_t> outOfRange = {0, 1, 2, 2, 3, 4};
  expectErrorMessage([&] { scene.addTriangleMesh(kQuadPositions, outOfRange); },
                     "ray scene mesh 1: triangle 1 uses vertex 4 but the mesh has 4 vertices");
  expectErrorMessage(
      [&] {
        scene.addTriangleMesh(kQuadPositions, std::vector<uint32_t>{0, 1, 2, 3});
      },
      "ray scene mesh 1: 4 indices do not make whole triangles");
  expectErrorMessage([&] { scene.addTriangleMesh(kQuadPositions, {}); },
                     "ray scene mesh 1: has no triangles");
  std::vector<glm::vec3> nonFinite = kQuadPositions;
  nonFinite[2].y = std::numeric_limits<float>::quiet_NaN();
  expectErrorMessage([&] { scene.addTriangleMesh(nonFinite, kQuadIndices); },
                     "ray scene mesh 1: vertex 2 has a non-finite position");
  nonFinite[2].y = kInfinity;
  expectErrorMessage([&] { scene.addTriangleMesh(nonFinite, kQuadIndices); },
                     "ray scene mesh 1: vertex 2 has a non-finite position");
  // The rejected meshes left nothing behind: the next one still gets id 1.
  EXPECT_EQ(scene.meshCount(), 1u);
  EXPECT_EQ(scene.addTriangleMesh(kQuadPositions, kQuadIndices), 1u);
}

TEST(RayScene, QueriesNeedACommittedScene) {
  RayScene scene;
  scene.addTriangleMesh(kQuadPositions, kQuadIndices);
  expectErrorMessage(
      [&] {
        scene.intersect({{0.5f, 0.2f, 1.0f}, {0.0f, 0.0f, -1.0f}}, 0.0f, kInfinity);
      },
      "ray scene: intersect called before commit()");
  scene.commit();
  EXPECT_TRUE(scene.occluded({0.5f, 0.2f, 1.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, kInfinity));
  scene.addTriangleMesh(kQuadPositions, kQuadIndices);
  expectErrorMessage(
      [&] {
        scene.occluded({0.5f, 0.2f, 1.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, kInfinity);
      },
      "ray scene: occluded called before commit()");
}

TEST(RayScene, EmbreeDeviceErrorsBecomeErrors) {
  expectErrorMessage(
      [] { RayScene scene("tessellation_cache_size=abc"); },
      "Embree: RTC_ERROR_UNKNOWN: cannot create a device with config \"tessellation_cache_size=abc\"");
}

TEST(RayScene, MovedSceneKeepsWorking) {
  RayScene original = quadScene();
  RayScene moved(std::move(original));
  EXPECT_EQ(moved.intersect({{0.75f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}}, 0.0f, kInfinity).primId, 0u);
  RayScene assigned;
  assigned = std::move(moved);
  EXPECT_EQ(assigned.intersect({{0.25f, 0.75f, 1.0f}, {0.0f, 0.0f, -1.0f}}, 0.0f, kInfinity).primId, 1u);
  EXPECT_EQ(assigned.meshCount(), 1u);
}

// A unit ball on a 12 x 12 ground under it, committed: the scene of the concurrency and batch tests.
void addBallOnGround(RayScene& scene) {
  const ProceduralMesh ball = uvSphere(glm::vec3(0.0f), 1.0f, 24, 48);
  const ProceduralMesh ground = plane(glm::vec3(0.0f, -1.0f, 0.0f), 6.0f);
  scene.addTriangleMesh(ball.positions, ball.indices);
  scene.addTriangleMesh(ground.positions, ground.indices);
  scene.commit();
}

TEST(RayScene, ConcurrentQueriesMatchSerialOnes) {
  RayScene scene;
  addBallOnGround(scene);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  std::vector<Ray> rays(20000);
  for (Ray& ray : rays)
    ray = {{3.0f * uniform(rng), 3.0f * uniform(rng), 3.0f * uniform(rng)},
           {uniform(rng), uniform(rng), uniform(rng)}};

  struct Result {
    Hit hit;
    bool occluded;
  };
  const auto trace = [&](std::size_t begin, std::size_t step, std::vector<Result>& out) {
    for (std::size_t i = begin; i < rays.size(); i += step)
      out[i] = {scene.intersect(rays[i], 0.0f, kInfinity),
                scene.occluded(rays[i].origin, rays[i].direction, 0.0f, 2.0f)};
  };
  std::vector<Result> serial(rays.size()), parallel(rays.size());
  trace(0, 1, serial);
  constexpr std::size_t kThreads = 4;
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < kThreads; ++t) threads.emplace_back(trace, t, kThreads, std::ref(parallel));
  for (std::thread& thread : threads) thread.join();

  std::size_t hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const Hit &a = serial[i].hit, &b = parallel[i].hit;
    ASSERT_EQ(a.hit, b.hit) << i;
    hits += a.hit;
    EXPECT_EQ(a.t, b.t);
    EXPECT_EQ(a.geomId, b.geomId);
    EXPECT_EQ(a.primId, b.primId);
    EXPECT_EQ(a.barycentrics, b.barycentrics);
    EXPECT_EQ(a.geometricNormal, b.geometricNormal);
    EXPECT_EQ(serial[i].occluded, parallel[i].occluded);
  }
  // A real mix of hits and misses, so the comparison covers both.
  EXPECT_GT(hits, rays.size() / 5);
  EXPECT_LT(hits, rays.size() * 4 / 5);
}

// The packet forms answer what the single queries answer, for batches of any size (partial
// packets included): intersectCoherent's hits and the batch occluded's verdicts, ray by ray.
TEST(RayScene, BatchQueriesMatchSingleOnes) {
  RayScene scene;
  addBallOnGround(scene);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  for (const std::size_t size : {1u, 7u, 8u, 9u, 15u, 16u, 17u, 1001u}) {
    std::vector<Ray> rays(size);
    std::vector<OcclusionQuery> shadows(size);
    for (std::size_t i = 0; i < size; ++i) {
      // Camera-like rays from one point (coherent), and shadow rays of varied extent.
      rays[i] = {{0.0f, 0.5f, 4.0f}, glm::normalize(glm::vec3(0.3f * uniform(rng), 0.3f * uniform(rng), -1.0f))};
      shadows[i] = {{3.0f * uniform(rng), 3.0f * uniform(rng), 3.0f * uniform(rng)},
                    {uniform(rng), uniform(rng), uniform(rng)}, 0.0f, 1.0f + uniform(rng), {}};
    }
    std::vector<Hit> hits(size);
    scene.intersectCoherent(rays, 0.0f, kInfinity, {}, hits);
    std::vector<std::uint8_t> blocked(size, 2);
    scene.occluded(shadows, blocked);
    std::size_t hitCount = 0, blockedCount = 0;
    for (std::size_t i = 0; i < size; ++i) {
      const Hit one = scene.intersect(rays[i], 0.0f, kInfinity);
      ASSERT_EQ(hits[i].hit, one.hit) << size << " " << i;
      hitCount += one.hit;
      EXPECT_EQ(hits[i].geomId, one.geomId);
      EXPECT_EQ(hits[i].primId, one.primId);
      // Equal on this machine's kernels; Embree does not promise its packet and single-ray
      // kernels round alike, so the test allows their rounding.
      if (one.hit) {
        EXPECT_NEAR(hits[i].t, one.t, 1e-5f * one.t);
      }
      EXPECT_NEAR(glm::distance(hits[i].barycentrics, one.barycentrics), 0.0f, 1e-5f);
      EXPECT_NEAR(glm::distance(hits[i].geometricNormal, one.geometricNormal), 0.0f, 1e-5f);
      const OcclusionQuery& s = shadows[i];
      const bool single = scene.occluded(s.origin, s.direction, s.tmin, s.tmax);
      EXPECT_EQ(blocked[i], single ? 1 : 0) << size << " " << i;
      blockedCount += single;
    }
    if (size > 100) {
      // Both answers occur, so the comparison covers both.
      EXPECT_GT(hitCount, size / 5);
      EXPECT_LT(hitCount, size * 4 / 5);
      EXPECT_GT(blockedCount, size / 20);
      EXPECT_LT(blockedCount, size * 19 / 20);
    }
  }
  std::vector<Hit> wrong(2);
  EXPECT_THROW(scene.intersectCoherent(std::vector<Ray>(3), 0.0f, kInfinity, {}, wrong), std::invalid_argument);
}

}  // namespace
}  // namespace iblkit
