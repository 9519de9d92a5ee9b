#include "engine/gl/drawn_lights.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

#include "core/image.h"
#include "core/sh_rotation.h"
#include "engine/gl/light_constants.h"

namespace iblkit {
namespace {

// R_y(degrees) d (environment_map.h's sense: +90 degrees takes +Z to +X).
glm::vec3 rotateAboutY(const glm::vec3& d, float degrees) {
  const float c = std::cos(glm::radians(degrees)), s = std::sin(glm::radians(degrees));
  return {c * d.x + s * d.z, d.y, -s * d.x + c * d.z};
}

void accumulate(SphericalHarmonics9& sum, const SphericalHarmonics9& term, float sign) {
  for (int k = 0; k < kShCoefficients; ++k) sum.coefficients[std::size_t(k)] += sign * term.coefficients[std::size_t(k)];
}

}  // namespace

int drawnLightCount(const EnvironmentStages& env, int requested) {
  const int suns = std::min(int(env.lights.suns.size()), kMaxEngineLights);
  return requested < 0 ? suns : std::min(requested, suns);
}

DrawnLights drawnLights(const EnvironmentStages& env, int requested, float extraRotationDegrees) {
  DrawnLights drawn;
  const int count = drawnLightCount(env, requested);
  const std::vector<EnvironmentLight>& suns = env.lights.suns;
  drawn.residualChain = !env.residualSpecular.levels.empty();
  SphericalHarmonics9 residual = drawn.residualChain ? env.residualSh9 : env.sh9;
  for (std::size_t i = 0; i < suns.size(); ++i) {
    const bool isDrawn = int(i) < count;
    if (drawn.residualChain && !isDrawn) accumulate(residual, suns[i].sh9, 1.0f);
    if (!drawn.residualChain && isDrawn) accumulate(residual, suns[i].sh9, -1.0f);
    if (isDrawn) {
      EnvironmentLight light = suns[i];
      light.direction = rotateAboutY(light.direction, extraRotationDegrees);
      drawn.lights.push_back(light);
    }
  }
  drawn.residualSh9 = extraRotationDegrees == 0.0f ? residual : rotateShAboutY(residual, extraRotationDegrees);
  return drawn;
}

bool bakedSunBounceFor(const std::vector<glm::vec3>& bakedDirections, const std::vector<EnvironmentLight>& drawn) {
  if (bakedDirections.empty() || drawn.size() > bakedDirections.size()) return false;
  for (std::size_t i = 0; i < drawn.size(); ++i)
    if (glm::distance(drawn[i].direction, bakedDirections[i]) > 1e-5f) return false;
  return true;
}

float lightEnergyShare(const EnvironmentLight& light, const SphericalHarmonics9& mapSh9) {
  const float total = luminance(mapSh9.coefficients[0]) * std::sqrt(4.0f * glm::pi<float>());
  return total > 0.0f ? luminance(light.irradiance) / total : 0.0f;
}

glm::vec2 lightAzimuthElevation(const glm::vec3& d) {
  return glm::degrees(glm::vec2(std::atan2(d.x, d.z), std::atan2(d.y, std::hypot(d.x, d.z))));
}

}  // namespace iblkit
