#include "baker/bake_in_memory.h"

#include <iostream>
#include <optional>

#include "baker/vertex_visibility.h"
#include "baker/visibility_attributes.h"
#include "core/scene_environment.h"

namespace iblkit {

namespace fs = std::filesystem;

BakedScene bakeInMemory(const fs::path& sceneFile, const InMemoryBakeOptions& options) {
  BakedScene bake;
  bake.scene = loadScene(sceneFile);
  bake.bakedInMemory = true;
  std::optional<EnvironmentMap> environment;
  if (!options.environmentStages) environment = loadSceneEnvironment(bake.scene, options.environment);
  std::cerr << sceneFile.string() << ": a scene, not a bake folder: baking it in memory (" << options.aoRays
            << " visibility rays per vertex)\n";
  VisibilitySettings settings;
  settings.rayCount = options.aoRays;
  useSceneMaterials(settings, bake.scene);  // AO rays pass through masked texels
  std::function<void(std::size_t, std::size_t)> stagesProgress;
  if (options.progress) {
    settings.progress = [&](std::size_t done, std::size_t total) { options.progress("visibility", done, total); };
    stagesProgress = [&](std::size_t done, std::size_t total) { options.progress("environment", done, total); };
  }
  attachVisibilityAttributes(bake.scene.meshes, bakeVertexVisibility(bake.scene.meshes, settings));
  if (options.environmentStages) {
    bake.env = *options.environmentStages;
  } else {
    bake.env = computeEnvironmentStages(*environment, options.stages, stagesProgress);
  }
  if (!bake.env.lights.suns.empty()) {
    settings.albedo = meshDiffuseAlbedos(bake.scene);
    attachSunBounce(bake.scene.meshes, bake.env.lights, settings);
  }
  return bake;
}

BakedScene loadOrBakeScene(const fs::path& folderOrScene, const InMemoryBakeOptions& options) {
  std::error_code error;
  if (fs::is_regular_file(folderOrScene, error)) return bakeInMemory(folderOrScene, options);
  return readBakeFolder(folderOrScene);
}

}  // namespace iblkit
