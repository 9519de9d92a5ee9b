#pragma once
// Which of an environment's dominant lights the engine draws as lights, and what the residual is
// then (docs/dominant-lights.md, engine section). No GL: the renderer uploads the result, the
// viewer's panel lists it.
#include <vector>

#include "bakefile/environment_stages.h"
#include "core/environment_lights.h"
#include "core/spherical_harmonics.h"

namespace iblkit {

struct DrawnLights {
  // The first K suns of env.lights (brightest first), directions turned by the extra rotation.
  std::vector<EnvironmentLight> lights;
  // The residual's SH9 radiance as drawn, turned by the extra rotation: env.residualSh9 plus the
  // sh9 of every sun not drawn (SH is linear, so a sun left out of the lights keeps its diffuse
  // light; its specular is not in the residual's chain and is lost). Without a residual chain
  // (env.residualSpecular empty: a bake made before lights existed, or one without suns), the
  // map's sh9 minus the drawn suns' sh9; the specular then reads the map's chain.
  SphericalHarmonics9 residualSh9;
  bool residualChain = false;  // the specular residual is env.residualSpecular (else env.specular)
};

// The number of suns drawn for a requested count: `requested` < 0 means all; at most
// kMaxEngineLights and the number of suns.
int drawnLightCount(const EnvironmentStages& env, int requested);

// The lights and residual for `requested` lights (drawnLightCount) at the extra rotation
// `extraRotationDegrees` about +Y (FrameSettings::envRotationDegrees).
DrawnLights drawnLights(const EnvironmentStages& env, int requested, float extraRotationDegrees);

// Whether a bake's suns' bounced light (_SUNBOUNCE, sun i in component i; `bakedDirections` the
// directions of the suns it was baked for, empty when the meshes lack it) stands for the lights
// drawn: as many suns baked at least, light i in the direction of sun i (within 1e-5: the same
// environment, no extra rotation). Otherwise the engine estimates the bounce (dominant_lights.glsl).
bool bakedSunBounceFor(const std::vector<glm::vec3>& bakedDirections, const std::vector<EnvironmentLight>& drawn);

// The share of the map's energy (luminance of the integral of L over the sphere) a light carries:
// lum(light.irradiance) / lum(L_00 sqrt(4 pi)) with L_00 the map's SH9 DC coefficient.
float lightEnergyShare(const EnvironmentLight& light, const SphericalHarmonics9& mapSh9);

// A light's direction as azimuth (degrees from +Z towards +X, core/latlong.h's longitude) and
// elevation (degrees above the horizon).
glm::vec2 lightAzimuthElevation(const glm::vec3& direction);

}  // namespace iblkit
