#include "baker/reused_visibility.h"

#include <algorithm>
#include <string>

#include "bakefile/bake_layout.h"
#include "bakefile/bake_record.h"
#include "bakefile/vertex_attributes.h"
#include "baker/reused_bake.h"
#include "core/content_hash.h"
#include "core/error.h"
#include "core/scene.h"
#include "core/texture.h"

namespace iblkit {

namespace fs = std::filesystem;
using nlohmann::json;

std::string sceneContentHash(const Scene& scene) {
  ContentHash hash;
  std::vector<fs::path> files = {scene.file};
  const auto add = [&](const fs::path& file) {
    if (!file.empty() && std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
  };
  for (const fs::path& model : scene.modelFiles) add(model);
  // An image embedded in a glTF names no file of its own: the model's bytes hold it.
  for (const TextureImage& image : scene.images) add(image.file);
  for (const fs::path& file : files) {
    // A procedural shape's model entry ("shape:sphere") names no file; the scene file holds it.
    std::error_code error;
    if (fs::is_regular_file(file, error))
      hash.add(file.filename().string()).addFile(file);
    else
      hash.add(file.string());
  }
  return hash.hex();
}

void reuseVisibility(const fs::path& bake, const json& parameters, const std::string& sceneHash, Scene& scene) {
  std::vector<Mesh>& meshes = scene.meshes;
  BakeInputs inputs;
  const json record = readBakeToReuse(bake, inputs);
  const fs::path recordFile = bake / kBakeRecordFile;
  requireSameParameters(bake, record, parameters, kVisibilityParameters, "visibility", "--visibility-from",
                        "the same visibility options");
  if (!record.contains("scene_hash") || record["scene_hash"] != sceneHash)
    fail(recordFile, "baked from other scene files than " + scene.file.string() +
                         " (its scene_hash differs: the scene, a model or a texture is not the same)");
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
