// The orbit camera's maths, without a window: it starts at the scene's camera, orbits about its
// target at a fixed distance, pans in the view plane, zooms along the view and resets.
#include "engine/view/orbit_camera.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

namespace iblkit {
namespace {

constexpr float kTolerance = 1e-5f;

void expectVecNear(const glm::vec3& a, const glm::vec3& b, float tolerance, const char* what) {
  EXPECT_LT(glm::length(a - b), tolerance) << what << ": (" << a.x << ", " << a.y << ", " << a.z << ") vs ("
                                           << b.x << ", " << b.y << ", " << b.z << ")";
}

Bounds unitBounds(const glm::vec3& centre = glm::vec3(0.0f)) {
  Bounds bounds;
  bounds.extend(centre - glm::vec3(1.0f));
  bounds.extend(centre + glm::vec3(1.0f));
  return bounds;
}

// The bundled mirror sphere scene's camera.
Camera sceneLikeCamera() {
  return Camera::lookAt(glm::vec3(0.0f, 0.6f, 3.2f), glm::vec3(0.0f), glm::vec3(0, 1, 0), glm::radians(45.0f),
                        0.1f, 50.0f);
}

TEST(OrbitCamera, StartsAtTheSceneCamera) {
  const Camera start = sceneLikeCamera();
  const OrbitCamera orbit(start, unitBounds());
  const Camera camera = orbit.camera();
  expectVecNear(camera.position, start.position, kTolerance, "position");
  expectVecNear(camera.forward, start.forward, kTolerance, "forward");
  expectVecNear(camera.up, start.up, kTolerance, "up");
  EXPECT_EQ(camera.yfovRadians, start.yfovRadians);
  expectVecNear(orbit.target(), glm::vec3(0.0f), kTolerance, "target");
  EXPECT_NEAR(orbit.distance(), glm::length(start.position), kTolerance);
}

// The target is the point of the view ray closest to the objects' centre, also off-centre.
TEST(OrbitCamera, TargetIsOnTheViewRayNearestTheObjects) {
  const Camera start = Camera::lookAt(glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0.0f), glm::vec3(0, 1, 0),
                                      glm::radians(40.0f), 0.1f, 50.0f);
  const OrbitCamera orbit(start, unitBounds(glm::vec3(1.0f, 0.0f, 2.0f)));
  expectVecNear(orbit.target(), glm::vec3(0.0f, 0.0f, 2.0f), kTolerance, "target");
  // Objects behind the camera: the target is the bounds' radius ahead.
  const OrbitCamera behind(start, unitBounds(glm::vec3(0.0f, 0.0f, 9.0f)));
  EXPECT_NEAR(behind.distance(), std::sqrt(3.0f), kTolerance);
  expectVecNear(behind.eye(), start.position, kTolerance, "eye");
}

TEST(OrbitCamera, OrbitKeepsTheTargetCentredAtTheSameDistance) {
  OrbitCamera orbit(sceneLikeCamera(), unitBounds());
  const float distance = orbit.distance();
  orbit.orbit(0.7f, 0.3f);
  EXPECT_NEAR(glm::length(orbit.eye() - orbit.target()), distance, kTolerance);
  expectVecNear(orbit.target(), glm::vec3(0.0f), kTolerance, "target");
  const Camera camera = orbit.camera();
  // The target projects to the centre of the image.
  const glm::vec4 clip =
      camera.projectionMatrix(4.0f / 3.0f) * camera.viewMatrix() * glm::vec4(orbit.target(), 1.0f);
  EXPECT_NEAR(clip.x / clip.w, 0.0f, kTolerance);
  EXPECT_NEAR(clip.y / clip.w, 0.0f, kTolerance);
  // Positive pitch raises the eye; yaw turns it about +Y (the height stays).
  const float height = orbit.eye().y;
  orbit.orbit(0.0f, 0.2f);
  EXPECT_GT(orbit.eye().y, height + 0.1f);
  const glm::vec3 before = orbit.eye();
  orbit.orbit(1.0f, 0.0f);
  EXPECT_NEAR(orbit.eye().y, before.y, kTolerance);
  EXPECT_GT(glm::length(orbit.eye() - before), 0.5f);
  // A full turn comes back.
  orbit.orbit(glm::two_pi<float>(), 0.0f);
  orbit.orbit(-1.0f, 0.0f);
  expectVecNear(orbit.eye(), before, 1e-4f, "after a full turn");
}

TEST(OrbitCamera, PitchStopsShortOfThePoles) {
  OrbitCamera orbit(sceneLikeCamera(), unitBounds());
  orbit.orbit(0.0f, 10.0f);
  EXPECT_FLOAT_EQ(orbit.pitch(), OrbitCamera::kMaxPitch);
  Camera camera = orbit.camera();
  EXPECT_TRUE(std::isfinite(camera.up.x + camera.up.y + camera.up.z));
  EXPECT_NEAR(glm::dot(camera.up, camera.forward), 0.0f, kTolerance);
  EXPECT_LT(camera.forward.y, -0.99f);  // looking down
  orbit.orbit(0.0f, -20.0f);
  EXPECT_FLOAT_EQ(orbit.pitch(), -OrbitCamera::kMaxPitch);
  camera = orbit.camera();
  EXPECT_GT(camera.forward.y, 0.99f);
}

TEST(OrbitCamera, PanMovesEyeAndTargetTogetherInTheViewPlane) {
  OrbitCamera orbit(sceneLikeCamera(), unitBounds());
  const Camera before = orbit.camera();
  const glm::vec3 target = orbit.target();
  orbit.pan(0.25f, -0.1f);
  const Camera after = orbit.camera();
  expectVecNear(after.forward, before.forward, kTolerance, "forward");
  const glm::vec3 moved = orbit.target() - target;
  expectVecNear(after.position - before.position, moved, kTolerance, "eye moved with the target");
  EXPECT_NEAR(glm::dot(moved, before.forward), 0.0f, kTolerance);
  // Fractions of the visible height at the target's distance, along the camera's right and up.
  const float visibleHeight = 2.0f * orbit.distance() * std::tan(0.5f * before.yfovRadians);
  const glm::vec3 right = glm::normalize(glm::cross(before.forward, before.up));
  EXPECT_NEAR(glm::dot(moved, right), 0.25f * visibleHeight, kTolerance);
  EXPECT_NEAR(glm::dot(moved, before.up), -0.1f * visibleHeight, kTolerance);
}

TEST(OrbitCamera, ZoomScalesTheDistanceWithinLimits) {
  OrbitCamera orbit(sceneLikeCamera(), unitBounds());
  const float distance = orbit.distance();
  orbit.zoom(0.5f);
  EXPECT_NEAR(orbit.distance(), 0.5f * distance, kTolerance);
  expectVecNear(orbit.target(), glm::vec3(0.0f), kTolerance, "target");
  const float radius = unitBounds().radius();
  orbit.zoom(1e-9f);
  EXPECT_NEAR(orbit.distance(), 1e-3f * radius, 1e-7f);
  orbit.zoom(1e12f);
  EXPECT_NEAR(orbit.distance(), 1e3f * radius, 1e-2f);
  const float kept = orbit.distance();
  orbit.zoom(-1.0f);
  orbit.zoom(0.0f);
  orbit.zoom(std::numeric_limits<float>::quiet_NaN());
  EXPECT_EQ(orbit.distance(), kept);
  // The clip planes follow the eye, so the objects stay between them.
  const Camera far = orbit.camera();
  EXPECT_GT(far.zfar, orbit.distance() + radius);
}

TEST(OrbitCamera, ResetReturnsToTheStart) {
  const Camera start = sceneLikeCamera();
  OrbitCamera orbit(start, unitBounds());
  orbit.orbit(1.0f, -0.4f);
  orbit.pan(0.3f, 0.2f);
  orbit.zoom(3.0f);
  orbit.reset();
  const Camera camera = orbit.camera();
  expectVecNear(camera.position, start.position, kTolerance, "position");
  expectVecNear(camera.forward, start.forward, kTolerance, "forward");
}

}  // namespace
}  // namespace iblkit
