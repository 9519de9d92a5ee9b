#pragma once
// The viewer's camera: it orbits a target point about the world's +Y axis (yaw) and the camera's
// right axis (pitch), pans the target in the view plane and zooms along the view direction. It
// starts at the scene's camera (the core's sceneCamera) and converts back to a core Camera, so the
// window draws exactly what iblkit-view --headless and iblkit-trace see until the user moves.
// No OpenGL here: the maths is tested on its own (tests/view/orbit_camera_test.cpp).
#include <glm/glm.hpp>

#include "core/camera.h"
#include "core/mesh.h"

namespace iblkit {

class OrbitCamera {
 public:
  // Pitch stays within +-kMaxPitch (radians) of the horizon, so the view never flips over the pole.
  static constexpr float kMaxPitch = 89.0f * 3.14159265f / 180.0f;

  // Starts at `start` (its roll is dropped: the orbit keeps world +Y up). The target is the point
  // on the view ray closest to the centre of `bounds` (the objects), or, when the bounds lie
  // behind the camera, the point at the bounds' radius along the ray. Clip planes follow the
  // distance with clipPlanesFor(bounds).
  OrbitCamera(const Camera& start, const Bounds& bounds);

  // Turns the eye about the target: yaw about world +Y, pitch about the camera's right axis
  // (radians; positive pitch raises the eye). The distance to the target is kept.
  void orbit(float yawRadians, float pitchRadians);
  // Moves target and eye together in the view plane by (right, up) fractions of the view's height
  // at the target's distance (1 = the whole visible height), so a drag follows the cursor.
  void pan(float right, float up);
  // Multiplies the distance to the target by `factor` (> 0); the distance stays within
  // [1e-3, 1e3] x the bounds' radius.
  void zoom(float factor);
  // Back to the start camera.
  void reset();

  glm::vec3 target() const { return target_; }
  float distance() const { return distance_; }
  float yaw() const { return yaw_; }
  float pitch() const { return pitch_; }
  glm::vec3 eye() const;
  // The core camera for rendering: looking at the target with world +Y up, the start camera's
  // field of view, clip planes from clipPlanesFor(eye, bounds).
  Camera camera() const;

 private:
  Camera start_;
  Bounds bounds_;
  float boundsRadius_ = 1.0f;
  glm::vec3 target_{0.0f};
  float distance_ = 1.0f;
  float yaw_ = 0.0f, pitch_ = 0.0f;  // the eye's direction from the target (see eye())
};

}  // namespace iblkit
