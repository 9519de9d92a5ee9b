#include "bakefile/bake_folder.h"


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
  const fs::path sceneFile = requireBakeFile(folder / kBakeSceneFile);
  bake.env = readEnvironmentStages(folder, inputs);
  bake.scene = loadScene(sceneFile);
  bake.transferBounces = inputs.transferBounces;
  requireBakedAttributes(bake.scene, sceneFile);
  return bake;
}

}  // namespace iblkit
