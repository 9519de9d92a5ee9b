#include "core/disk_irradiance.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

#include "core/environment_lights.h"

namespace iblkit {

float uniformDiskIrradiance(float cosTheta, float angularRadius) {
  const float pi = glm::pi<float>();
  const float r = std::clamp(angularRadius, 0.0f, 0.5f * pi);
  const float c = std::clamp(cosTheta, -1.0f, 1.0f);
  const float sinRadius = std::sin(r);
  const float sinSquared = sinRadius * sinRadius;
  if (sinSquared <= 0.0f) return 0.0f;
  // Wholly above (c > sin r) or wholly below (c < -sin r) the horizon.
  if (c * c > sinSquared) return pi * sinSquared * std::max(c, 0.0f);
  // Across it. x = cot r stays > 0 (r < pi/2 by a hair at most); sin(theta) >= cos(r) here, so
  // |y| <= 1 up to rounding.
  const float x = std::max(std::cos(r) / sinRadius, 1e-7f);
  const float sinTheta = std::max(std::sqrt(std::max(0.0f, 1.0f - c * c)), 1e-7f);
  const float y = std::clamp(-x * c / sinTheta, -1.0f, 1.0f);
  const float sinThetaSqrtY = sinTheta * std::sqrt(std::max(0.0f, 1.0f - y * y));
  const float e = (c * std::acos(y) - x * sinThetaSqrtY) * sinSquared + std::atan(sinThetaSqrtY / x);
  return std::max(e, 0.0f);
}

glm::vec3 sunIrradiance(const EnvironmentLight& light, const glm::vec3& n) {
  return light.radiance * uniformDiskIrradiance(glm::dot(n, light.direction), light.angularRadius);
}

}  // namespace iblkit
