#pragma once
// Builds small glTF 2.0 files in code for tests: accessors append to one binary buffer, and the
// JSON document is open for the test to edit (nodes, materials, cameras, deliberate mistakes).
// The same document can be written as .gltf with the buffer in a .bin file or a data URI, or
// as .glb.

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/base64.h"

namespace iblkit::test {

// glTF component types (glTF 2.0 section 3.6.2.2).
inline constexpr int kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123, kUnsignedInt = 5125,
                     kFloat = 5126;

class GltfBuilder {
 public:
  enum class Storage { BinFile, DataUri, Glb };

  GltfBuilder();

  nlohmann::json& document() { return document_; }

  // Appends bytes as a new buffer view (4-byte aligned); returns its index.
  int addBufferView(const void* data, std::size_t size, int byteStride = 0);
  // An accessor over a new buffer view holding `data`.
  int addAccessor(const void* data, std::size_t size, int componentType, std::size_t count,
                  const std::string& type, bool normalized = false, int byteStride = 0);
  int addFloats(const std::vector<glm::vec3>& values);  // VEC3 float, with min and max
  int addFloats(const std::vector<glm::vec2>& values);  // VEC2 float
  int addFloats(const std::vector<float>& values);      // SCALAR float
  int addFloats(const std::vector<glm::vec4>& values);  // VEC4 float (TANGENT)
  // Indices stored with the given component type (unsigned byte, short or int).
  int addIndices(const std::vector<std::uint32_t>& indices, int componentType = kUnsignedInt);

  // An image stored in a new buffer view with its mimeType (glTF 2.0 section 5.17); returns the
  // image's index. Textures, samplers and materials are left to the document.
  int addImage(const std::vector<std::uint8_t>& bytes, const std::string& mimeType);

  // A mesh of the given primitives; returns its index.
  int addMesh(const nlohmann::json& primitives);
  // A node; listed in scene 0 when `root`. Returns its index.
  int addNode(const nlohmann::json& node, bool root = true);
  // A mesh with one primitive on a root node: the common case.
  int addPrimitiveNode(const nlohmann::json& primitive);
  // The square [-halfSize, halfSize]^2 at z = 0 facing +z as cells x cells quads of two triangles,
  // on a root node: POSITION, NORMAL (+z) and TEXCOORD_0 from (0, 0) at its top left seen from +z
  // to (uvScale, uvScale), no TANGENT, material `material`. Returns the node's index.
  int addQuadNode(float halfSize = 1.0f, float uvScale = 1.0f, int cells = 1, int material = 0);

  // Writes the document to `path`; Storage::BinFile puts the buffer in "<stem>.bin" beside it.
  void write(const std::filesystem::path& path, Storage storage) const;

 private:
  nlohmann::json document_;
  std::vector<unsigned char> buffer_;
};

using iblkit::base64;  // core/base64.h, for data: URIs

// A unit cube, [0, 1]^3, 8 shared vertices and 12 counter-clockwise triangles, no normals.
struct CubeGeometry {
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;
};
CubeGeometry unitCube();

}  // namespace iblkit::test
