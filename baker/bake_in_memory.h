#pragma once
// A scene baked in memory, as iblkit-view does when it is given a scene rather than a bake folder:
// few visibility rays and the viewer's lighter environment stages, so it takes a second or two.
// The program chooses this explicitly (programs/iblkit_view.cpp); the GL libraries only read a
// BakedScene (bakefile/bake_folder.h).
#include <cstddef>
#include <filesystem>
#include <functional>

#include "bakefile/bake_folder.h"
#include "baker/environment_stages.h"
#include "core/scene_environment.h"

namespace iblkit {

struct InMemoryBakeOptions {
  // Visibility rays per vertex (few: this runs at start-up).
  int aoRays = 64;
  // The environment map, its rotation and intensity; unset: the scene's.
  EnvironmentOverride environment;
  EnvironmentStageOptions stages = kViewerEnvironmentStages;
  // Given: these stages light the scene as they are (no map is loaded; `environment` and `stages`
  // are unused): the viewer opening a model under the environment it already shows.
  const EnvironmentStages* environmentStages = nullptr;
  // Called with the step under way ("visibility": vertices; "environment": stages) and how far it
  // is (done of total), from worker threads and possibly concurrently: it must be thread-safe.
  // Each step ends with done == total. May be empty.
  std::function<void(const char* step, std::size_t done, std::size_t total)> progress;
};

// Loads `sceneFile` (.json, .gltf or .glb), bakes its vertex visibility and its environment's
// stages (loadSceneEnvironment: the scene's rotation and intensity unless overridden), and says so
// on stderr. Throws Error("<file>: ...") for a scene that names no environment map or a map that
// is missing.
BakedScene bakeInMemory(const std::filesystem::path& sceneFile, const InMemoryBakeOptions& options = {});

// A bake folder read with readBakeFolder, or a scene file baked with bakeInMemory.
BakedScene loadOrBakeScene(const std::filesystem::path& folderOrScene, const InMemoryBakeOptions& options = {});

}  // namespace iblkit
