#pragma once
// The .json scene description (docs/scene-format.md): glTF models placed in the world, an
// optional ground plane, the environment map, an optional camera and the image size. Parsing is
// strict: an unknown key (a typo) or a value of the wrong type is an Error naming its key path,
// e.g. "scene.json: models[0].scale: expected a nonzero number or an array of 3 nonzero numbers".

#include <filesystem>

#include "core/scene.h"

namespace iblkit {

// Loads a .json scene; paths inside it are relative to the file's folder.
Scene loadSceneFile(const std::filesystem::path& file);

}  // namespace iblkit
