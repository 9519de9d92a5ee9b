#include "bakefile/bake_folder.h"

#include <fstream>
#include <nlohmann/json.hpp>

#include "bakefile/bake_layout.h"
#include "bakefile/bake_record.h"
#include "bakefile/vertex_attributes.h"
#include "core/error.h"

namespace iblkit {

namespace fs = std::filesystem;

BakedScene readBakeFolder(const fs::path& folder) {
  std::error_code error;
  if (!fs::is_directory(folder, error)) fail(folder, "no such bake folder");
  const BakeInputs inputs = readBakeRecord(folder / kBakeRecordFile);
  BakedScene bake;
  const fs::path sceneFile = folder / kBakeSceneFile;
  if (!fs::is_regular_file(sceneFile, error)) fail(sceneFile, "missing (incomplete bake folder?)");
  bake.env = readEnvironmentStages(folder, inputs);
  bake.scene = loadScene(sceneFile);
  requireBakedAttributes(bake.scene, sceneFile);
  return bake;
}

bool isBakeFolder(const fs::path& folder) {
  std::ifstream stream(folder / kBakeRecordFile);
  if (!stream) return false;
  const nlohmann::json record = nlohmann::json::parse(stream, nullptr, false);
  return record.is_object() && record.value("version", std::string()) == kBakeVersion;
}

}  // namespace iblkit
