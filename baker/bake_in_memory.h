#pragma once
// A scene baked in memory, as iblkit-view does when it is given a scene rather than a bake folder:
// few visibility rays and the viewer's lighter environment stages, so it takes a second or two.
// The program chooses this explicitly (programs/iblkit_view.cpp); the GL libraries only read a
// BakedScene (bakefile/bake_folder.h).
#include <filesystem>

#include "baker/environment_stages.h"
#include "bakefile/bake_folder.h"

namespace iblkit {

struct InMemoryBakeOptions {
  // Visibility rays per vertex (few: this runs at start-up).
  int aoRays = 64;
  // The environment map; empty = the scene's environment.file.
  std::filesystem::path environment;
  EnvironmentStageOptions stages = kViewerEnvironmentStages;
};

// Loads `sceneFile` (.json, .gltf or .glb), bakes its vertex visibility and its environment's
// stages (the scene's rotation and intensity applied), and says so on stderr. Throws
// Error("<file>: ...") for a scene that names no environment map or a map that is missing.
BakedScene bakeInMemory(const std::filesystem::path& sceneFile, const InMemoryBakeOptions& options = {});

// A bake folder read with readBakeFolder, or a scene file baked with bakeInMemory.
BakedScene loadOrBakeScene(const std::filesystem::path& folderOrScene, const InMemoryBakeOptions& options = {});

}  // namespace iblkit
