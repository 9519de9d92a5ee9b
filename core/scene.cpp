#include "core/scene.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <utility>

#include "core/error.h"
#include "core/gltf_load.h"
#include "core/scene_file.h"

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

}  // namespace

Scene loadScene(const std::filesystem::path& path) {
  const std::string extension = lowercaseExtension(path);
  if (extension == ".json") return loadSceneFile(path);
  if (extension == ".gltf" || extension == ".glb") return sceneFromGltf(path);
  fail(path, "unknown scene type '" + path.extension().string() + "' (expected .json, .gltf or .glb)");
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
