#include "support/gltf_builder.h"

#include <array>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace iblkit::test {

namespace {

void writeBytes(const std::filesystem::path& path, const void* data, std::size_t size) {
  std::ofstream stream(path, std::ios::binary);
  stream.write(static_cast<const char*>(data), std::streamsize(size));
  if (!stream) throw std::runtime_error("cannot write " + path.string());
}

void appendU32(std::vector<unsigned char>& out, std::uint32_t value) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(&value);
  out.insert(out.end(), bytes, bytes + 4);
}

}  // namespace

GltfBuilder::GltfBuilder() {
  document_ = {
      {"asset", {{"version", "2.0"}}}, {"scene", 0}, {"scenes", {{{"nodes", nlohmann::json::array()}}}}};
}

int GltfBuilder::addBufferView(const void* data, std::size_t size, int byteStride) {
  buffer_.resize((buffer_.size() + 3) / 4 * 4, 0);
  nlohmann::json view = {{"buffer", 0}, {"byteOffset", buffer_.size()}, {"byteLength", size}};
  if (byteStride) view["byteStride"] = byteStride;
  const auto* bytes = static_cast<const unsigned char*>(data);
  buffer_.insert(buffer_.end(), bytes, bytes + size);
  document_["bufferViews"].push_back(view);
  return int(document_["bufferViews"].size()) - 1;
}

int GltfBuilder::addAccessor(const void* data, std::size_t size, int componentType, std::size_t count,
                             const std::string& type, bool normalized, int byteStride) {
  nlohmann::json accessor = {{"bufferView", addBufferView(data, size, byteStride)},
                             {"componentType", componentType},
                             {"count", count},
                             {"type", type}};
  if (normalized) accessor["normalized"] = true;
  document_["accessors"].push_back(accessor);
  return int(document_["accessors"].size()) - 1;
}

int GltfBuilder::addFloats(const std::vector<glm::vec3>& values) {
  const int index =
      addAccessor(values.data(), values.size() * sizeof(glm::vec3), kFloat, values.size(), "VEC3");
  if (!values.empty()) {
    glm::vec3 lo = values[0], hi = values[0];
    for (const glm::vec3& v : values) lo = glm::min(lo, v), hi = glm::max(hi, v);
    document_["accessors"][index]["min"] = {lo.x, lo.y, lo.z};
    document_["accessors"][index]["max"] = {hi.x, hi.y, hi.z};
  }
  return index;
}

int GltfBuilder::addFloats(const std::vector<glm::vec2>& values) {
  return addAccessor(values.data(), values.size() * sizeof(glm::vec2), kFloat, values.size(), "VEC2");
}

int GltfBuilder::addFloats(const std::vector<float>& values) {
  return addAccessor(values.data(), values.size() * sizeof(float), kFloat, values.size(), "SCALAR");
}

int GltfBuilder::addFloats(const std::vector<glm::vec4>& values) {
  return addAccessor(values.data(), values.size() * sizeof(glm::vec4), kFloat, values.size(), "VEC4");
}

int GltfBuilder::addImage(const std::vector<std::uint8_t>& bytes, const std::string& mimeType) {
  document_["images"].push_back({{"bufferView", addBufferView(bytes.data(), bytes.size())}, {"mimeType", mimeType}});
  return int(document_["images"].size()) - 1;
}

int GltfBuilder::addIndices(const std::vector<std::uint32_t>& indices, int componentType) {
  const std::size_t size = componentType == kUnsignedByte ? 1 : componentType == kUnsignedShort ? 2 : 4;
  std::vector<unsigned char> bytes(indices.size() * size);
  for (std::size_t i = 0; i < indices.size(); ++i)
    std::memcpy(&bytes[i * size], &indices[i], size);  // little-endian
  return addAccessor(bytes.data(), bytes.size(), componentType, indices.size(), "SCALAR");
}

int GltfBuilder::addMesh(const nlohmann::json& primitives) {
  document_["meshes"].push_back({{"primitives", primitives}});
  return int(document_["meshes"].size()) - 1;
}

int GltfBuilder::addNode(const nlohmann::json& node, bool root) {
  document_["nodes"].push_back(node);
  const int index = int(document_["nodes"].size()) - 1;
  if (root) document_["scenes"][0]["nodes"].push_back(index);
  return index;
}

int GltfBuilder::addPrimitiveNode(const nlohmann::json& primitive) {
  return addNode({{"mesh", addMesh(nlohmann::json::array({primitive}))}});
}

