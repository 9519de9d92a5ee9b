#include "baker/bake_in_memory.h"

#include <iostream>

#include "baker/vertex_visibility.h"
#include "baker/visibility_attributes.h"
#include "core/environment_map_file.h"
#include "core/error.h"

namespace iblkit {

namespace fs = std::filesystem;

BakedScene bakeInMemory(const fs::path& sceneFile, const InMemoryBakeOptions& options) {
  BakedScene bake;
  bake.scene = loadScene(sceneFile);
  bake.bakedInMemory = true;
  const fs::path environmentFile =
      options.environment.empty() ? bake.scene.environment.file : options.environment;
  if (environmentFile.empty())
    fail(sceneFile, "names no environment map (give one, or bake it with iblkit-bake --env)");
  std::error_code error;
  if (!fs::is_regular_file(environmentFile, error)) fail(environmentFile, "missing (incomplete bake folder?)");
  EnvironmentMap environment = loadEnvironmentMap(environmentFile);
  environment.setRotationDegrees(bake.scene.environment.rotationDegrees);
  environment.setIntensity(bake.scene.environment.intensity);
  std::cerr << sceneFile.string() << ": a scene, not a bake folder: baking it in memory (" << options.aoRays
            << " visibility rays per vertex)\n";
  VisibilitySettings settings;
  settings.rayCount = options.aoRays;
  attachVisibilityAttributes(bake.scene.meshes, bakeVertexVisibility(bake.scene.meshes, settings));
  bake.env = computeEnvironmentStages(environment, options.stages);
  return bake;
}

BakedScene loadOrBakeScene(const fs::path& folderOrScene, const InMemoryBakeOptions& options) {
  std::error_code error;
  if (fs::is_regular_file(folderOrScene, error)) return bakeInMemory(folderOrScene, options);
  return readBakeFolder(folderOrScene);
}

}  // namespace iblkit
