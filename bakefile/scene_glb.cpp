#include "bakefile/scene_glb.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
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
    const std::size_t offset = bytes_.size();  // a multiple of 4: elements are 4 bytes, images padded
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

  // Appends `data` (an encoded image) as a buffer view without a target (glTF 2.0 section
  // 3.6.1.2: image data is not vertex data), padded with zeros so the next view stays 4-byte
  // aligned; returns the view's index.
  int addBytes(const std::vector<std::uint8_t>& data) {
    const std::size_t offset = bytes_.size();
    bytes_.insert(bytes_.end(), data.begin(), data.end());
    bytes_.resize((bytes_.size() + 3) / 4 * 4, 0);
    json& views = document_["bufferViews"];
    views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", data.size()}});
    return int(views.size()) - 1;
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
  if (mesh.normals.size() != vertices || (!mesh.texcoords.empty() && mesh.texcoords.size() != vertices) ||
      (!mesh.texcoords1.empty() && mesh.texcoords1.size() != vertices) ||
      (!mesh.tangents.empty() && mesh.tangents.size() != vertices) ||
      (!mesh.colors.empty() && mesh.colors.size() != vertices))
    fail(file, what + ": normals, texture coordinates, tangents or colours do not match the " + std::to_string(vertices) +
                   " vertices");
  for (const std::uint32_t i : mesh.indices)
    if (i >= vertices) fail(file, what + ": index " + std::to_string(i) + " is out of range");
  requireFinite(file, &mesh.positions.front().x, 3 * vertices, what + " POSITION");
  requireFinite(file, &mesh.normals.front().x, 3 * vertices, what + " NORMAL");

  json attributes;
  attributes["POSITION"] = buffer.addPositions(mesh.positions);
  attributes["NORMAL"] = buffer.addAccessor(mesh.normals.data(), vertices, 3, kFloat, kArrayBuffer);
  if (!mesh.texcoords.empty()) {
    requireFinite(file, &mesh.texcoords.front().x, 2 * vertices, what + " TEXCOORD_0");
    attributes["TEXCOORD_0"] = buffer.addAccessor(mesh.texcoords.data(), vertices, 2, kFloat, kArrayBuffer);
  }
  if (!mesh.texcoords1.empty()) {
    requireFinite(file, &mesh.texcoords1.front().x, 2 * vertices, what + " TEXCOORD_1");
    attributes["TEXCOORD_1"] = buffer.addAccessor(mesh.texcoords1.data(), vertices, 2, kFloat, kArrayBuffer);
  }
  // TANGENT is VEC4 float with w = +1 or -1 (glTF 2.0 section 3.7.2.1), as Mesh::tangents holds it;
  // writing the generated ones too gives other viewers and our own reader the same frames.
  if (!mesh.tangents.empty()) {
    requireFinite(file, &mesh.tangents.front().x, 4 * vertices, what + " TANGENT");
    attributes["TANGENT"] = buffer.addAccessor(mesh.tangents.data(), vertices, 4, kFloat, kArrayBuffer);
  }
  // COLOR_0 as VEC4 float, linear (glTF 2.0 section 3.7.2.1), as Mesh::colors holds it.
  if (!mesh.colors.empty()) {
    requireFinite(file, &mesh.colors.front().x, 4 * vertices, what + " COLOR_0");
    attributes["COLOR_0"] = buffer.addAccessor(mesh.colors.data(), vertices, 4, kFloat, kArrayBuffer);
  }
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

// A material slot's textureInfo (glTF 2.0 section 5.22): the texture, its TEXCOORD set, and
// KHR_texture_transform when the transform is not the identity (the extension's texCoord is not
// written: TextureRef::texCoord already is the set the transform's uv come from).
json textureInfo(const TextureRef& ref, json& extensionsUsed) {
  json info = {{"index", ref.texture}};
  if (ref.texCoord != 0) info["texCoord"] = ref.texCoord;
  if (!ref.transform.identity()) {
    const TextureTransform& t = ref.transform;
    info["extensions"]["KHR_texture_transform"] = {
        {"offset", {t.offset.x, t.offset.y}}, {"rotation", t.rotation}, {"scale", {t.scale.x, t.scale.y}}};
    extensionsUsed.push_back("KHR_texture_transform");
  }
  return info;
}

json material(const Material& m, json& extensionsUsed) {
  json pbr = {{"baseColorFactor", {m.baseColor.r, m.baseColor.g, m.baseColor.b, m.alpha}},
              {"metallicFactor", m.metallic},
              {"roughnessFactor", m.roughness}};
  if (m.baseColorTexture.present()) pbr["baseColorTexture"] = textureInfo(m.baseColorTexture, extensionsUsed);
  if (m.metallicRoughnessTexture.present())
    pbr["metallicRoughnessTexture"] = textureInfo(m.metallicRoughnessTexture, extensionsUsed);
  json result = {{"name", m.name}, {"pbrMetallicRoughness", pbr}};
  if (m.normalTexture.present()) {
    result["normalTexture"] = textureInfo(m.normalTexture, extensionsUsed);
    result["normalTexture"]["scale"] = m.normalScale;
  }
  if (m.occlusionTexture.present()) {
    result["occlusionTexture"] = textureInfo(m.occlusionTexture, extensionsUsed);
    result["occlusionTexture"]["strength"] = m.occlusionStrength;
  }
  if (m.emissiveTexture.present()) result["emissiveTexture"] = textureInfo(m.emissiveTexture, extensionsUsed);
  if (m.alphaMode == AlphaMode::Mask) {
    result["alphaMode"] = "MASK";
    result["alphaCutoff"] = m.alphaCutoff;
  } else if (m.alphaMode == AlphaMode::Blend) {
    result["alphaMode"] = "BLEND";
  }
  if (m.doubleSided) result["doubleSided"] = true;
  result["extensions"]["KHR_materials_specular"] = {
      {"specularFactor", m.specular},
      {"specularColorFactor", {m.specularColor.r, m.specularColor.g, m.specularColor.b}}};
  extensionsUsed.push_back("KHR_materials_specular");
  if (m.ior != 1.5f) {
    result["extensions"]["KHR_materials_ior"] = {{"ior", m.ior}};
    extensionsUsed.push_back("KHR_materials_ior");
  }
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

// glTF sampler filter enums (glTF 2.0 section 5.26: the GL values).
int magFilterEnum(const TextureSampler& sampler) {
  return sampler.magFilter == TextureFilter::Nearest ? 9728 : 9729;  // NEAREST, LINEAR
}
int minFilterEnum(const TextureSampler& sampler) {
  const bool linear = sampler.minFilter == TextureFilter::Linear;
  if (!sampler.mipmaps) return linear ? 9729 : 9728;  // LINEAR, NEAREST
  // NEAREST_MIPMAP_NEAREST 9984, LINEAR_MIPMAP_NEAREST 9985, NEAREST_MIPMAP_LINEAR 9986,
  // LINEAR_MIPMAP_LINEAR 9987.
  return 9984 + (linear ? 1 : 0) + (sampler.mipFilter == TextureFilter::Linear ? 2 : 0);
}

// The scene's images, copied byte for byte into the BIN chunk (never decoded and re-encoded, so
// the bake loses nothing and other viewers read the very files the asset shipped), and its
// textures, each with its own sampler. A WebP image is read through EXT_texture_webp, which has
// no fallback here, so the extension is required (EXT_texture_webp, "glTF Schema Updates").
void writeTextures(const Scene& scene, BinaryBuffer& buffer, json& document, json& extensionsUsed,
                   json& extensionsRequired, const fs::path& file) {
  if (scene.textures.empty()) return;
  document["images"] = json::array();
  for (std::size_t i = 0; i < scene.images.size(); ++i) {
    const TextureImage& image = scene.images[i];
    const std::string what = "image " + std::to_string(i) + (image.name.empty() ? "" : " (" + image.name + ")");
    if (image.encoded.empty()) fail(file, what + " has no encoded bytes to copy");
    if (image.mimeType != "image/png" && image.mimeType != "image/jpeg" && image.mimeType != "image/webp")
      fail(file, what + ": mime type '" + image.mimeType + "' is not PNG, JPEG or WebP");
    json entry = {{"bufferView", buffer.addBytes(image.encoded)}, {"mimeType", image.mimeType}};
    if (!image.name.empty()) entry["name"] = image.name;
    document["images"].push_back(entry);
  }
  document["samplers"] = json::array();
  document["textures"] = json::array();
  for (std::size_t t = 0; t < scene.textures.size(); ++t) {
    const Texture& texture = scene.textures[t];
    if (texture.image < 0 || std::size_t(texture.image) >= scene.images.size())
      fail(file, "texture " + std::to_string(t) + ": image " + std::to_string(texture.image) + " does not exist");
    const TextureSampler& sampler = texture.sampler;
    document["samplers"].push_back({{"magFilter", magFilterEnum(sampler)},
                                    {"minFilter", minFilterEnum(sampler)},
                                    {"wrapS", int(sampler.wrapS)},
                                    {"wrapT", int(sampler.wrapT)}});
    json entry = {{"sampler", t}};
    if (!texture.name.empty()) entry["name"] = texture.name;
    if (scene.images[texture.image].mimeType == "image/webp") {
      entry["extensions"]["EXT_texture_webp"] = {{"source", texture.image}};
      extensionsUsed.push_back("EXT_texture_webp");
      extensionsRequired.push_back("EXT_texture_webp");
    } else {
      entry["source"] = texture.image;
    }
    document["textures"].push_back(entry);
  }
}

// Every texture slot of every material refers to a texture the scene has.
void requireTextures(const Scene& scene, const fs::path& file) {
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    const std::pair<const char*, const TextureRef*> slots[] = {
        {"baseColorTexture", &m.baseColorTexture}, {"metallicRoughnessTexture", &m.metallicRoughnessTexture},
        {"normalTexture", &m.normalTexture},       {"occlusionTexture", &m.occlusionTexture},
        {"emissiveTexture", &m.emissiveTexture}};
    for (const auto& [slot, ref] : slots) {
      if (!ref->present()) continue;
      const std::string where = "material " + std::to_string(i) + " (" + m.name + ") " + slot;
      if (std::size_t(ref->texture) >= scene.textures.size())
        fail(file, where + ": texture " + std::to_string(ref->texture) + " does not exist");
      if (ref->texCoord != 0 && ref->texCoord != 1)
        fail(file, where + ": texCoord " + std::to_string(ref->texCoord) + " is not 0 or 1");
    }
  }
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
  json extensionsUsed = json::array(), extensionsRequired = json::array();
  requireTextures(scene, file);
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
  // The images go after the vertex data: one BIN chunk holds both, each view 4-byte aligned.
  writeTextures(scene, buffer, document, extensionsUsed, extensionsRequired, file);
  document["nodes"] = nodes;
  document["scenes"] = {{{"nodes", roots}}};
  document["buffers"] = {{{"byteLength", buffer.bytes().size()}}};
  std::sort(extensionsUsed.begin(), extensionsUsed.end());
  extensionsUsed.erase(std::unique(extensionsUsed.begin(), extensionsUsed.end()), extensionsUsed.end());
  if (!extensionsUsed.empty()) document["extensionsUsed"] = extensionsUsed;
  std::sort(extensionsRequired.begin(), extensionsRequired.end());
  extensionsRequired.erase(std::unique(extensionsRequired.begin(), extensionsRequired.end()),
                           extensionsRequired.end());
  if (!extensionsRequired.empty()) document["extensionsRequired"] = extensionsRequired;

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
