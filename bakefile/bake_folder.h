#pragma once
// A bake folder as its readers see it (bake_layout.h; docs/baker.md): the baked scene and the
// environment stages. The engine, the viewer and the report read bakes through here; a scene
// baked in memory (baker/bake_in_memory.h) gives the same BakedScene.
#include <filesystem>

#include "bakefile/environment_stages.h"
#include "core/scene.h"

namespace iblkit {

struct BakedScene {
  // Meshes in world space, ground included (Mesh::isGround from the glTF extras). Every mesh
  // carries the baked vertex attributes _AO, _BENTNORMAL, _BENTLENGTH and _SHT0.._SHT2
  // (vertex_attributes.h).
  Scene scene;
  EnvironmentStages env;
  // True when the scene was baked in memory rather than read from a folder.
  bool bakedInMemory = false;
  // Interreflection bounces in the meshes' SH transfer (BakeInputs::transferBounces; 0 for an
  // in-memory bake).
  int transferBounces = 0;
};

// Reads an iblkit-bake output folder: bake.json, whose "version" must be kBakeVersion and which
// names the environment map, its rotation and intensity (the lat-long map is read from there, for
// the sky and the `mirror` mode), scene.glb (with the baked attributes on every mesh), and the
// environment stages. Throws Error("<file>: <problem>") naming the file that is missing,
// incomplete or of the wrong version.
BakedScene readBakeFolder(const std::filesystem::path& folder);

}  // namespace iblkit
