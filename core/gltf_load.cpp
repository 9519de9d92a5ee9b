#include "core/gltf_load.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <map>
#include <numeric>
#include <span>
#include <string>
#include <tuple>
#include <utility>

#include <tbb/parallel_for.h>

#include <exception>

#include "core/error.h"
#include "core/gltf_model.h"
#include "core/static_pose.h"
#include "core/texture_image.h"

namespace iblkit {

namespace fs = std::filesystem;

namespace {

std::string coordinateLimitText() {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", double(kMaxSceneCoordinate));
  return text;
}

std::string primitiveName(int mesh, int primitive) {
  return "mesh " + std::to_string(mesh) + " primitive " + std::to_string(primitive);
}

// ---------------------------------------------------------------------------------------------
// Materials

// A [0, 1] factor; values outside are clamped with a warning rather than silently.
float unitFactor(double value, const std::string& what, const fs::path& file) {
  if (value >= 0.0 && value <= 1.0) return float(value);
  warn(file, what + " " + std::to_string(value) + " clamped to [0, 1]");
  return float(std::clamp(value, 0.0, 1.0));
}

glm::vec3 colorFactor(const std::vector<double>& values, const std::string& what, const fs::path& file) {
  if (values.size() < 3) fail(file, what + " must have at least 3 numbers");
  return glm::vec3(unitFactor(values[0], what, file), unitFactor(values[1], what, file),
                   unitFactor(values[2], what, file));
}

// A number inside an extension object, or `fallback` when absent.
double extensionNumber(const tinygltf::Value& extension, const char* key, double fallback,
                       const std::string& what, const fs::path& file) {
  if (!extension.Has(key)) return fallback;
  const tinygltf::Value& value = extension.Get(key);
  if (!value.IsNumber()) fail(file, what + "." + key + " must be a number");
  return value.GetNumberAsDouble();
}

std::vector<double> extensionNumbers(const tinygltf::Value& extension, const char* key,
                                     std::vector<double> fallback, const std::string& what,
                                     const fs::path& file) {
  if (!extension.Has(key)) return fallback;
  const tinygltf::Value& value = extension.Get(key);
  std::vector<double> numbers;
  for (int i = 0; value.IsArray() && i < int(value.ArrayLen()); ++i) {
    if (!value.Get(i).IsNumber()) break;
    numbers.push_back(value.Get(i).GetNumberAsDouble());
  }
  if (!value.IsArray() || numbers.size() != value.ArrayLen())
    fail(file, what + "." + key + " must be an array of numbers");
  return numbers;
}

glm::vec2 extensionVec2(const tinygltf::Value& extension, const char* key, glm::vec2 fallback,
                        const std::string& what, const fs::path& file) {
  const std::vector<double> v = extensionNumbers(extension, key, {fallback.x, fallback.y}, what, file);
  if (v.size() != 2 || !std::isfinite(v[0]) || !std::isfinite(v[1]))
    fail(file, what + "." + key + " must be 2 finite numbers");
  if (std::abs(v[0]) > kMaxTextureTransformValue || std::abs(v[1]) > kMaxTextureTransformValue)
    fail(file, what + "." + key + " must lie within +-1e6");
  return glm::vec2(float(v[0]), float(v[1]));
}

// A texCoord set: TEXCOORD_0 or TEXCOORD_1, the two sets glTF 2.0 section 3.7.2.1 requires
// clients to support; a file naming another set is refused rather than drawn with the wrong uvs.
int texCoordSet(long long texCoord, const std::string& what, const fs::path& file) {
  if (texCoord != 0 && texCoord != 1)
    fail(file, what + ": texCoord " + std::to_string(texCoord) + " is not supported (TEXCOORD_0 and TEXCOORD_1 only)");
  return int(texCoord);
}

// A material's textureInfo (glTF 2.0 section 5.22) with its KHR_texture_transform. The texture
// index stays the file's; Loader::loadTextures renumbers it.
template <typename Info>
TextureRef textureRef(const Info& info, const std::string& what, std::size_t textureCount, const fs::path& file) {
  TextureRef ref;
  if (info.index < 0) return ref;
  if (std::size_t(info.index) >= textureCount)
    fail(file, what + ": texture " + std::to_string(info.index) + " does not exist");
  ref.texture = info.index;
  ref.texCoord = texCoordSet(info.texCoord, what, file);
  const auto found = info.extensions.find("KHR_texture_transform");
  if (found != info.extensions.end()) {
    const tinygltf::Value& t = found->second;
    const std::string ext = what + " KHR_texture_transform";
    if (!t.IsObject()) fail(file, ext + " must be an object");
    ref.transform.offset = extensionVec2(t, "offset", glm::vec2(0.0f), ext, file);
    ref.transform.scale = extensionVec2(t, "scale", glm::vec2(1.0f), ext, file);
    const double rotation = extensionNumber(t, "rotation", 0.0, ext, file);
    if (!std::isfinite(rotation) || std::abs(rotation) > kMaxTextureTransformValue)
      fail(file, ext + ".rotation must be a finite number within +-1e6");
    ref.transform.rotation = float(rotation);
    // The extension's texCoord overrides the textureInfo's (KHR_texture_transform README).
    if (t.Has("texCoord")) {
      if (!t.Get("texCoord").IsInt()) fail(file, ext + ".texCoord must be an integer");
      ref.texCoord = texCoordSet(t.Get("texCoord").GetNumberAsInt(), ext, file);
    }
  }
  return ref;
}

// A textureInfo inside an extension's JSON (tinygltf leaves extensions as Values), for textureRef.
struct ValueTextureInfo {
  int index = -1;
  long long texCoord = 0;
  tinygltf::ExtensionMap extensions;
};

ValueTextureInfo textureInfoFromValue(const tinygltf::Value& value, const std::string& what, const fs::path& file) {
  ValueTextureInfo info;
  if (!value.IsObject()) fail(file, what + " must be an object");
  if (!value.Get("index").IsInt()) fail(file, what + ".index must be an integer");
  info.index = value.Get("index").GetNumberAsInt();
  if (info.index < 0) fail(file, what + ".index must be >= 0");
  if (value.Has("texCoord")) {
    if (!value.Get("texCoord").IsInt()) fail(file, what + ".texCoord must be an integer");
    info.texCoord = value.Get("texCoord").GetNumberAsInt();
  }
  const tinygltf::Value& extensions = value.Get("extensions");
  if (extensions.IsObject())
    for (const std::string& key : extensions.Keys()) info.extensions[key] = extensions.Get(key);
  return info;
}

// KHR_materials_pbrSpecularGlossiness (archived, common in older assets), converted to the
// metallic-roughness model with KHR_materials_specular: base colour and alpha = diffuse (factor
// and texture), metallic 0, roughness = 1 - glossiness, dielectric F0 = the specular factor
// (specularColor = specular / 0.04, specular 1: min(0.04 specularColor, 1) = specular, the F0 the
// extension gives). Without it such a material would be glTF's default, a rough white metal.
// specularGlossinessTexture is not read (per-texel F0 and roughness have no slot): its factors are
// used, and the caller warns.
void convertSpecularGlossiness(const tinygltf::Value& ext, const std::string& what, std::size_t textureCount,
                               const fs::path& file, Material& material) {
  if (!ext.IsObject()) fail(file, what + " must be an object");
  const std::vector<double> diffuse = extensionNumbers(ext, "diffuseFactor", {1.0, 1.0, 1.0, 1.0}, what, file);
  const std::vector<double> specular = extensionNumbers(ext, "specularFactor", {1.0, 1.0, 1.0}, what, file);
  const double glossiness = extensionNumber(ext, "glossinessFactor", 1.0, what, file);
  const auto unit = [](double x) { return x >= 0.0 && x <= 1.0; };
  if (diffuse.size() != 4 || !std::all_of(diffuse.begin(), diffuse.end(), unit))
    fail(file, what + ".diffuseFactor must be 4 numbers in [0, 1]");
  if (specular.size() != 3 || !std::all_of(specular.begin(), specular.end(), unit))
    fail(file, what + ".specularFactor must be 3 numbers in [0, 1]");
  if (!unit(glossiness)) fail(file, what + ".glossinessFactor must be in [0, 1]");
  material.baseColor = glm::vec3(float(diffuse[0]), float(diffuse[1]), float(diffuse[2]));
  material.alpha = float(diffuse[3]);
  material.metallic = 0.0f;
  material.roughness = float(1.0 - glossiness);
  material.specular = 1.0f;
  material.specularColor = glm::vec3(float(specular[0]), float(specular[1]), float(specular[2])) / 0.04f;
  material.metallicRoughnessTexture = TextureRef{};
  material.baseColorTexture = ext.Has("diffuseTexture")
                                  ? textureRef(textureInfoFromValue(ext.Get("diffuseTexture"), what + " diffuseTexture", file),
                                               what + " diffuseTexture", textureCount, file)
                                  : TextureRef{};
}

AlphaMode alphaMode(const std::string& mode, const std::string& what, const fs::path& file) {
  if (mode == "OPAQUE" || mode.empty()) return AlphaMode::Opaque;
  if (mode == "MASK") return AlphaMode::Mask;
  if (mode == "BLEND") return AlphaMode::Blend;
  fail(file, what + ": unknown alphaMode '" + printableExcerpt(mode) + "' (expected OPAQUE, MASK or BLEND)");
}

Material convertMaterial(const tinygltf::Material& source, int index, std::size_t textureCount,
                         const fs::path& file) {
  const std::string what = "material " + std::to_string(index);
  Material material;
  material.name = source.name;
  const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
  material.baseColor = colorFactor(pbr.baseColorFactor, what + " baseColorFactor", file);
  if (pbr.baseColorFactor.size() >= 4)
    material.alpha = unitFactor(pbr.baseColorFactor[3], what + " baseColorFactor", file);
  material.metallic = unitFactor(pbr.metallicFactor, what + " metallicFactor", file);
  material.roughness = unitFactor(pbr.roughnessFactor, what + " roughnessFactor", file);
  // emissiveFactor is [0, 1] per the schema; KHR_materials_emissive_strength scales it beyond.
  material.emissive = colorFactor(source.emissiveFactor, what + " emissiveFactor", file);

  const auto strength = source.extensions.find("KHR_materials_emissive_strength");
  if (strength != source.extensions.end()) {
    const std::string ext = what + " KHR_materials_emissive_strength";
    const double s = extensionNumber(strength->second, "emissiveStrength", 1.0, ext, file);
    if (!(s >= 0.0)) fail(file, ext + ".emissiveStrength must be >= 0");
    material.emissive *= float(s);
  }
  const auto ior = source.extensions.find("KHR_materials_ior");
  if (ior != source.extensions.end()) {
    const std::string ext = what + " KHR_materials_ior";
    const double value = extensionNumber(ior->second, "ior", 1.5, ext, file);
    // The schema allows 0 (F0 1) and 1 and above; beyond 1e3 the F0 is 1 to float precision.
    if (!(value == 0.0 || (value >= 1.0 && value <= 1e3))) fail(file, ext + ".ior must be 0 or in [1, 1000]");
    material.ior = float(value);
  }
  const auto specular = source.extensions.find("KHR_materials_specular");
  if (specular != source.extensions.end()) {
    const std::string ext = what + " KHR_materials_specular";
    material.specular = unitFactor(extensionNumber(specular->second, "specularFactor", 1.0, ext, file),
                                   ext + " specularFactor", file);
    const std::vector<double> color =
        extensionNumbers(specular->second, "specularColorFactor", {1.0, 1.0, 1.0}, ext, file);
    // specularColorFactor may exceed 1 (the extension clamps F0 after multiplying), so only
    // negative values are rejected.
    if (color.size() != 3 || *std::min_element(color.begin(), color.end()) < 0.0)
      fail(file, ext + ".specularColorFactor must be 3 numbers >= 0");
    material.specularColor = glm::vec3(float(color[0]), float(color[1]), float(color[2]));
  }

  material.baseColorTexture = textureRef(pbr.baseColorTexture, what + " baseColorTexture", textureCount, file);
  material.metallicRoughnessTexture =
      textureRef(pbr.metallicRoughnessTexture, what + " metallicRoughnessTexture", textureCount, file);
  material.normalTexture = textureRef(source.normalTexture, what + " normalTexture", textureCount, file);
  material.occlusionTexture = textureRef(source.occlusionTexture, what + " occlusionTexture", textureCount, file);
  material.emissiveTexture = textureRef(source.emissiveTexture, what + " emissiveTexture", textureCount, file);
  if (!std::isfinite(source.normalTexture.scale) || std::abs(source.normalTexture.scale) > kMaxTextureTransformValue)
    fail(file, what + " normalTexture.scale must be a finite number within +-1e6");
  material.normalScale = float(source.normalTexture.scale);
  material.occlusionStrength = unitFactor(source.occlusionTexture.strength, what + " occlusionTexture.strength", file);

  const auto specularGlossiness = source.extensions.find("KHR_materials_pbrSpecularGlossiness");
  if (specularGlossiness != source.extensions.end()) {
    const std::string ext = what + " KHR_materials_pbrSpecularGlossiness";
    convertSpecularGlossiness(specularGlossiness->second, ext, textureCount, file, material);
    if (specularGlossiness->second.Has("specularGlossinessTexture"))
      warn(file, ext + ": specularGlossinessTexture is not read (its specular and glossiness factors are)");
  }

  material.alphaMode = alphaMode(source.alphaMode, what, file);
  if (!(source.alphaCutoff >= 0.0) || !std::isfinite(source.alphaCutoff))
    fail(file, what + ": alphaCutoff must be a number >= 0");
  material.alphaCutoff = float(source.alphaCutoff);
  material.doubleSided = source.doubleSided;
  return material;
}

// Every TextureRef of a material, for renumbering and for finding the textures in use.
std::array<TextureRef*, 5> textureRefs(Material& m) {
  return {&m.baseColorTexture, &m.metallicRoughnessTexture, &m.normalTexture, &m.occlusionTexture,
          &m.emissiveTexture};
}

// ---------------------------------------------------------------------------------------------
// Textures, samplers and images

TextureWrap wrapMode(int value, const std::string& what, const fs::path& file) {
  switch (value) {
    case TINYGLTF_TEXTURE_WRAP_REPEAT: return TextureWrap::Repeat;
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::ClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::MirroredRepeat;
    default: fail(file, what + ": unknown wrap mode " + std::to_string(value));
  }
}

// glTF 2.0 section 5.26 with the GL enums it uses; absent filters get texture.h's defaults
// (LINEAR magnification, LINEAR_MIPMAP_LINEAR minification).
TextureSampler convertSampler(const tinygltf::Sampler& source, int index, const fs::path& file) {
  const std::string what = "sampler " + std::to_string(index);
  TextureSampler sampler;
  sampler.wrapS = wrapMode(source.wrapS, what + " wrapS", file);
  sampler.wrapT = wrapMode(source.wrapT, what + " wrapT", file);
  switch (source.magFilter) {
    case -1: break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST: sampler.magFilter = TextureFilter::Nearest; break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR: sampler.magFilter = TextureFilter::Linear; break;
    default: fail(file, what + ": unknown magFilter " + std::to_string(source.magFilter));
  }
  const auto minification = [&](TextureFilter filter, bool mipmaps, TextureFilter mipFilter) {
    sampler.minFilter = filter;
    sampler.mipmaps = mipmaps;
    sampler.mipFilter = mipFilter;
  };
  constexpr TextureFilter N = TextureFilter::Nearest, L = TextureFilter::Linear;
  switch (source.minFilter) {
    case -1: break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST: minification(N, false, L); break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR: minification(L, false, L); break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST: minification(N, true, N); break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST: minification(L, true, N); break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR: minification(N, true, L); break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR: minification(L, true, L); break;
    default: fail(file, what + ": unknown minFilter " + std::to_string(source.minFilter));
  }
  return sampler;
}

// An image index inside a texture extension object ("source"), or -1 when there is none.
int extensionSource(const tinygltf::Texture& texture, const char* extension, const std::string& what,
                    const fs::path& file) {
  const auto found = texture.extensions.find(extension);
  if (found == texture.extensions.end()) return -1;
  const tinygltf::Value& source = found->second.Get("source");
  if (!source.IsInt() || source.GetNumberAsInt() < 0)
    fail(file, what + " " + extension + ".source must be an image index");
  return source.GetNumberAsInt();
}

// Where an image came from, for messages: its uri (up to a data URI's comma), or its name.
std::string imageLabel(const tinygltf::Image& image) {
  if (!image.uri.empty()) {
    const std::size_t comma = image.uri.rfind("data:", 0) == 0 ? image.uri.find(',') : std::string::npos;
    return printableExcerpt(comma == std::string::npos ? image.uri : image.uri.substr(0, comma + 1), 80);
  }
  if (image.as_is) return "data:" + image.mimeType + ";base64,";
  return printableExcerpt(image.name, 80);
}

// ---------------------------------------------------------------------------------------------
// Primitives

void requireFinite(std::span<const float> values, const std::string& what, const fs::path& file) {
  for (float v : values)
    if (!std::isfinite(v)) fail(file, what);
}

// Triangle lists from the three triangle modes, glTF 2.0 section 3.7.2.1.
std::vector<std::uint32_t> triangleList(std::vector<std::uint32_t> v, int mode, const std::string& where,
                                        const fs::path& file) {
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    if (v.size() % 3 != 0)
      fail(file, where + ": " + std::to_string(v.size()) + " indices do not make whole triangles");
    return v;
  }
  std::vector<std::uint32_t> triangles;
  for (std::size_t i = 0; i + 2 < v.size(); ++i) {
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP)
      triangles.insert(triangles.end(), {v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]});
    else
      triangles.insert(triangles.end(), {v[i + 1], v[i + 2], v[0]});
  }
  return triangles;
}

