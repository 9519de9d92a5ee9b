#include "reference/environment_point_lights.h"

#include <algorithm>

#include "core/image.h"

namespace iblkit {

namespace {
std::vector<float> luminances(const std::vector<EnvironmentLight>& lights) {
  std::vector<float> out;
  out.reserve(lights.size());
  for (const EnvironmentLight& light : lights) out.push_back(luminance(light.irradiance));
  return out;
}
}  // namespace

EnvironmentPointLights::EnvironmentPointLights(const EnvironmentMap& map, int levels)
    : lights_(medianCutLights(map, levels)), distribution_(luminances(lights_)) {}

float EnvironmentPointLights::probability(int i) const {
  const std::span<const float> cdf = distribution_.cdf();
  return cdf[static_cast<std::size_t>(i) + 1] - cdf[static_cast<std::size_t>(i)];
}

EnvironmentPointLights::Sample EnvironmentPointLights::sample(float u) const {
  const int i = distribution_.sample(u).offset;
  const EnvironmentLight& light = lights_[static_cast<std::size_t>(i)];
  return {light.direction, light.irradiance / probability(i)};
}

glm::vec3 EnvironmentPointLights::irradiance(const glm::vec3& n) const {
  glm::vec3 sum(0.0f);
  for (const EnvironmentLight& light : lights_)
    sum += light.irradiance * std::max(0.0f, glm::dot(n, light.direction));
  return sum;
}

}  // namespace iblkit
