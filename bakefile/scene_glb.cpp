#include "bakefile/scene_glb.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/file_io.h"

namespace iblkit {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// glTF 2.0 constants: component types (section 3.6.2.2), buffer view targets (3.6.1.2), and the
// GLB magic numbers (section 4.4).
constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr std::uint32_t kGlbMagic = 0x46546C67, kGlbVersion = 2, kChunkJson = 0x4E4F534A,
                        kChunkBin = 0x004E4942;
const char* const kAccessorTypes[] = {"SCALAR", "VEC2", "VEC3", "VEC4"};

// Accumulates the BIN chunk and the accessors that describe it.
class BinaryBuffer {
 public:
  explicit BinaryBuffer(json& document) : document_(document) {}

  // Appends `count` elements of `components` values each (4-byte floats or uint32) as a buffer
  // view and an accessor over it; returns the accessor's index.
  int addAccessor(const void* data, std::size_t count, int components, int componentType, int target) {
    const std::size_t size = count * std::size_t(components) * 4;
    const std::size_t offset = bytes_.size();  // always a multiple of 4: every element is 4 bytes
    bytes_.resize(offset + size);
    std::memcpy(bytes_.data() + offset, data, size);
    json& views = document_["bufferViews"];
    views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}, {"target", target}});
    json& accessors = document_["accessors"];
    accessors.push_back({{"bufferView", views.size() - 1},
                         {"componentType", componentType},
                         {"count", count},
                         {"type", kAccessorTypes[components - 1]}});
    return int(accessors.size()) - 1;
  }

  // POSITION needs its bounds (glTF 2.0 section 3.7.2.1).
  int addPositions(const std::vector<glm::vec3>& positions) {
    const int index = addAccessor(positions.data(), positions.size(), 3, kFloat, kArrayBuffer);
    glm::vec3 lower = positions.front(), upper = positions.front();
    for (const glm::vec3& p : positions) lower = glm::min(lower, p), upper = glm::max(upper, p);
    document_["accessors"][index]["min"] = {lower.x, lower.y, lower.z};
    document_["accessors"][index]["max"] = {upper.x, upper.y, upper.z};
    return index;
  }

  const std::vector<unsigned char>& bytes() const { return bytes_; }

 private:
  json& document_;
  std::vector<unsigned char> bytes_;
};

void requireFinite(const fs::path& file, const float* values, std::size_t count, const std::string& what) {
  for (std::size_t i = 0; i < count; ++i)
    if (!std::isfinite(values[i])) fail(file, what + " has a non-finite value");
}

json primitive(const Mesh& mesh, std::size_t index, std::size_t materialCount, BinaryBuffer& buffer,
               const fs::path& file) {
  const std::string what = "mesh " + std::to_string(index) + " (" + mesh.name + ")";
  const std::size_t vertices = mesh.vertexCount();
  if (mesh.triangleCount() == 0 || mesh.indices.size() % 3 != 0) fail(file, what + " has no whole triangles");
  if (mesh.material < 0 || std::size_t(mesh.material) >= materialCount)
    fail(file, what + ": material " + std::to_string(mesh.material) + " does not exist");
  if (mesh.normals.size() != vertices || (!mesh.texcoords.empty() && mesh.texcoords.size() != vertices))
    fail(file, what + ": normals or texture coordinates do not match the " + std::to_string(vertices) +
                   " vertices");
  for (const std::uint32_t i : mesh.indices)
    if (i >= vertices) fail(file, what + ": index " + std::to_string(i) + " is out of range");
  requireFinite(file, &mesh.positions.front().x, 3 * vertices, what + " POSITION");
  requireFinite(file, &mesh.normals.front().x, 3 * vertices, what + " NORMAL");

  json attributes;
  attributes["POSITION"] = buffer.addPositions(mesh.positions);
  attributes["NORMAL"] = buffer.addAccessor(mesh.normals.data(), vertices, 3, kFloat, kArrayBuffer);
  if (!mesh.texcoords.empty())
    attributes["TEXCOORD_0"] = buffer.addAccessor(mesh.texcoords.data(), vertices, 2, kFloat, kArrayBuffer);
  for (const auto& [name, attribute] : mesh.attributes) {
    const std::string where = what + " attribute " + name;
    if (name.size() < 2 || name[0] != '_') fail(file, where + ": name must start with '_'");
    if (attribute.componentCount < 1 || attribute.componentCount > 4)
      fail(file, where + ": componentCount must be in 1..4");
    if (attribute.data.size() != vertices * std::size_t(attribute.componentCount))
      fail(file, where + " has " + std::to_string(attribute.data.size()) + " values for " +
                     std::to_string(vertices) + " vertices");
    requireFinite(file, attribute.data.data(), attribute.data.size(), where);
    attributes[name] =
        buffer.addAccessor(attribute.data.data(), vertices, attribute.componentCount, kFloat, kArrayBuffer);
  }
  const int indices =
      buffer.addAccessor(mesh.indices.data(), mesh.indices.size(), 1, kUnsignedInt, kElementArrayBuffer);
  return {{"attributes", attributes}, {"indices", indices}, {"material", mesh.material}, {"mode", 4}};
}

