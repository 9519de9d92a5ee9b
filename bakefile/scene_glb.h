#pragma once
// Writing a whole flattened Scene (every mesh in world space, the ground included, its
// materials and its camera) as one new glTF 2.0 binary file (.glb): the baker's output geometry,
// carrying the baked per-vertex attributes. A .json scene places several glTF models, so the
// result cannot be a copy of one input file (gltf_write.h); this writes the GLB container itself
// (glTF 2.0 section 4.4: 12-byte header, a JSON chunk padded with spaces and a BIN chunk padded
// with zeros, both to 4 bytes).

#include <filesystem>

#include "core/scene.h"

namespace iblkit {

// Writes `scene` to `file` as .glb; gltf_load.h reads it back to the same meshes (vertex order
// kept), materials, textures, images and camera. Per mesh: one glTF mesh with one triangle
// primitive (POSITION, NORMAL, TEXCOORD_0 and TEXCOORD_1 when present, TANGENT (VEC4, w the
// handedness) when Mesh::tangents is filled, uint32 indices, and every Mesh::attributes entry as a
// float SCALAR/VEC2/VEC3/VEC4 accessor under its own name), on one root node with the identity
// transform named after the mesh; the ground's node has extras {"isGround": true}. Materials:
// pbrMetallicRoughness factors (baseColorFactor's alpha included), emissiveFactor (with
// KHR_materials_emissive_strength when a component exceeds 1), KHR_materials_specular, alphaMode
// with alphaCutoff for MASK, doubleSided, and the five texture slots (texCoord, normalTexture's
// scale, occlusionTexture's strength, KHR_texture_transform when not the identity). Textures:
// Scene::images are copied byte for byte (TextureImage::encoded, never re-encoded) into the BIN
// chunk as buffer-view images with their mimeType; one sampler per texture (its filters and wrap
// modes); a WebP image is the texture's EXT_texture_webp source (in extensionsUsed and
// extensionsRequired). The camera, when the scene has one, is a perspective camera on its own node
// with aspectRatio = width / height. Written under a temporary name and renamed. Throws
// Error("<file>: ...") for a mesh without triangles, a material, texture or image index out of
// range, a texCoord other than 0 or 1, an image without encoded bytes or of another mime type,
// attribute data whose size does not match the vertex count, or a non-finite position, normal,
// texture coordinate, tangent or attribute value.
void writeSceneGlb(const Scene& scene, const std::filesystem::path& file);

}  // namespace iblkit
