#pragma once
// Synthetic maps with a sun, for the tests of the dominant lights (core/environment_lights.h):
// a smooth sky with a small disk of uniform radiance, rendered with supersampled texels so the
// disk's edge texels hold their covered fraction.
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>
#include <initializer_list>
#include <vector>

#include "core/environment_lights.h"
#include "core/environment_map.h"
#include "core/latlong.h"

namespace iblkit::test {

// Sky radiance: brighter above, never zero, low frequency.
inline glm::vec3 softSkyRadiance(const glm::vec3& d) {
  return glm::vec3(0.25f, 0.3f, 0.4f) + glm::vec3(0.3f, 0.4f, 0.6f) * std::max(0.0f, d.y);
}

struct SunDisk {
  glm::vec3 direction{0.0f, 1.0f, 0.0f};  // unit, in the map's own frame
  float angularRadius = 0.03f;            // radians
  glm::vec3 radiance{2e4f, 1.8e4f, 1.5e4f};
};

// The disk as the engine draws a sun (core/environment_lights.h): its solid angle 2 pi (1 - cos r)
// and the irradiance radiance x solid angle; the SH9 and texel rectangle left empty.
inline EnvironmentLight diskLight(const SunDisk& disk) {
  EnvironmentLight light;
  light.direction = disk.direction;
  light.angularRadius = disk.angularRadius;
  light.solidAngle = 2.0f * glm::pi<float>() * (1.0f - std::cos(disk.angularRadius));
  light.radiance = disk.radiance;
  light.irradiance = light.radiance * light.solidAngle;
  return light;
}

// softSkyRadiance plus the disks, as a width x width/2 map (8 x 8 samples per texel).
inline EnvironmentMap sunnySky(int width, std::initializer_list<SunDisk> suns) {
  const std::vector<SunDisk> disks(suns);
  return EnvironmentMap::fromImage(
      latLongFromRadiance(width, width / 2, 8,
                          [&](const glm::vec3& d) {
                            glm::vec3 l = softSkyRadiance(d);
                            for (const SunDisk& sun : disks)
                              if (glm::dot(d, sun.direction) >= std::cos(sun.angularRadius))
                                l += sun.radiance;
                            return l;
                          }),
      "sunny sky");
}

}  // namespace iblkit::test
