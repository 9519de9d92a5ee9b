#pragma once
// Scenes built in code for the reference tracer's tests: procedural meshes with known geometry
// under analytic environments, rendered small so each test program stays fast.

#include <cmath>
#include <glm/gtc/constants.hpp>
#include <optional>
#include <utility>

#include "core/environment_map.h"
#include "core/latlong.h"
#include "core/procedural_mesh.h"
#include "core/scene.h"
#include "reference/environment_sampler.h"
#include "reference/integrator.h"
#include "reference/render_scene.h"
#include "reference/renderer.h"

namespace iblkit::test {

// A Lambert material (specular 0, metallic 0) of the given grey albedo.
inline Material lambert(float albedo) {
  Material material;
  material.baseColor = glm::vec3(albedo);
  material.metallic = 0.0f;
  material.specular = 0.0f;
  material.roughness = 1.0f;
  return material;
}

inline Mesh meshFrom(const ProceduralMesh& procedural, int material, bool isGround = false) {
  Mesh mesh;
  mesh.name = isGround ? "ground" : "object";
  mesh.positions = procedural.positions;
  mesh.normals = procedural.normals;
  mesh.indices = procedural.indices;
  mesh.material = material;
  mesh.isGround = isGround;
  return mesh;
}

// The finely tessellated unit sphere at the origin, seen from +Z at distance 4 (40 degree field
// of view: the sphere fills about 70% of the image's height).
inline Scene sphereScene(const Material& material) {
  Scene scene;
  scene.materials = {material};
  scene.meshes = {meshFrom(uvSphere(glm::vec3(0.0f), 1.0f, 64, 128), 0)};
  scene.bounds = objectBounds(scene.meshes);
  scene.camera = Camera::lookAt(glm::vec3(0.0f, 0.0f, 4.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f),
                                glm::radians(40.0f), 0.1f, 100.0f);
  return scene;
}

// Renders `scene` under `environment` at width x height, spp samples per pixel; mediancut and
// lights use 2^medianCutLevels regions; the samples are those from index firstSample on.
inline RenderResult renderWith(Scene scene, const EnvironmentMap& environment,
                               const IntegratorSettings& integratorSettings, int size, int spp,
                               std::uint32_t seed = 1, int threads = 2, int medianCutLevels = 6,
                               int firstSample = 0,
                               LightOrientation orientation = LightOrientation::ByNormal) {
  const Camera camera = sceneCamera(scene, 1.0f);
  const RenderScene renderScene(std::move(scene));
  const EnvironmentSampler sampler(environment, false, orientation);
  std::optional<MedianCutSampler> medianCut;
  std::optional<EnvironmentPointLights> pointLights;
  if (integratorSettings.envSampling == EnvSampling::MedianCut)
    medianCut.emplace(environment, medianCutLevels);
  if (integratorSettings.envSampling == EnvSampling::Lights)
    pointLights.emplace(environment, medianCutLevels);
  const Integrator integrator(renderScene, environment, sampler, integratorSettings,
                              {medianCut ? &*medianCut : nullptr, pointLights ? &*pointLights : nullptr});
  RenderSettings settings;
  settings.width = settings.height = size;
  settings.samplesPerPixel = spp;
  settings.firstSample = firstSample;
  settings.seed = seed;
  settings.threads = threads;
  return render(integrator, camera, settings);
}

inline IntegratorSettings integratorOf(IntegratorKind kind, EnvSampling envSampling = EnvSampling::Mis) {
  IntegratorSettings settings;
  settings.kind = kind;
  settings.envSampling = envSampling;
  return settings;
}

// A grey sky brighter towards the zenith with a small bright spot (a sun) 45 degrees up: peaked
// enough that the light strategy and the BRDF strategy both matter.
inline EnvironmentMap spotEnvironment() {
  const glm::vec3 spot = glm::normalize(glm::vec3(0.5f, 0.7f, 0.6f));
  return EnvironmentMap::fromImage(
      latLongFromRadiance(128, 64, 2,
                          [&](const glm::vec3& d) {
                            return glm::vec3(0.3f + 0.2f * d.y) +
                                   glm::vec3(60.0f) * std::pow(std::max(0.0f, glm::dot(d, spot)), 200.0f);
                          }),
      "spot");
}

// Pixels (green channel) where two renders of one image differ by more than 4 sigma of their
// estimated variances: a handful at most for unbiased estimators of the same image.
inline int pixelsApartBeyond4Sigma(const RenderResult& first, const RenderResult& second) {
  int outliers = 0;
  for (int y = 0; y < first.beauty.height(); ++y)
    for (int x = 0; x < first.beauty.width(); ++x) {
      const float a = first.beauty.at(x, y).g, b = second.beauty.at(x, y).g;
      const float sigma = std::sqrt(first.variance.at(x, y).g + second.variance.at(x, y).g);
      outliers += std::abs(a - b) > 4.0f * sigma + 1e-4f;
    }
  return outliers;
}

}  // namespace iblkit::test
