#include "core/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace iblkit {

namespace {
// Zero-size bounds have no scale to frame; use a unit sphere around their centre.
float framingRadius(const Bounds& bounds) {
  const float r = bounds.radius();
  return r > 0.0f ? r : 1.0f;
}
}  // namespace

Camera Camera::lookAt(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up, float yfovRadians,
                      float znear, float zfar) {
  Camera camera;
  camera.position = eye;
  camera.forward = glm::normalize(target - eye);
  const glm::vec3 right = glm::normalize(glm::cross(camera.forward, up));
  camera.up = glm::cross(right, camera.forward);
  camera.yfovRadians = yfovRadians;
  camera.znear = znear;
  camera.zfar = zfar;
  return camera;
}

glm::mat4 Camera::viewMatrix() const { return glm::lookAt(position, position + forward, up); }

glm::mat4 Camera::viewMatrix(const glm::dvec3& origin) const {
  const glm::vec3 eye(glm::dvec3(position) - origin);
  return glm::lookAt(eye, eye + forward, up);
}

glm::mat4 Camera::projectionMatrix(float aspect) const {
  return glm::perspective(yfovRadians, aspect, znear, zfar);
}

Ray Camera::primaryRay(const glm::vec2& rasterPos, int width, int height) const {
  return PrimaryRays(*this, width, height)(rasterPos);
}

PrimaryRays::PrimaryRays(const Camera& camera, int width, int height)
    : position_(camera.position),
      forward_(camera.forward),
      toNdcX_(2.0f / float(width)),
      toNdcY_(2.0f / float(height)) {
  // glm::perspective maps camera-space (x, y, -1) to NDC (x / (aspect tan), y / tan).
  const float tanHalfFov = std::tan(0.5f * camera.yfovRadians);
  const float aspect = float(width) / float(height);
  // The same orthonormal basis glm::lookAt builds from (forward, up).
  const glm::vec3 right = glm::normalize(glm::cross(camera.forward, camera.up));
  const glm::vec3 trueUp = glm::cross(right, camera.forward);
  right_ = (aspect * tanHalfFov) * right;
  up_ = tanHalfFov * trueUp;
}

Ray PrimaryRays::operator()(const glm::vec2& rasterPos) const {
  const float ndcX = rasterPos.x * toNdcX_ - 1.0f;
  const float ndcY = 1.0f - rasterPos.y * toNdcY_;
  return Ray{position_, glm::normalize(ndcX * right_ + ndcY * up_ + forward_)};
}

ClipPlanes clipPlanesFor(const glm::vec3& position, const Bounds& bounds) {
  const float d = glm::length(position - bounds.center());
  const float r = framingRadius(bounds);
  return ClipPlanes{0.01f * std::max(d, r), d + 20.0f * r};
}

Camera frameBounds(const Bounds& bounds, float aspect) {
  const float yfov = glm::radians(45.0f);
  const float elevation = glm::radians(20.0f);
  // Half-angle of the horizontal field of view from the vertical one and the aspect ratio.
  const float halfX = std::atan(aspect * std::tan(0.5f * yfov));
  const float halfMin = std::min(0.5f * yfov, halfX);
  const float r = framingRadius(bounds);
  const float distance = 1.1f * r / std::sin(halfMin);

  const glm::vec3 target = bounds.center();
  const glm::vec3 towardCamera(0.0f, std::sin(elevation), std::cos(elevation));
  const glm::vec3 eye = target + distance * towardCamera;
  const ClipPlanes clip = clipPlanesFor(eye, bounds);
  return Camera::lookAt(eye, target, glm::vec3(0.0f, 1.0f, 0.0f), yfov, clip.znear, clip.zfar);
}

}  // namespace iblkit
