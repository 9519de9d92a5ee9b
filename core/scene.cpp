#include "core/scene.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <utility>

#include "core/error.h"
#include "core/gltf_load.h"
#include "core/scene_file.h"
#include "core/tangent_frames.h"

namespace iblkit {

namespace {

std::string lowercaseExtension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

Scene sceneFromGltf(const std::filesystem::path& path) {
  GltfContents contents = loadGltf(path);
  Scene scene;
  scene.file = path;
  scene.modelFiles = {path};
  scene.meshes = std::move(contents.meshes);
  scene.materials = std::move(contents.materials);
  scene.textures = std::move(contents.textures);
  scene.images = std::move(contents.images);
  scene.camera = contents.camera;
  scene.bounds = objectBounds(scene.meshes);
  return scene;
}

// glTF 2.0 section 3.7.2.1: a primitive with a normal texture and no TANGENT gets MikkTSpace
// tangents. Done once here, after every mesh and material override exists, so the raster, the
// reference and the baker all perturb normals with the same frame. The meshes are already in
// world space: for a non-uniformly scaled node this differs slightly from MikkTSpace in the
// primitive's own space (docs/material-model.md "Tangents").
void generateMissingTangents(Scene& scene) {
  for (Mesh& mesh : scene.meshes) {
    if (mesh.material < 0 || mesh.material >= static_cast<int>(scene.materials.size())) continue;
    const TextureRef& normalTexture = scene.materials[mesh.material].normalTexture;
    if (normalTexture.present() && mesh.tangents.empty()) generateTangents(mesh, normalTexture.texCoord);
  }
}

// A slot reading a TEXCOORD set its primitive lacks (the glTF validator's error
// MESH_PRIMITIVE_MISSING_TEXCOORD, or a .json override giving a texture to an untextured model)
// reads uv (0, 0) everywhere, as a missing vertex attribute reads 0 in OpenGL: the set is filled
// with zeros and a warning, so every program indexes the same, present uvs.
void fillMissingTexcoords(Scene& scene) {
  for (Mesh& mesh : scene.meshes) {
    if (mesh.material < 0 || mesh.material >= static_cast<int>(scene.materials.size())) continue;
    const Material& m = scene.materials[mesh.material];
    for (int set = 0; set < 2; ++set) {
      std::vector<glm::vec2>& uvs = set == 0 ? mesh.texcoords : mesh.texcoords1;
      bool reads = false;
      for (const TextureRef* ref : {&m.baseColorTexture, &m.metallicRoughnessTexture, &m.normalTexture,
                                    &m.occlusionTexture, &m.emissiveTexture})
        reads = reads || (ref->present() && ref->texCoord == set);
      if (!reads || !uvs.empty()) continue;
      uvs.assign(mesh.vertexCount(), glm::vec2(0.0f));
      const bool model = mesh.source.model >= 0 && mesh.source.model < static_cast<int>(scene.modelFiles.size());
      const std::string where = mesh.source.mesh >= 0 ? "mesh " + std::to_string(mesh.source.mesh) + " primitive " +
                                                            std::to_string(mesh.source.primitive)
                                                      : "'" + mesh.name + "'";
      warn(model ? scene.modelFiles[mesh.source.model] : scene.file,
           where + ": material '" + m.name + "' reads TEXCOORD_" + std::to_string(set) +
               ", which the mesh does not have; its textures read uv (0, 0)");
    }
  }
}

}  // namespace

Scene loadScene(const std::filesystem::path& path) {
  const std::string extension = lowercaseExtension(path);
  Scene scene;
  if (extension == ".json")
    scene = loadSceneFile(path);
  else if (extension == ".gltf" || extension == ".glb")
    scene = sceneFromGltf(path);
  else
    fail(path, "unknown scene type '" + path.extension().string() + "' (expected .json, .gltf or .glb)");
  fillMissingTexcoords(scene);
  generateMissingTangents(scene);
  return scene;
}

Bounds objectBounds(const std::vector<Mesh>& meshes) {
  Bounds bounds;
  for (const Mesh& mesh : meshes)
    if (!mesh.isGround) bounds.extend(mesh.bounds());
  return bounds;
}

Camera sceneCamera(const Scene& scene, float aspect) {
  return scene.camera ? *scene.camera : frameBounds(scene.bounds, aspect);
}

}  // namespace iblkit
