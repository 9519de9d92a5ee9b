#pragma once
// Small baked scenes for the engine's tests, made in memory with the baker library (header-only:
// only test programs that link iblkit_baker include it): a sphere, optionally on a ground plane,
// under a smooth analytic environment, with few visibility rays and a small environment chain.
#include <glm/gtc/constants.hpp>
#include <string>

#include "baker/environment_stages.h"
#include "baker/vertex_visibility.h"
#include "baker/visibility_attributes.h"
#include "bakefile/bake_folder.h"
#include "core/latlong.h"
#include "core/procedural_mesh.h"

namespace iblkit::test {

// A smooth, coloured, everywhere-positive sky: brighter above, a warm lobe towards +X and a blue
// one towards -Z, so that directions are told apart by colour. Low frequency, so bilinear lookups
// and SH9 are both accurate.
inline glm::vec3 testSkyRadiance(const glm::vec3& d) {
  return glm::vec3(0.3f) + glm::vec3(0.6f, 0.5f, 0.4f) * (0.5f + 0.5f * d.y) +
         glm::vec3(1.2f, 0.6f, 0.1f) * std::max(0.0f, d.x) * std::max(0.0f, d.x) +
         glm::vec3(0.1f, 0.3f, 1.0f) * std::max(0.0f, -d.z);
}

inline EnvironmentMap testSky(int width = 64) {
  return EnvironmentMap::fromImage(latLongFromRadiance(width, width / 2, 2, testSkyRadiance), "test sky");
}

struct TestBakeOptions {
  Material sphereMaterial{};
  bool ground = false;
  int aoRays = 16;
  int rings = 48, segments = 96;
};

// A unit sphere at the origin (material 0), optionally on a ground plane at y = -1 (material 1),
// seen from (0, 0.5, 4) with a 40 degree field of view; environment testSky(64), baked.
inline BakedScene makeTestBake(const TestBakeOptions& options) {
  BakedScene bake;
  Scene& scene = bake.scene;
  scene.meshes.push_back(
      toMesh(uvSphere(glm::vec3(0.0f), 1.0f, options.rings, options.segments), "sphere", 0));
  scene.materials.push_back(options.sphereMaterial);
  if (options.ground) {
    Mesh ground = toMesh(plane(glm::vec3(0.0f, -1.0f, 0.0f), 8.0f), "ground", 1);
    ground.isGround = true;
    scene.meshes.push_back(ground);
    Material grey;
    grey.baseColor = glm::vec3(0.5f);
    grey.metallic = 0.0f;
    scene.materials.push_back(grey);
  }
  scene.bounds = objectBounds(scene.meshes);
  scene.camera = Camera::lookAt(glm::vec3(0.0f, 0.5f, 4.0f), glm::vec3(0.0f), glm::vec3(0, 1, 0),
                                glm::radians(40.0f), 0.1f, 50.0f);
  VisibilitySettings settings;
  settings.rayCount = options.aoRays;
  attachVisibilityAttributes(scene.meshes, bakeVertexVisibility(scene.meshes, settings));
  bake.env = computeEnvironmentStages(
      testSky(), {.shWindowCutoff = std::nullopt, .specularSamples = 64, .lutSize = 32, .lutSamples = 64, .irradianceCubeSize = 16});
  return bake;
}

}  // namespace iblkit::test
