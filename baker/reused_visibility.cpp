#include "baker/reused_visibility.h"

#include <fstream>
#include <string>

#include "bakefile/bake_layout.h"
#include "bakefile/bake_record.h"
#include "bakefile/vertex_attributes.h"
#include "core/error.h"
#include "core/scene.h"

namespace iblkit {

namespace fs = std::filesystem;
using nlohmann::json;

void reuseVisibility(const fs::path& bake, const json& parameters, std::vector<Mesh>& meshes) {
  std::error_code error;
  if (!fs::is_directory(bake, error)) fail(bake, "no such bake folder");
  const fs::path recordFile = requireBakeFile(bake / kBakeRecordFile);
  readBakeRecord(recordFile);  // the version and the inputs
  std::ifstream stream(recordFile);
  const json record = json::parse(stream, nullptr, false);
  if (record.is_discarded() || !record.contains("parameters") || !record["parameters"].is_object())
    fail(recordFile, "no parameters");
  for (const char* name : kVisibilityParameters) {
    const json& theirs = record["parameters"].contains(name) ? record["parameters"][name] : json();
    const json& ours = parameters.at(name);
    if (theirs != ours)
      fail(recordFile, std::string("visibility baked with ") + name + " " + theirs.dump() + ", not " + ours.dump() +
                           " (--visibility-from needs the same visibility options)");
  }
  const fs::path sceneFile = requireBakeFile(bake / kBakeSceneFile);
  const Scene baked = loadScene(sceneFile);
  if (baked.meshes.size() != meshes.size())
    fail(sceneFile, std::to_string(baked.meshes.size()) + " meshes, the scene has " + std::to_string(meshes.size()) +
                        " (not a bake of this scene)");
  const char* names[] = {kAmbientOcclusionAttribute, kBentNormalAttribute, kBentLengthAttribute,
                         kTransferAttributes[0],     kTransferAttributes[1], kTransferAttributes[2]};
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const Mesh& from = baked.meshes[m];
    Mesh& to = meshes[m];
    if (from.positions != to.positions || from.indices != to.indices || from.isGround != to.isGround)
      fail(sceneFile, "mesh " + std::to_string(m) + " '" + to.name + "' is not the scene's (not a bake of this scene)");
    for (const char* name : names) {
      const auto found = from.attributes.find(name);
      if (found == from.attributes.end() ||
          found->second.data.size() != std::size_t(found->second.componentCount) * from.vertexCount())
        fail(sceneFile, "mesh " + std::to_string(m) + " has no vertex attribute " + name);
      to.attributes[name] = found->second;
    }
  }
}

}  // namespace iblkit
