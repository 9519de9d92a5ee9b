#include "engine/view/orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

namespace iblkit {
namespace {

constexpr glm::vec3 kWorldUp{0.0f, 1.0f, 0.0f};

// The unit direction from the target to the eye.
glm::vec3 eyeDirection(float yaw, float pitch) {
  return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
}

Bounds nonEmpty(const Bounds& bounds) {
  if (!bounds.empty() && bounds.radius() > 0.0f) return bounds;
  Bounds unit;
  unit.extend(glm::vec3(-1.0f));
  unit.extend(glm::vec3(1.0f));
  return unit;
}

}  // namespace

OrbitCamera::OrbitCamera(const Camera& start, const Bounds& bounds)
    : start_(start), bounds_(nonEmpty(bounds)), boundsRadius_(bounds_.radius()) {
  reset();
}

void OrbitCamera::reset() {
  const glm::vec3 forward = glm::normalize(start_.forward);
  const float along = glm::dot(bounds_.center() - start_.position, forward);
  distance_ = along > 1e-3f * boundsRadius_ ? along : boundsRadius_;
  target_ = start_.position + forward * distance_;
  pitch_ = std::asin(std::clamp(-forward.y, -1.0f, 1.0f));
  pitch_ = std::clamp(pitch_, -kMaxPitch, kMaxPitch);
  yaw_ = std::atan2(-forward.x, -forward.z);
}

void OrbitCamera::orbit(float yawRadians, float pitchRadians) {
  yaw_ = std::remainder(yaw_ + yawRadians, glm::two_pi<float>());
  pitch_ = std::clamp(pitch_ + pitchRadians, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(float right, float up) {
  const glm::vec3 forward = -eyeDirection(yaw_, pitch_);
  const glm::vec3 rightAxis = glm::normalize(glm::cross(forward, kWorldUp));
  const glm::vec3 upAxis = glm::cross(rightAxis, forward);
  const float visibleHeight = 2.0f * distance_ * std::tan(0.5f * start_.yfovRadians);
  target_ += (rightAxis * right + upAxis * up) * visibleHeight;
}

void OrbitCamera::zoom(float factor) {
  if (!(factor > 0.0f) || !std::isfinite(factor)) return;
  distance_ = std::clamp(distance_ * factor, 1e-3f * boundsRadius_, 1e3f * boundsRadius_);
}

glm::vec3 OrbitCamera::eye() const { return target_ + distance_ * eyeDirection(yaw_, pitch_); }

Camera OrbitCamera::camera() const {
  const glm::vec3 position = eye();
  const ClipPlanes clip = clipPlanesFor(position, bounds_);
  return Camera::lookAt(position, target_, kWorldUp, start_.yfovRadians, clip.znear, clip.zfar);
}

}  // namespace iblkit
