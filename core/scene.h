#pragma once
// Scene: everything a program renders or bakes, loaded from a scene description (.json,
// docs/scene-format.md) or directly from a glTF file (.gltf / .glb, gltf_load.h).

#include <filesystem>
#include <optional>
#include <vector>

#include "core/camera.h"
#include "core/material.h"
#include "core/mesh.h"

namespace iblkit {

// Image size used when a scene does not give one (16:9).
inline constexpr int kDefaultImageWidth = 960;
inline constexpr int kDefaultImageHeight = 540;

// The environment map lighting the scene. A bare glTF file has none (empty file): the program
// chooses one.
struct EnvironmentSettings {
  std::filesystem::path file;    // absolute or relative to the working directory
  float rotationDegrees = 0.0f;  // about world +Y, right-handed (counter-clockwise seen from above)
  float intensity = 1.0f;        // radiance multiplier
};

struct Scene {
  std::filesystem::path file;                     // what loadScene was given
  std::vector<std::filesystem::path> modelFiles;  // glTF files; MeshSource::model indexes this
  std::vector<Mesh> meshes;                       // world space, the ground (if any) included
  std::vector<Material> materials;                // Mesh::material indexes this
  std::vector<Texture> textures;                  // TextureRef::texture indexes this
  std::vector<TextureImage> images;               // Texture::image indexes this
  std::optional<Camera> camera;                   // absent: sceneCamera frames the bounds
  EnvironmentSettings environment;
  Bounds bounds;  // of every mesh except the ground
  int width = kDefaultImageWidth, height = kDefaultImageHeight;
};

// Loads a .json scene description, or a .gltf / .glb file as a scene of its own (its camera, no
// environment, default image size). The extension decides, case-insensitively; any other
// extension is an Error.
Scene loadScene(const std::filesystem::path& path);

// Bounds of all meshes that are not the ground.
Bounds objectBounds(const std::vector<Mesh>& meshes);

// The scene's camera, or frameBounds(scene.bounds, aspect) when it has none.
Camera sceneCamera(const Scene& scene, float aspect);

}  // namespace iblkit