template <typename Vec>
std::vector<Vec> toVectors(const std::vector<float>& values) {
  std::vector<Vec> result(values.size() / Vec::length());
  if (!result.empty()) std::memcpy(result.data(), values.data(), result.size() * sizeof(Vec));
  return result;
}

// The material extensions that change how a material looks and that iblkit reads (the rest are
// skipped, each named once in a warning by warnUnrenderedMaterialExtensions).
bool renderedMaterialExtension(const std::string& name) {
  return name == "KHR_materials_emissive_strength" || name == "KHR_materials_specular" || name == "KHR_materials_ior" ||
         name == "KHR_materials_pbrSpecularGlossiness";
}

// One warning per skipped material extension, with the materials that use it: glTF lets a
// viewer ignore an extension a file does not require, but a user whose glass renders opaque
// (KHR_materials_transmission) or whose old asset's colours are the defaults
// (KHR_materials_pbrSpecularGlossiness) should be told why.
void warnUnrenderedMaterialExtensions(const tinygltf::Model& model, const fs::path& file) {
  std::map<std::string, std::vector<std::size_t>> users;
  for (std::size_t i = 0; i < model.materials.size(); ++i)
    for (const auto& [name, value] : model.materials[i].extensions)
      if (!renderedMaterialExtension(name)) users[name].push_back(i);
  for (const auto& [name, materials] : users) {
    std::string list;
    for (std::size_t k = 0; k < materials.size() && k < 8; ++k) list += (k ? ", " : "") + std::to_string(materials[k]);
    if (materials.size() > 8) list += ", ...";
    warn(file, printableExcerpt(name) + " is not rendered: material" + (materials.size() > 1 ? "s " : " ") + list +
                   (materials.size() > 1 ? " are" : " is") + " drawn without it");
  }
}

