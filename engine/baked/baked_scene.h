#pragma once
// A baked scene as the engine reads it: the output folder of iblkit-bake (docs/baker.md), or a
// scene file baked in memory with the baker library.
#include <filesystem>

#include "engine/baked/environment_stages.h"
#include "core/scene.h"

namespace iblkit {

// The bake.json version this reader understands.
inline constexpr const char* kBakeVersion = "iblkit-bake 1";

struct BakedScene {
  // Meshes in world space, ground included (Mesh::isGround from the glTF extras). Every mesh
  // carries the baked vertex attributes _AO, _BENTNORMAL, _BENTLENGTH and _SHT0.._SHT2
  // (baker/visibility_attributes.h).
  Scene scene;
  EnvironmentStages env;
  // True when loadBake was given a scene and baked it itself.
  bool bakedInMemory = false;
};

struct LoadBakeOptions {
  // In-memory bakes only: visibility rays per vertex (few: this runs at start-up).
  int aoRays = 64;
  // In-memory bakes only: the environment map; empty = the scene's environment.file.
  std::filesystem::path environment;
};

// Reads an iblkit-bake output folder: scene.glb (with the baked attributes on every mesh),
// env/sh9.json, env/specular.exr (all levels), env/brdf_lut.exr and bake.json, whose "version" must
// be kBakeVersion and which names the environment map, its rotation and intensity (the lat-long
// map is read from there, for the sky and the `mirror` mode).
// Given a .json, .gltf or .glb scene instead, bakes it in memory (visibility with options.aoRays,
// and prepareEnvironment) and says so on stderr.
// Throws Error("<file>: <problem>") naming the file that is missing, incomplete or of the wrong
// version.
BakedScene loadBake(const std::filesystem::path& dirOrScene, const LoadBakeOptions& options = {});

}  // namespace iblkit
