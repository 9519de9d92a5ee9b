#include "core/camera.h"

#include <gtest/gtest.h>

#include <cmath>

namespace iblkit {
namespace {

// Raster position and NDC depth of a world point, through view and projection (camera.h's
// pixel convention).
glm::vec3 project(const Camera& camera, const glm::vec3& world, int width, int height) {
  const glm::vec4 clip =
      camera.projectionMatrix(float(width) / float(height)) * camera.viewMatrix() * glm::vec4(world, 1.0f);
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  return glm::vec3((ndc.x + 1.0f) * 0.5f * float(width), (1.0f - ndc.y) * 0.5f * float(height), ndc.z);
}

TEST(Camera, LookAtBuildsAnOrthonormalBasis) {
  const Camera camera = Camera::lookAt(glm::vec3(1, 2, 3), glm::vec3(1, 2, -7), glm::vec3(0.3f, 2.0f, 0.0f),
                                       glm::radians(60.0f), 0.5f, 50.0f);
  EXPECT_NEAR(glm::length(camera.forward), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::length(camera.up), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(camera.forward, camera.up), 0.0f, 1e-6f);
  EXPECT_NEAR(camera.forward.z, -1.0f, 1e-6f);
  EXPECT_GT(camera.up.y, 0.9f);
  // The view matrix puts the camera at the origin looking down -Z.
  const glm::mat4 view = camera.viewMatrix();
  const glm::vec3 origin(view * glm::vec4(camera.position, 1.0f));
  EXPECT_NEAR(glm::length(origin), 0.0f, 1e-5f);
  const glm::vec3 ahead(view * glm::vec4(camera.forward, 0.0f));
  EXPECT_NEAR(ahead.z, -1.0f, 1e-6f);
}

TEST(Camera, PrimaryRaysProjectBackToTheirRasterPosition) {
  const Camera camera = Camera::lookAt(glm::vec3(0.5f, 1.0f, 4.0f), glm::vec3(0.0f, 0.2f, 0.0f),
                                       glm::vec3(0, 1, 0), glm::radians(50.0f), 0.1f, 100.0f);
  for (const glm::ivec2 size : {glm::ivec2(640, 360), glm::ivec2(300, 500), glm::ivec2(7, 5)}) {
    for (const glm::vec2 fraction : {glm::vec2(0.5f, 0.5f), glm::vec2(0.0f, 0.0f), glm::vec2(1.0f, 1.0f),
                                     glm::vec2(0.1f, 0.8f), glm::vec2(0.93f, 0.27f)}) {
      const glm::vec2 raster = fraction * glm::vec2(size);
      const Ray ray = camera.primaryRay(raster, size.x, size.y);
      EXPECT_EQ(ray.origin, camera.position);
      EXPECT_NEAR(glm::length(ray.direction), 1.0f, 1e-6f);
      for (const float depth : {0.5f, 3.0f, 40.0f}) {
        const glm::vec3 projected = project(camera, ray.origin + depth * ray.direction, size.x, size.y);
        EXPECT_NEAR(projected.x, raster.x, 1e-4f * float(size.x));
        EXPECT_NEAR(projected.y, raster.y, 1e-4f * float(size.y));
      }
    }
  }
}

TEST(Camera, RasterOriginIsTheTopLeftCorner) {
  const Camera camera = Camera::lookAt(glm::vec3(0.0f), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0),
                                       glm::radians(90.0f), 0.1f, 10.0f);
  const Ray centre = camera.primaryRay(glm::vec2(100.0f, 50.0f), 200, 100);
  EXPECT_NEAR(centre.direction.z, -1.0f, 1e-6f);
  // 90 degree vertical field of view, aspect 2: the top-left corner is at (-2, 1, -1).
  const Ray corner = camera.primaryRay(glm::vec2(0.0f, 0.0f), 200, 100);
  const glm::vec3 expected = glm::normalize(glm::vec3(-2.0f, 1.0f, -1.0f));
  EXPECT_NEAR(corner.direction.x, expected.x, 1e-6f);
  EXPECT_NEAR(corner.direction.y, expected.y, 1e-6f);
  EXPECT_NEAR(corner.direction.z, expected.z, 1e-6f);
}

TEST(Camera, ViewMatrixFromAnOriginSeesTheWorldMovedByIt) {
  // viewMatrix(o) applied to p - o is viewMatrix() applied to p; far from the world's origin it
  // keeps the precision of the offsets (the engine's render space).
  const Camera camera = Camera::lookAt(glm::vec3(3.0f, 2.0f, 5.0f), glm::vec3(0.5f, 0.0f, -1.0f), glm::vec3(0, 1, 0),
                                       glm::radians(40.0f), 0.1f, 100.0f);
  const glm::dvec3 origin(1.25, -0.5, 2.0);
  for (const glm::vec3 p : {glm::vec3(0.0f), glm::vec3(1.0f, 2.0f, -3.0f), glm::vec3(-4.0f, 0.5f, 0.25f)}) {
    const glm::vec4 world = camera.viewMatrix() * glm::vec4(p, 1.0f);
    const glm::vec4 moved = camera.viewMatrix(origin) * glm::vec4(glm::vec3(glm::dvec3(p) - origin), 1.0f);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(moved[k], world[k], 1e-5f) << k;
  }
  // 36,000 units out (a float's step there is 1/256), a point a short exact offset from the camera:
  // in camera space the offset turned by the camera's basis. The world-space matrix loses it to
  // the rounding of its products with 36,000-unit coordinates.
  Camera far = camera;
  far.position += glm::vec3(30000.0f, 0.0f, -20000.0f);
  const glm::vec3 offset(0.25f, 0.125f, -0.5f);
  const glm::vec3 p = far.position + offset;  // exact
  const glm::vec3 right = glm::normalize(glm::cross(far.forward, far.up));
  const glm::vec3 expected(glm::dot(offset, right), glm::dot(offset, far.up), -glm::dot(offset, far.forward));
  const glm::dvec3 o(far.position);
  const glm::vec4 precise = far.viewMatrix(o) * glm::vec4(glm::vec3(glm::dvec3(p) - o), 1.0f);
  const glm::vec4 rounded = far.viewMatrix() * glm::vec4(p, 1.0f);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(precise[k], expected[k], 1e-6f) << k;
  EXPECT_GT(glm::length(glm::vec3(rounded) - expected), 1e-4f);
}

TEST(ClipPlanes, FollowDistanceAndRadius) {
  Bounds bounds;
  bounds.extend(glm::vec3(-1.0f, 0.0f, 0.0f));
  bounds.extend(glm::vec3(1.0f, 0.0f, 0.0f));  // radius 1 around the origin
  const ClipPlanes far = clipPlanesFor(glm::vec3(0.0f, 0.0f, 10.0f), bounds);
  EXPECT_FLOAT_EQ(far.znear, 0.1f);
  EXPECT_FLOAT_EQ(far.zfar, 30.0f);
  const ClipPlanes inside = clipPlanesFor(glm::vec3(0.0f, 0.0f, 0.5f), bounds);
  EXPECT_FLOAT_EQ(inside.znear, 0.01f);
  EXPECT_FLOAT_EQ(inside.zfar, 20.5f);
}

TEST(FrameBounds, EveryCornerProjectsInsideTheImage) {
  Bounds tall, wide, flat;
  tall.extend(glm::vec3(-0.2f, 0.0f, -0.2f));
  tall.extend(glm::vec3(0.2f, 3.0f, 0.2f));
  wide.extend(glm::vec3(-5.0f, 10.0f, -1.0f));
  wide.extend(glm::vec3(5.0f, 11.0f, 1.0f));
  flat.extend(glm::vec3(100.0f, 0.0f, 100.0f));
  flat.extend(glm::vec3(101.0f, 0.0f, 101.0f));
  for (const Bounds& bounds : {tall, wide, flat}) {
    for (const glm::ivec2 size : {glm::ivec2(960, 540), glm::ivec2(400, 800), glm::ivec2(512, 512)}) {
      const Camera camera = frameBounds(bounds, float(size.x) / float(size.y));
      for (const glm::vec3& corner : bounds.corners()) {
        const glm::vec3 p = project(camera, corner, size.x, size.y);
        EXPECT_GT(p.x, 0.0f);
        EXPECT_LT(p.x, float(size.x));
        EXPECT_GT(p.y, 0.0f);
        EXPECT_LT(p.y, float(size.y));
        EXPECT_GT(p.z, -1.0f);  // between the near and far planes
        EXPECT_LT(p.z, 1.0f);
      }
    }
  }
}

TEST(FrameBounds, LooksFromTwentyDegreesAboveOnThePlusZSide) {
  Bounds bounds;
  bounds.extend(glm::vec3(-1.0f, -1.0f, -1.0f));
  bounds.extend(glm::vec3(1.0f, 1.0f, 1.0f));
  const float aspect = 16.0f / 9.0f;
  const Camera camera = frameBounds(bounds, aspect);
  const glm::vec3 toCamera = camera.position - bounds.center();
  EXPECT_NEAR(std::asin(glm::normalize(toCamera).y), glm::radians(20.0f), 1e-5f);
  EXPECT_NEAR(toCamera.x, 0.0f, 1e-5f);
  EXPECT_GT(toCamera.z, 0.0f);
  EXPECT_NEAR(glm::dot(camera.forward, -glm::normalize(toCamera)), 1.0f, 1e-6f);
  EXPECT_NEAR(camera.yfovRadians, glm::radians(45.0f), 1e-7f);
  // Landscape: the vertical field of view is the smaller one; the sphere (radius sqrt 3) fills
  // it less a 10% margin.
  EXPECT_NEAR(glm::length(toCamera), 1.1f * std::sqrt(3.0f) / std::sin(glm::radians(22.5f)), 1e-4f);
}

TEST(FrameBounds, EmptyBoundsFrameAUnitSphere) {
  const Camera camera = frameBounds(Bounds(), 1.0f);
  EXPECT_NEAR(glm::length(camera.position), 1.1f / std::sin(glm::radians(22.5f)), 1e-4f);
  EXPECT_LT(camera.znear, camera.zfar);
}

}  // namespace
}  // namespace iblkit