int GltfBuilder::addQuadNode(float halfSize, float uvScale, int cells, int material) {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec2> uvs;
  for (int i = 0; i <= cells; ++i)
    for (int j = 0; j <= cells; ++j) {
      const float x = static_cast<float>(j) / cells, y = static_cast<float>(i) / cells;
      positions.emplace_back(halfSize * (2.0f * x - 1.0f), halfSize * (2.0f * y - 1.0f), 0.0f);
      uvs.emplace_back(uvScale * x, uvScale * (1.0f - y));
    }
  const std::vector<glm::vec3> normals(positions.size(), glm::vec3(0, 0, 1));
  std::vector<std::uint32_t> indices;
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j) {
      const std::uint32_t a = static_cast<std::uint32_t>(i * (cells + 1) + j);
      const std::uint32_t b = a + static_cast<std::uint32_t>(cells + 1);
      for (std::uint32_t c : {a, a + 1, b + 1, a, b + 1, b}) indices.push_back(c);
    }
  return addPrimitiveNode({{"attributes",
                            {{"POSITION", addFloats(positions)},
                             {"NORMAL", addFloats(normals)},
                             {"TEXCOORD_0", addFloats(uvs)}}},
                           {"indices", addIndices(indices)},
                           {"material", material}});
}

void GltfBuilder::write(const std::filesystem::path& path, Storage storage) const {
  nlohmann::json document = document_;
  if (!buffer_.empty()) {
    nlohmann::json buffer = {{"byteLength", buffer_.size()}};
    if (storage == Storage::BinFile) {
      const std::filesystem::path bin = std::filesystem::path(path).replace_extension(".bin");
      writeBytes(bin, buffer_.data(), buffer_.size());
      buffer["uri"] = bin.filename().string();
    } else if (storage == Storage::DataUri) {
      buffer["uri"] = "data:application/octet-stream;base64," + base64(buffer_);
    }
    // Buffer 0 is the builder's; buffers a test added after it (EXT_meshopt_compression's
    // fallback buffer, say) are kept.
    nlohmann::json buffers = document_.contains("buffers") && document_["buffers"].is_array() ? document_["buffers"]
                                                                                             : nlohmann::json::array();
    if (buffers.empty())
      buffers.push_back(buffer);
    else
      buffers[0] = buffer;
    document["buffers"] = buffers;
  }
  std::string json = document.dump();
  if (storage != Storage::Glb) {
    writeBytes(path, json.data(), json.size());
    return;
  }
  // GLB container (glTF 2.0 section 4.4): header, JSON chunk padded with spaces, BIN chunk
  // padded with zeros.
  json.resize((json.size() + 3) / 4 * 4, ' ');
  std::vector<unsigned char> bin = buffer_;
  bin.resize((bin.size() + 3) / 4 * 4, 0);
  std::vector<unsigned char> glb;
  const std::size_t total = 12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size());
  glb.insert(glb.end(), {'g', 'l', 'T', 'F'});
  appendU32(glb, 2);
  appendU32(glb, std::uint32_t(total));
  appendU32(glb, std::uint32_t(json.size()));
  appendU32(glb, 0x4E4F534Au);
  glb.insert(glb.end(), json.begin(), json.end());
  if (!bin.empty()) {
    appendU32(glb, std::uint32_t(bin.size()));
    appendU32(glb, 0x004E4942u);
    glb.insert(glb.end(), bin.begin(), bin.end());
  }
  writeBytes(path, glb.data(), glb.size());
}

CubeGeometry unitCube() {
  CubeGeometry cube;
  for (int i = 0; i < 8; ++i)
    cube.positions.emplace_back(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1));
  // Each face as a cycle of corners; ordered counter-clockwise seen from outside below.
  const std::array<std::array<std::uint32_t, 4>, 6> faces = {
      {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}}};
  for (std::size_t f = 0; f < faces.size(); ++f) {
    std::array<std::uint32_t, 4> q = faces[f];
    glm::vec3 outward(0.0f);
    outward[int(f / 2)] = (f % 2) ? 1.0f : -1.0f;
    const glm::vec3& a = cube.positions[q[0]];
    if (glm::dot(glm::cross(cube.positions[q[1]] - a, cube.positions[q[2]] - a), outward) < 0.0f)
      std::swap(q[1], q[3]);
    cube.indices.insert(cube.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
  }
  return cube;
}

}  // namespace iblkit::test
