#pragma once
// The scene a program renders, taken the same way by every program that renders one
// (iblkit-view, its window and --headless, and iblkit-trace): a positional MODEL, which is a .json
// scene or a bare .gltf/.glb model (or, for iblkit-view, a bake folder), and --env MAP,
// --env-rotation DEGREES and --env-intensity X, each replacing the scene's (docs/conventions.md).
// A bare model names no map, so `MODEL --env MAP` is how a glTF is lit without a scene file.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>

#include "core/scene_environment.h"

namespace iblkit {

struct SceneArguments {
  std::filesystem::path input;      // the positional MODEL
  EnvironmentOverride environment;  // --env, --env-rotation, --env-intensity
};

// Adds the positional `name` (its help is `description`; required unless `required` is false,
// for a program that can take the scene from elsewhere) and the environment options
// (addEnvironmentOptions, cli/program.h) to `app`.
void addSceneArguments(CLI::App& app, SceneArguments& arguments, const std::string& name,
                       const std::string& description, bool required = true);

// checkEnvironmentOverride (a UsageError for a rotation or intensity no map can take), then a
// missing --env file as Error("MAP: cannot open: No such file or directory"), the loader's words: both before a scene is read or baked.
void checkSceneArguments(const SceneArguments& arguments);

// True when `input` names a file (a scene or a model) rather than a bake folder.
bool isSceneFile(const std::filesystem::path& input);

}  // namespace iblkit