class Loader {
 public:
  Loader(const tinygltf::Model& model, const fs::path& file) : model_(model), file_(file) {}

  GltfContents load() {
    for (std::size_t i = 0; i < model_.materials.size(); ++i)
      contents_.materials.push_back(convertMaterial(model_.materials[i], int(i), model_.textures.size(), file_));
    warnUnrenderedMaterialExtensions(model_, file_);
    if (!model_.lights.empty())
      warn(file_, "KHR_lights_punctual: " + std::to_string(model_.lights.size()) +
                      " light(s) not rendered (iblkit lights a scene with its environment map only)");
    loadTextures();

    localMeshes_.resize(model_.meshes.size());
    traverse(rootNodes());
    if (contents_.meshes.empty()) fail(file_, "no triangle meshes");
    if (cameraZfarMissing_) {
      Bounds bounds;
      for (const Mesh& mesh : contents_.meshes) bounds.extend(mesh.bounds());
      contents_.camera->zfar = clipPlanesFor(contents_.camera->position, bounds).zfar;
    }
    return std::move(contents_);
  }

 private:
  // A primitive in its mesh's local space, with what deforms it (static_pose.h).
  struct LocalPrimitive {
    Mesh mesh;
    std::vector<VertexInfluences> influences;  // JOINTS_n / WEIGHTS_n; empty without them
    std::uint32_t largestJoint = 0;
    std::vector<MorphTarget> targets;
  };

