#pragma once
// glTF 2.0 loading (.gltf with external or embedded buffers, .glb), flattened to world-space
// triangle meshes. What is read and how:
// - Scene: the file's default scene, else scene 0, else every root node (a node no other node
//   lists as a child). Node transforms (matrix, or translation * rotation * scale) are
//   composed down the hierarchy; a node reached twice (a cycle, or two parents) is an error.
// - Primitives: TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN become triangle lists (glTF 2.0
//   section 3.7.2.1); points and lines are skipped with a warning. Indices may be unsigned
//   byte, short or int, or absent. Attributes: POSITION, NORMAL, TEXCOORD_0 and every attribute
//   whose name starts with '_' (SCALAR to VEC4); float or the integer types of
//   KHR_mesh_quantization. KHR_draco_mesh_compression is decoded.
// - Vertices keep the primitive's order (Draco: the decoder's order), so per-vertex data can be
//   written back (gltf_write.h). Zero-area triangles are dropped (warning with the count);
//   missing, NaN or zero-length normals are replaced by angle-weighted normals (warning).
// - Materials: baseColorFactor, metallicFactor, roughnessFactor, emissiveFactor (times
//   KHR_materials_emissive_strength), KHR_materials_specular's specularFactor and
//   specularColorFactor. Textures are ignored (one warning per file). Primitives without a
//   material use a default glTF material appended after the file's materials.
// - Ground: a node with extras {"isGround": true} (written by the baker, bakefile/scene_glb.h) gives
//   meshes with Mesh::isGround set, so objectBounds leaves them out as for a .json scene's ground.
// - Camera: the first perspective camera met in depth-first scene-graph order, placed by its
//   node's world transform (looking down its local -Z, +Y up). Its aspectRatio is ignored (the
//   image decides); without zfar, zfar comes from clipPlanesFor(camera, bounds of the meshes).
// Bad input (broken or truncated files, references or reads out of range, non-finite values,
// URIs leaving the file's folder, undecodable Draco data, nothing to draw) throws iblkit::Error
// with a one-line message naming the file.

#include <filesystem>
#include <optional>
#include <vector>

#include "core/camera.h"
#include "core/material.h"
#include "core/mesh.h"

namespace iblkit {

struct GltfContents {
  std::vector<Mesh> meshes;  // world space, one per (node, primitive); source.model = 0
  std::vector<Material> materials;
  std::vector<Texture> textures;  // Material TextureRef::texture indexes this
  std::vector<TextureImage> images;
  std::optional<Camera> camera;
};

GltfContents loadGltf(const std::filesystem::path& file);

}  // namespace iblkit
