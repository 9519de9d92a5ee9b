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
