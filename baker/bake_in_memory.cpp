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
  attachVisibilityAttributes(bake.scene.meshes, bakeVertexVisibility(bake.scene.meshes, settings));
  bake.env = options.environmentStages ? *options.environmentStages : computeEnvironmentStages(*environment, options.stages);
  return bake;
}

BakedScene loadOrBakeScene(const fs::path& folderOrScene, const InMemoryBakeOptions& options) {
  std::error_code error;
  if (fs::is_regular_file(folderOrScene, error)) return bakeInMemory(folderOrScene, options);
  return readBakeFolder(folderOrScene);
}

}  // namespace iblkit