  std::vector<int> rootNodes() const {
    if (model_.defaultScene >= int(model_.scenes.size()))
      fail(file_, "default scene " + std::to_string(model_.defaultScene) + " does not exist");
    if (model_.defaultScene >= 0) return model_.scenes[model_.defaultScene].nodes;
    if (!model_.scenes.empty()) return model_.scenes[0].nodes;
    std::vector<bool> isChild(model_.nodes.size(), false);
    for (const tinygltf::Node& node : model_.nodes)
      for (int child : node.children)
        if (child >= 0 && std::size_t(child) < isChild.size()) isChild[child] = true;
    std::vector<int> roots;
    for (std::size_t i = 0; i < isChild.size(); ++i)
      if (!isChild[i]) roots.push_back(int(i));
    return roots;
  }

  glm::mat4 localTransform(const tinygltf::Node& node, int index) const {
    const std::string what = "node " + std::to_string(index);
    if (!node.matrix.empty()) {
      if (node.matrix.size() != 16) fail(file_, what + ": matrix must have 16 numbers");
      glm::dmat4 m;
      std::copy(node.matrix.begin(), node.matrix.end(), glm::value_ptr(m));  // column-major, as glTF
      return glm::mat4(m);
    }
    glm::mat4 m(1.0f);
    if (!node.translation.empty()) {
      if (node.translation.size() != 3) fail(file_, what + ": translation must have 3 numbers");
      m = glm::translate(m, glm::vec3(node.translation[0], node.translation[1], node.translation[2]));
    }
    if (!node.rotation.empty()) {
      if (node.rotation.size() != 4) fail(file_, what + ": rotation must have 4 numbers");
      // glTF stores x, y, z, w; glm's constructor takes w first.
      const glm::quat q(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]),
                        float(node.rotation[2]));
      if (!(glm::length(q) > 0.0f)) fail(file_, what + ": rotation is not a valid quaternion");
      m *= glm::mat4_cast(glm::normalize(q));
    }
    if (!node.scale.empty()) {
      if (node.scale.size() != 3) fail(file_, what + ": scale must have 3 numbers");
      m = glm::scale(m, glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
    }
    return m;
  }

  // Depth-first, pre-order, children in their listed order; iterative so deep hierarchies
  // cannot overflow the call stack.
  void traverse(const std::vector<int>& roots) {
    std::vector<bool> visited(model_.nodes.size(), false);
    std::vector<std::pair<int, glm::mat4>> stack;
    for (auto root = roots.rbegin(); root != roots.rend(); ++root) stack.emplace_back(*root, glm::mat4(1.0f));
    while (!stack.empty()) {
      const auto [index, parent] = stack.back();
      stack.pop_back();
      if (index < 0 || std::size_t(index) >= model_.nodes.size())
        fail(file_, "node " + std::to_string(index) + " does not exist");
      if (visited[index])
        fail(file_, "node " + std::to_string(index) +
                        " is reached twice in the scene graph (a cycle or two parents)");
      visited[index] = true;
      const tinygltf::Node& node = model_.nodes[index];
      const glm::mat4 world = parent * localTransform(node, index);
      if (node.mesh >= 0) {
        const std::vector<glm::mat4> instances = instanceTransforms(node, index);
        countVertices(node.mesh, index, std::max<std::size_t>(instances.size(), 1));
        if (instances.empty()) instantiate(node.mesh, index, world);
        for (const glm::mat4& instance : instances) instantiate(node.mesh, index, world * instance);
      }
      if (node.camera >= 0 && !contents_.camera) readCamera(node.camera, index, world);
      for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
        stack.emplace_back(*child, world);
    }
  }

  // EXT_mesh_gpu_instancing: the node's mesh drawn once per instance, each placed by its
  // TRANSLATION, ROTATION and SCALE (any of them; the others identity) in the node's space. Empty
  // for a node without the extension. ROTATION is float or normalised byte or short (the
  // extension's types, as KHR_mesh_quantization's); at most kMaxInstances per node.
  static constexpr std::size_t kMaxInstances = 1u << 20;
  // The most vertices a file may expand to, instances and reused meshes included, and the most
  // morph target elements (targets x vertices) a primitive may hold: a small file can otherwise
  // ask for any amount of memory (a mesh instanced a million times, thousands of targets, a sparse
  // accessor without a view). 2^26 vertices are about 4 GiB of meshes.
  static constexpr std::size_t kMaxSceneVertices = std::size_t(1) << 26;
  static constexpr std::size_t kMaxMorphElements = std::size_t(1) << 26;
  std::vector<glm::mat4> instanceTransforms(const tinygltf::Node& node, int index) const {
    const auto found = node.extensions.find("EXT_mesh_gpu_instancing");
    if (found == node.extensions.end()) return {};
    const std::string what = "node " + std::to_string(index) + " EXT_mesh_gpu_instancing";
    const tinygltf::Value& attributes = found->second.Get("attributes");
    if (!attributes.IsObject()) fail(file_, what + " needs an attributes object");
    std::vector<float> translations, rotations, scales;
    std::size_t count = 0;
    bool any = false;
    const std::array<std::tuple<const char*, int, std::vector<float>*>, 3> streams = {
        {{"TRANSLATION", 3, &translations}, {"ROTATION", 4, &rotations}, {"SCALE", 3, &scales}}};
    for (const auto& [semantic, components, values] : streams) {
      const tinygltf::Value& accessor = attributes.Get(semantic);
      if (!accessor.IsInt()) continue;
      *values = gltf::readFloats(model_, accessor.GetNumberAsInt(), components, semantic, file_);
      requireFinite(*values, what + ": non-finite " + semantic + " value", file_);
      const std::size_t n = values->size() / std::size_t(components);
      if (any && n != count) fail(file_, what + ": TRANSLATION, ROTATION and SCALE have different counts");
      count = n;
      any = true;
    }
    if (!any) fail(file_, what + " has no TRANSLATION, ROTATION or SCALE accessor");
    if (count > kMaxInstances)
      fail(file_, what + ": " + std::to_string(count) + " instances, beyond the limit of " + std::to_string(kMaxInstances));
    std::vector<glm::mat4> transforms(count, glm::mat4(1.0f));
    for (std::size_t i = 0; i < count; ++i) {
      glm::mat4& m = transforms[i];
      if (!translations.empty()) m = glm::translate(m, glm::make_vec3(&translations[3 * i]));
      if (!rotations.empty()) {
        const glm::quat q(rotations[4 * i + 3], rotations[4 * i], rotations[4 * i + 1], rotations[4 * i + 2]);
        if (!(glm::length(q) > 0.0f)) fail(file_, what + ": instance " + std::to_string(i) + " has a zero rotation");
        m *= glm::mat4_cast(glm::normalize(q));
      }
      if (!scales.empty()) m = glm::scale(m, glm::make_vec3(&scales[3 * i]));
    }
    return transforms;
  }

  // The baker marks the ground of a .json scene with node extras {"isGround": true}
  // (bakefile/scene_glb.h), so a baked scene is framed without it, as the original scene was.
  static bool isGroundNode(const tinygltf::Node& node) {
    const tinygltf::Value& flag = node.extras.Get("isGround");
    return flag.IsBool() && flag.Get<bool>();
  }

  // Mesh `meshIndex`'s primitives in local space, read once.
  const std::vector<std::optional<LocalPrimitive>>& localPrimitives(int meshIndex, int nodeIndex) {
    if (std::size_t(meshIndex) >= model_.meshes.size())
      fail(file_,
           "node " + std::to_string(nodeIndex) + ": mesh " + std::to_string(meshIndex) + " does not exist");
    std::vector<std::optional<LocalPrimitive>>& locals = localMeshes_[meshIndex];
    if (locals.empty()) {
      const tinygltf::Mesh& mesh = model_.meshes[meshIndex];
      for (std::size_t p = 0; p < mesh.primitives.size(); ++p)
        locals.push_back(readPrimitive(meshIndex, int(p)));
    }
    return locals;
  }

  // Adds `copies` instances of mesh `meshIndex` to the scene's vertex count, before they are made.
  void countVertices(int meshIndex, int nodeIndex, std::size_t copies) {
    std::size_t vertices = 0;
    for (const std::optional<LocalPrimitive>& local : localPrimitives(meshIndex, nodeIndex))
      if (local) vertices += local->mesh.vertexCount();
    if (vertices > 0 && copies > (kMaxSceneVertices - sceneVertices_) / vertices)
      fail(file_, "node " + std::to_string(nodeIndex) + ": the scene's meshes exceed " +
                      std::to_string(kMaxSceneVertices) + " vertices (instances and reused meshes included)");
    sceneVertices_ += copies * vertices;
  }

  void instantiate(int meshIndex, int nodeIndex, const glm::mat4& world) {
    const std::vector<std::optional<LocalPrimitive>>& locals = localPrimitives(meshIndex, nodeIndex);
    const tinygltf::Node& node = model_.nodes[nodeIndex];
    // Morph targets at their default weights: the node's, else the mesh's (section 3.7.2.2).
    const std::vector<double>& defaultWeights = node.weights.empty() ? model_.meshes[meshIndex].weights : node.weights;
    std::vector<float> weights;
    for (const double w : defaultWeights) {
      if (!std::isfinite(w))
        fail(file_, "node " + std::to_string(nodeIndex) + " (mesh " + std::to_string(meshIndex) +
                        "): morph target weights must be finite");
      weights.push_back(float(w));
    }
    for (const std::optional<LocalPrimitive>& local : locals) {
      if (!local) continue;
      Mesh mesh = local->mesh;
      mesh.source.node = nodeIndex;
      mesh.isGround = isGroundNode(node);
      const std::string where = primitiveName(mesh.source.mesh, mesh.source.primitive);
      applyMorphTargets(mesh, local->targets, weights);
      // A skinned mesh's own node transform is not applied: its joints place it (section 3.7.3).
      if (node.skin >= 0 && !local->influences.empty()) {
        const std::vector<glm::mat4>& joints = jointMatrices(node.skin, nodeIndex);
        if (local->largestJoint >= joints.size())
          fail(file_, where + ": JOINTS refer to joint " + std::to_string(local->largestJoint) + " of skin " +
                          std::to_string(node.skin) + ", which has " + std::to_string(joints.size()));
        transformMeshPerVertex(mesh, skinningMatrices(local->influences, joints));
      } else {
        transformMesh(mesh, world);
      }
      if (const long long v = firstVertexOutOfRange(mesh); v >= 0) {
        const glm::vec3& p = mesh.positions[std::size_t(v)];
        const bool finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
        fail(file_, where + ": " +
                        (finite ? "vertex position beyond " + coordinateLimitText() : "non-finite vertex position") +
                        " (vertex " + std::to_string(v) + " in node " + std::to_string(nodeIndex) +
                        ", after its transforms: scale, translation or matrix)");
      }
      if (const std::size_t dropped = removeZeroAreaTriangles(mesh))
        warn(file_, where + ": dropped " + std::to_string(dropped) + " zero-area triangles");
      if (mesh.indices.empty()) continue;
      const bool hadNormals = !mesh.normals.empty();
      if (const std::size_t repaired = repairNormals(mesh)) {
        warn(file_, hadNormals ? where + ": replaced " + std::to_string(repaired) +
                                     " zero-length or NaN normals with angle-weighted normals"
                               : where + " has no normals; generated angle-weighted normals");
      }
      contents_.meshes.push_back(std::move(mesh));
    }
  }

  // The world transform of node `index` through its parents (joints need not be in the scene's
  // tree); a parent chain longer than the node count is a cycle.
  glm::mat4 globalTransform(int index) {
    if (parents_.empty()) {
      parents_.assign(model_.nodes.size(), -1);
      for (std::size_t n = 0; n < model_.nodes.size(); ++n)
        for (const int child : model_.nodes[n].children)
          if (child >= 0 && std::size_t(child) < parents_.size() && parents_[std::size_t(child)] < 0)
            parents_[std::size_t(child)] = int(n);
    }
    glm::mat4 m(1.0f);
    std::size_t steps = 0;
    for (int n = index; n >= 0; n = parents_[std::size_t(n)]) {
      if (++steps > model_.nodes.size()) fail(file_, "node " + std::to_string(index) + ": its parents form a cycle");
      m = localTransform(model_.nodes[std::size_t(n)], n) * m;
    }
    return m;
  }

  // Skin `skin`'s joint matrices: each joint's world transform times its inverse bind matrix
  // (identity when the skin has none), computed once.
  const std::vector<glm::mat4>& jointMatrices(int skin, int nodeIndex) {
    if (std::size_t(skin) >= model_.skins.size())
      fail(file_, "node " + std::to_string(nodeIndex) + ": skin " + std::to_string(skin) + " does not exist");
    if (jointMatrices_.empty()) jointMatrices_.resize(model_.skins.size());
    std::optional<std::vector<glm::mat4>>& cached = jointMatrices_[std::size_t(skin)];
    if (cached) return *cached;
    const tinygltf::Skin& source = model_.skins[std::size_t(skin)];
    const std::string what = "skin " + std::to_string(skin);
    std::vector<glm::mat4> inverseBind(source.joints.size(), glm::mat4(1.0f));
    if (source.inverseBindMatrices >= 0) {
      const std::vector<glm::mat4> read =
          gltf::readMatrices(model_, source.inverseBindMatrices, "inverseBindMatrices", file_);
      if (read.size() < source.joints.size())
        fail(file_, what + ": " + std::to_string(read.size()) + " inverse bind matrices for " +
                        std::to_string(source.joints.size()) + " joints");
      for (const glm::mat4& m : read)
        requireFinite(std::span<const float>(glm::value_ptr(m), 16), what + ": non-finite inverse bind matrix", file_);
      std::copy_n(read.begin(), source.joints.size(), inverseBind.begin());
    }
    std::vector<glm::mat4> joints;
    for (std::size_t j = 0; j < source.joints.size(); ++j) {
      const int joint = source.joints[j];
      if (joint < 0 || std::size_t(joint) >= model_.nodes.size())
        fail(file_, what + ": joint node " + std::to_string(joint) + " does not exist");
      joints.push_back(globalTransform(joint) * inverseBind[j]);
    }
    cached = std::move(joints);
    return *cached;
  }

  // JOINTS_n and WEIGHTS_n (n = 0, 1): joints unsigned byte or short, weights float or normalised
  // unsigned byte or short, finite and >= 0; empty when the primitive has no JOINTS_0 and WEIGHTS_0.
  std::vector<VertexInfluences> readInfluences(const tinygltf::Primitive& primitive, std::size_t vertexCount,
                                               const std::string& where, std::uint32_t& largestJoint) const {
    std::vector<VertexInfluences> influences;
    for (int set = 0; set < 2; ++set) {
      const std::string jointsName = "JOINTS_" + std::to_string(set), weightsName = "WEIGHTS_" + std::to_string(set);
      const auto joints = primitive.attributes.find(jointsName);
      const auto weights = primitive.attributes.find(weightsName);
      if (joints == primitive.attributes.end() || weights == primitive.attributes.end()) break;
      if (joints->second >= 0 && std::size_t(joints->second) < model_.accessors.size()) {
        const int type = model_.accessors[std::size_t(joints->second)].componentType;
        if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)
          fail(file_, where + ": " + jointsName + " must be unsigned byte or unsigned short");
      }
      const std::vector<float> j = gltf::readFloats(model_, joints->second, 4, jointsName, file_);
      const std::vector<float> w = gltf::readFloats(model_, weights->second, 4, weightsName, file_);
      if (j.size() != 4 * vertexCount || w.size() != 4 * vertexCount)
        fail(file_, where + ": " + jointsName + " or " + weightsName + " does not have one element per vertex (" +
                        std::to_string(vertexCount) + ")");
      if (influences.empty()) influences.resize(vertexCount);
      for (std::size_t v = 0; v < vertexCount; ++v)
        for (int k = 0; k < 4; ++k) {
          const float weight = w[4 * v + std::size_t(k)];
          if (!(weight >= 0.0f) || !std::isfinite(weight))
            fail(file_, where + ": " + weightsName + " has a negative or non-finite weight");
          const auto joint = std::uint32_t(j[4 * v + std::size_t(k)]);
          influences[v].joints[std::size_t(4 * set + k)] = joint;
          influences[v].weights[std::size_t(4 * set + k)] = weight;
          if (weight > 0.0f) largestJoint = std::max(largestJoint, joint);
        }
    }
    return influences;
  }

  // Morph targets' POSITION, NORMAL and TANGENT displacements (VEC3 float or, with
  // KHR_mesh_quantization, normalised integers), finite, one per vertex.
  std::vector<MorphTarget> readMorphTargets(const tinygltf::Primitive& primitive, std::size_t vertexCount,
                                            const std::string& where) const {
    std::vector<MorphTarget> targets;
    if (vertexCount > 0 && primitive.targets.size() > kMaxMorphElements / vertexCount)
      fail(file_, where + ": " + std::to_string(primitive.targets.size()) + " morph targets of " +
                      std::to_string(vertexCount) + " vertices, beyond the limit of " +
                      std::to_string(kMaxMorphElements) + " target vertices");
    for (std::size_t t = 0; t < primitive.targets.size(); ++t) {
      MorphTarget target;
      for (const auto& [semantic, accessor] : primitive.targets[t]) {
        if (semantic != "POSITION" && semantic != "NORMAL" && semantic != "TANGENT") continue;
        const std::string what = where + ": morph target " + std::to_string(t) + " " + semantic;
        const std::vector<float> values = gltf::readFloats(model_, accessor, 3, "target " + semantic, file_);
        if (values.size() != 3 * vertexCount)
          fail(file_, what + " has " + std::to_string(values.size() / 3) + " elements but POSITION has " +
                          std::to_string(vertexCount));
        requireFinite(values, what + ": non-finite value", file_);
        (semantic == "POSITION" ? target.positions : semantic == "NORMAL" ? target.normals : target.tangents) =
            toVectors<glm::vec3>(values);
      }
      targets.push_back(std::move(target));
    }
    return targets;
  }

  // A primitive in its mesh's local space, checked; nullopt for points and lines.
  std::optional<LocalPrimitive> readPrimitive(int meshIndex, int primitiveIndex) {
    const tinygltf::Primitive& primitive = model_.meshes[meshIndex].primitives[primitiveIndex];
    const std::string where = primitiveName(meshIndex, primitiveIndex);
    if (primitive.mode >= TINYGLTF_MODE_POINTS && primitive.mode <= TINYGLTF_MODE_LINE_STRIP) {
      warn(file_, where + " is points or lines (mode " + std::to_string(primitive.mode) + "); skipped");
      return std::nullopt;
    }
    if (primitive.mode < TINYGLTF_MODE_TRIANGLES || primitive.mode > TINYGLTF_MODE_TRIANGLE_FAN)
      fail(file_, where + ": unknown primitive mode " + std::to_string(primitive.mode));

    Mesh mesh;
    const std::string& name = model_.meshes[meshIndex].name;
    mesh.name = name.empty() ? "mesh " + std::to_string(meshIndex) : name;
    mesh.source = MeshSource{0, -1, meshIndex, primitiveIndex};
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) fail(file_, where + " has no POSITION attribute");
    mesh.positions = toVectors<glm::vec3>(gltf::readFloats(model_, position->second, 3, "POSITION", file_));
    const std::size_t vertexCount = mesh.positions.size();

    for (const auto& [semantic, accessor] : primitive.attributes) {
      const bool custom = semantic.size() > 1 && semantic[0] == '_';
      const bool texcoord = semantic == "TEXCOORD_0" || semantic == "TEXCOORD_1";
      if (semantic == "COLOR_0") {
        mesh.colors = readColors(accessor, vertexCount, where);
        continue;
      }
      if (semantic != "NORMAL" && semantic != "TANGENT" && !texcoord && !custom) continue;
      int components = semantic == "NORMAL" ? 3 : semantic == "TANGENT" ? 4 : texcoord ? 2 : 0;
      if (custom) {
        components = accessor >= 0 && std::size_t(accessor) < model_.accessors.size()
                         ? gltf::componentCount(model_.accessors[accessor].type)
                         : 1;
        if (components == 0) {
          warn(file_, where + ": attribute " + semantic + " is a matrix; skipped");
          continue;
        }
      }
      std::vector<float> values = gltf::readFloats(model_, accessor, components, semantic, file_);
      if (values.size() != vertexCount * components)
        fail(file_, where + ": " + semantic + " has " + std::to_string(values.size() / components) +
                        " elements but POSITION has " + std::to_string(vertexCount));
      if (semantic == "NORMAL") {
        mesh.normals = toVectors<glm::vec3>(values);
      } else if (semantic == "TANGENT") {
        mesh.tangents = readTangents(values, where);
      } else {
        requireFinite(values, where + ": non-finite " + semantic + " value", file_);
        if (custom)
          mesh.attributes[semantic] = VertexAttribute{components, std::move(values)};
        else if (semantic == "TEXCOORD_0")
          mesh.texcoords = toVectors<glm::vec2>(values);
        else
          mesh.texcoords1 = toVectors<glm::vec2>(values);
      }
    }

    std::vector<std::uint32_t> vertices(vertexCount);
    if (primitive.indices >= 0)
      vertices = gltf::readIndices(model_, primitive.indices, file_);
    else
      std::iota(vertices.begin(), vertices.end(), 0u);
    for (std::uint32_t index : vertices)
      if (index >= vertexCount)
        fail(file_, where + ": index " + std::to_string(index) + " out of range (" +
                        std::to_string(vertexCount) + " vertices)");
    mesh.indices = triangleList(std::move(vertices), primitive.mode, where, file_);
    mesh.material = materialIndex(primitive.material, where);
    LocalPrimitive local;
    local.influences = readInfluences(primitive, vertexCount, where, local.largestJoint);
    local.targets = readMorphTargets(primitive, vertexCount, where);
    local.mesh = std::move(mesh);
    return local;
  }

  // COLOR_0 (glTF 2.0 section 3.7.2.1): VEC3 or VEC4 of floats, normalised unsigned bytes or
  // normalised unsigned shorts, linear; VEC3 reads alpha 1. Values outside [0, 1] (floats only can
  // be) are clamped with a warning; NaN or infinite values are an error.
  std::vector<glm::vec4> readColors(int accessor, std::size_t vertexCount, const std::string& where) const {
    const std::string what = where + ": COLOR_0";
    if (accessor < 0 || std::size_t(accessor) >= model_.accessors.size())
      fail(file_, what + ": accessor " + std::to_string(accessor) + " does not exist");
    const tinygltf::Accessor& info = model_.accessors[std::size_t(accessor)];
    const int components = gltf::componentCount(info.type);
    if (components != 3 && components != 4) fail(file_, what + " must be VEC3 or VEC4");
    const bool integer = info.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                         info.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    if (info.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !(integer && info.normalized))
      fail(file_, what + " must be float, normalized unsigned byte or normalized unsigned short");
    const std::vector<float> values = gltf::readFloats(model_, accessor, components, "COLOR_0", file_);
    if (values.size() != vertexCount * std::size_t(components))
      fail(file_, what + " has " + std::to_string(values.size() / std::size_t(components)) +
                      " elements but POSITION has " + std::to_string(vertexCount));
    requireFinite(values, what + ": non-finite value", file_);
    std::vector<glm::vec4> colors(vertexCount, glm::vec4(1.0f));
    std::size_t clamped = 0;
    for (std::size_t i = 0; i < vertexCount; ++i)
      for (int c = 0; c < components; ++c) {
        const float v = values[i * std::size_t(components) + std::size_t(c)];
        clamped += v < 0.0f || v > 1.0f;
        colors[i][c] = std::clamp(v, 0.0f, 1.0f);
      }
    if (clamped > 0)
      warn(file_, what + " has " + std::to_string(clamped) + " components outside [0, 1]; clamped");
    return colors;
  }

  // TANGENT (glTF 2.0 section 3.7.2.1): xyz a unit vector, w +1 or -1 the handedness. w is
  // snapped to its sign. A tangent that is not finite or has zero xyz makes the file's tangents
  // unusable as a frame: they are dropped with a warning, and loadScene generates them instead.
  std::vector<glm::vec4> readTangents(const std::vector<float>& values, const std::string& where) const {
    std::vector<glm::vec4> tangents = toVectors<glm::vec4>(values);
    std::size_t bad = 0;
    for (glm::vec4& t : tangents) {
      const float length = glm::length(glm::vec3(t));
      if (!std::isfinite(t.w) || !std::isfinite(length) || length == 0.0f) ++bad;
      t.w = t.w < 0.0f ? -1.0f : 1.0f;
    }
    if (bad == 0) return tangents;
    warn(file_, where + ": TANGENT has " + std::to_string(bad) +
                    " zero-length or non-finite tangents; ignored (tangents are generated)");
    return {};
  }

  int materialIndex(int material, const std::string& where) {
    if (material >= int(model_.materials.size()))
      fail(file_, where + ": material " + std::to_string(material) + " does not exist");
    if (material >= 0) return material;
    if (defaultMaterial_ < 0) {
      Material fallback;
      fallback.name = "default";
      contents_.materials.push_back(fallback);
      defaultMaterial_ = int(contents_.materials.size()) - 1;
    }
    return defaultMaterial_;
  }

  void readCamera(int cameraIndex, int nodeIndex, const glm::mat4& world) {
    const std::string what = "camera " + std::to_string(cameraIndex);
    if (std::size_t(cameraIndex) >= model_.cameras.size())
      fail(file_, "node " + std::to_string(nodeIndex) + ": " + what + " does not exist");
    const tinygltf::Camera& camera = model_.cameras[cameraIndex];
    if (camera.type != "perspective") {
      warn(file_, what + " is not a perspective camera; ignored");
      return;
    }
    const tinygltf::PerspectiveCamera& p = camera.perspective;
    if (!(p.yfov > 0.0 && p.yfov < glm::pi<double>())) fail(file_, what + ": yfov must be in (0, pi)");
    if (!(p.znear > 0.0)) fail(file_, what + ": znear must be > 0");
    if (p.zfar != 0.0 && !(p.zfar > p.znear)) fail(file_, what + ": zfar must be greater than znear");

    const glm::vec3 position(world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    const glm::vec3 forward = glm::mat3(world) * glm::vec3(0.0f, 0.0f, -1.0f);
    const glm::vec3 up = glm::mat3(world) * glm::vec3(0.0f, 1.0f, 0.0f);
    if (!(glm::length(glm::cross(forward, up)) > 0.0f) || !std::isfinite(glm::length(position)))
      fail(file_, "node " + std::to_string(nodeIndex) + ": degenerate camera transform");
    // zfar 0 means infinite in glTF; load() replaces it once the scene's bounds are known.
    cameraZfarMissing_ = p.zfar == 0.0;
    contents_.camera = Camera::lookAt(position, position + forward, up, float(p.yfov), float(p.znear),
                                      cameraZfarMissing_ ? float(p.znear) : float(p.zfar));
  }

  // The image a texture shows: EXT_texture_webp's source (WebP is read), else its plain source.
  // KHR_texture_basisu (KTX2) is not read: its fallback source is used with a warning, and a
  // texture with no other source is an error.
  int textureImage(int index) const {
    const tinygltf::Texture& texture = model_.textures[index];
    const std::string what = "texture " + std::to_string(index);
    const int webp = extensionSource(texture, "EXT_texture_webp", what, file_);
    const int basisu = extensionSource(texture, "KHR_texture_basisu", what, file_);
    int image = webp >= 0 ? webp : texture.source;
    if (webp < 0 && basisu >= 0) {
      if (texture.source < 0)
        fail(file_, what + " has only a KHR_texture_basisu (KTX2) image, which is not supported; "
                           "give it a PNG, JPEG or WebP source");
      warn(file_, what + ": KHR_texture_basisu (KTX2) is not supported; using its fallback source, image " +
                      std::to_string(texture.source));
    }
    if (image < 0) fail(file_, what + " has no image source");
    if (std::size_t(image) >= model_.images.size())
      fail(file_, what + ": image " + std::to_string(image) + " does not exist");
    return image;
  }

  // The textures the materials use, and their images, renumbered in the file's order (textures
  // and images no material reaches are not loaded); every index is checked, used or not.
  void loadTextures() {
    for (std::size_t t = 0; t < model_.textures.size(); ++t) {
      const tinygltf::Texture& texture = model_.textures[t];
      const std::string what = "texture " + std::to_string(t);
      if (texture.source >= int(model_.images.size()))
        fail(file_, what + ": image " + std::to_string(texture.source) + " does not exist");
      if (texture.sampler >= int(model_.samplers.size()))
        fail(file_, what + ": sampler " + std::to_string(texture.sampler) + " does not exist");
    }
    std::vector<int> textureIndex(model_.textures.size(), -1), imageIndex(model_.images.size(), -1);
    for (Material& material : contents_.materials)
      for (TextureRef* ref : textureRefs(material))
        if (ref->present()) textureIndex[ref->texture] = 0;
    std::vector<int> firstTexture(model_.images.size(), -1);  // for messages
    std::vector<int> textureSources;
    for (std::size_t t = 0; t < model_.textures.size(); ++t) {
      if (textureIndex[t] < 0) continue;
      textureIndex[t] = int(contents_.textures.size());
      const tinygltf::Texture& source = model_.textures[t];
      Texture texture;
      texture.name = source.name;
      const int image = textureImage(int(t));
      textureSources.push_back(image);
      if (firstTexture[image] < 0) firstTexture[image] = int(t);
      if (source.sampler >= 0) texture.sampler = convertSampler(model_.samplers[source.sampler], source.sampler, file_);
      contents_.textures.push_back(texture);
    }
    std::vector<int> images;  // file indices of the images in use, in order
    for (std::size_t i = 0; i < model_.images.size(); ++i)
      if (firstTexture[i] >= 0) {
        imageIndex[i] = int(images.size());
        images.push_back(int(i));
      }
    for (std::size_t t = 0; t < contents_.textures.size(); ++t)
      contents_.textures[t].image = imageIndex[textureSources[t]];
    for (Material& material : contents_.materials)
      for (TextureRef* ref : textureRefs(material))
        if (ref->present()) ref->texture = textureIndex[ref->texture];

    // Decoding dominates the load time of textured files (a 4k PNG takes ~0.1 s), so images decode
    // in parallel. Failures are collected and the first by image index is thrown, so the message
    // does not depend on thread timing.
    contents_.images.resize(images.size());
    std::vector<std::string> declared(images.size());
    std::vector<std::exception_ptr> errors(images.size());
    tbb::parallel_for(std::size_t(0), images.size(), [&](std::size_t k) {
      try {
        loadImage(images[k], firstTexture[images[k]], contents_.images[k], declared[k]);
      } catch (...) {
        errors[k] = std::current_exception();
      }
    });
    for (const std::exception_ptr& error : errors)
      if (error) std::rethrow_exception(error);
    for (std::size_t k = 0; k < images.size(); ++k)
      if (!declared[k].empty() && declared[k] != contents_.images[k].mimeType)
        warn(file_, imageWhat(images[k], firstTexture[images[k]]) + ": declared " + printableExcerpt(declared[k]) +
                        " but holds " + contents_.images[k].mimeType + "; read as " + contents_.images[k].mimeType);
  }

  std::string imageWhat(int image, int texture) const {
    const std::string label = imageLabel(model_.images[image]);
    return "texture " + std::to_string(texture) + " image " + std::to_string(image) +
           (label.empty() ? std::string() : " '" + label + "'");
  }

  // Reads and decodes one image; runs on TBB's threads, so it only throws (no warnings).
  void loadImage(int index, int texture, TextureImage& image, std::string& declared) const {
    const std::string what = imageWhat(index, texture);
    const tinygltf::Image& source = model_.images[index];
    fs::path origin;
    std::vector<std::uint8_t> bytes = gltf::imageBytes(model_, index, file_, what, &declared, &origin);
    // glTF 2.0 section 5.17: image/png and image/jpeg; EXT_texture_webp adds image/webp.
    if (!declared.empty() && !isDecodableImageMimeType(declared))
      fail(file_, what + ": mime type " + printableExcerpt(declared) +
                      " is not supported (image/png, image/jpeg and image/webp are)");
    image.name = source.name;
    image.file = origin;
    image.uri = source.uri.rfind("data:", 0) == 0 ? source.uri.substr(0, source.uri.find(',') + 1)
                : source.as_is                    ? "data:" + source.mimeType + ";base64,"
                                                  : source.uri;
    decodeTextureImage(image, std::move(bytes), file_, what);
  }

  const tinygltf::Model& model_;
  const fs::path& file_;
  GltfContents contents_;
  std::vector<std::vector<std::optional<LocalPrimitive>>> localMeshes_;  // per glTF mesh, per primitive
  std::vector<std::optional<std::vector<glm::mat4>>> jointMatrices_;     // per skin, once computed
  std::vector<int> parents_;  // per node, its parent (-1: a root), for globalTransform
  std::size_t sceneVertices_ = 0;  // the vertices instantiated so far (kMaxSceneVertices)
  int defaultMaterial_ = -1;
  bool cameraZfarMissing_ = false;
};

}  // namespace

GltfContents loadGltf(const fs::path& file) {
  const tinygltf::Model model = gltf::readModel(file);
  return Loader(model, file).load();
}

}  // namespace iblkit