json material(const Material& m, json& extensionsUsed) {
  json pbr = {{"baseColorFactor", {m.baseColor.r, m.baseColor.g, m.baseColor.b, 1.0f}},
              {"metallicFactor", m.metallic},
              {"roughnessFactor", m.roughness}};
  json result = {{"name", m.name}, {"pbrMetallicRoughness", pbr}};
  result["extensions"]["KHR_materials_specular"] = {
      {"specularFactor", m.specular},
      {"specularColorFactor", {m.specularColor.r, m.specularColor.g, m.specularColor.b}}};
  extensionsUsed.push_back("KHR_materials_specular");
  // emissiveFactor is limited to [0, 1]; a brighter emission keeps its colour there and its
  // intensity in KHR_materials_emissive_strength.
  const float strength = std::max({m.emissive.r, m.emissive.g, m.emissive.b});
  if (strength > 0.0f) {
    const glm::vec3 factor = strength > 1.0f ? m.emissive / strength : m.emissive;
    result["emissiveFactor"] = {factor.r, factor.g, factor.b};
    if (strength > 1.0f) {
      result["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", strength}};
      extensionsUsed.push_back("KHR_materials_emissive_strength");
    }
  }
  return result;
}

// The camera's node transform: glTF cameras look down their local -Z with +Y up (section 3.10.2).
json cameraMatrix(const Camera& camera) {
  const glm::vec3 back = -camera.forward, right = glm::normalize(glm::cross(camera.up, back));
  const glm::vec3 up = glm::cross(back, right);
  const glm::vec3 columns[4] = {right, up, back, camera.position};
  json matrix = json::array();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) matrix.push_back(r < 3 ? columns[c][r] : (c == 3 ? 1.0f : 0.0f));
  return matrix;
}

void appendUint32(std::vector<char>& out, std::uint32_t value) {
  for (int byte = 0; byte < 4; ++byte) out.push_back(static_cast<char>((value >> (8 * byte)) & 0xffu));
}

}  // namespace

void writeSceneGlb(const Scene& scene, const fs::path& file) {
  if (scene.meshes.empty()) fail(file, "the scene has no meshes");
  json document = {{"asset", {{"version", "2.0"}, {"generator", "iblkit-bake"}}}, {"scene", 0}};
  BinaryBuffer buffer(document);
  json extensionsUsed = json::array();
  document["materials"] = json::array();
  for (const Material& m : scene.materials) document["materials"].push_back(material(m, extensionsUsed));

  json nodes = json::array(), roots = json::array();
  document["meshes"] = json::array();
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    const Mesh& mesh = scene.meshes[i];
    document["meshes"].push_back(
        {{"name", mesh.name}, {"primitives", {primitive(mesh, i, scene.materials.size(), buffer, file)}}});
    json node = {{"name", mesh.name}, {"mesh", i}};
    if (mesh.isGround) node["extras"] = {{"isGround", true}};
    roots.push_back(nodes.size());
    nodes.push_back(node);
  }
  if (scene.camera) {
    const Camera& c = *scene.camera;
    document["cameras"] = {{{"type", "perspective"},
                            {"perspective",
                             {{"yfov", c.yfovRadians},
                              {"znear", c.znear},
                              {"zfar", c.zfar},
                              {"aspectRatio", float(scene.width) / float(scene.height)}}}}};
    roots.push_back(nodes.size());
    nodes.push_back({{"name", "camera"}, {"camera", 0}, {"matrix", cameraMatrix(c)}});
  }
  document["nodes"] = nodes;
  document["scenes"] = {{{"nodes", roots}}};
  document["buffers"] = {{{"byteLength", buffer.bytes().size()}}};
  std::sort(extensionsUsed.begin(), extensionsUsed.end());
  extensionsUsed.erase(std::unique(extensionsUsed.begin(), extensionsUsed.end()), extensionsUsed.end());
  if (!extensionsUsed.empty()) document["extensionsUsed"] = extensionsUsed;

  std::string text = document.dump();
  text.resize((text.size() + 3) / 4 * 4, ' ');
  std::vector<char> bin(buffer.bytes().begin(), buffer.bytes().end());
  bin.resize((bin.size() + 3) / 4 * 4, 0);

  std::vector<char> glb;
  appendUint32(glb, kGlbMagic);
  appendUint32(glb, kGlbVersion);
  appendUint32(glb, std::uint32_t(12 + 8 + text.size() + 8 + bin.size()));
  appendUint32(glb, std::uint32_t(text.size()));
  appendUint32(glb, kChunkJson);
  glb.insert(glb.end(), text.begin(), text.end());
  appendUint32(glb, std::uint32_t(bin.size()));
  appendUint32(glb, kChunkBin);
  glb.insert(glb.end(), bin.begin(), bin.end());

  writeAtomically(file, [&](const fs::path& temporary) {
    std::ofstream stream(temporary, std::ios::binary);
    stream.write(glb.data(), std::streamsize(glb.size()));
    if (!stream.flush()) fail(file, "cannot write file");
  });
}

}  // namespace iblkit
