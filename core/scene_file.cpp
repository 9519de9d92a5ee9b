#include "core/scene_file.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <initializer_list>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/gltf_load.h"
#include "core/input_file.h"
#include "core/procedural_mesh.h"
#include "core/texture_image.h"

namespace iblkit {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kMaxImageSize = 16384;
// kMaxSceneCoordinate (mesh.h) as the messages print it, and the largest environment rotation.
constexpr const char* kMaxCoordinateText = "1e+09";
constexpr double kMaxRotationDegrees = 1e6;

// Reads one JSON object strictly: only the listed keys are allowed, and every error names the
// key path ("models[0].scale").
class ObjectReader {
 public:
  ObjectReader(const json& object, std::string path, const fs::path& file,
               std::initializer_list<const char*> keys)
      : object_(object), path_(std::move(path)), file_(file) {
    if (!object.is_object()) fail(file_, (path_.empty() ? "the document" : path_) + ": expected an object");
    for (const auto& [key, value] : object.items()) {
      bool known = false;
      for (const char* allowed : keys) known = known || key == allowed;
      if (known) continue;
      std::string expected;
      for (const char* allowed : keys) expected += (expected.empty() ? "" : ", ") + std::string(allowed);
      fail(file_, keyPath(key) + ": unknown key (expected one of: " + expected + ")");
    }
  }

  bool has(const char* key) const { return object_.contains(key); }
  const json& at(const char* key) const { return object_.at(key); }

  std::string keyPath(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

  [[noreturn]] void wrongValue(const char* key, const std::string& expected) const {
    fail(file_, keyPath(key) + ": expected " + expected);
  }

  const json& required(const char* key) const {
    if (!has(key))
      fail(file_, (path_.empty() ? "the document" : path_) + ": missing required key '" + key + "'");
    return at(key);
  }

  std::string string(const char* key) const {
    const json& value = required(key);
    if (!value.is_string() || value.get<std::string>().empty()) wrongValue(key, "a non-empty string");
    return value.get<std::string>();
  }

  bool boolean(const char* key, bool fallback) const {
    if (!has(key)) return fallback;
    if (!at(key).is_boolean()) wrongValue(key, "true or false");
    return at(key).get<bool>();
  }

  // A number in [min, max]; `fallback` when absent.
  double number(const char* key, double fallback, double min = -kInfinity, double max = kInfinity) const {
    if (!has(key)) return fallback;
    const json& value = at(key);
    if (!value.is_number() || !std::isfinite(value.get<double>()) || value.get<double>() < min ||
        value.get<double>() > max) {
      std::ostringstream range;
      if (min > -kInfinity && max < kInfinity)
        range << " in [" << min << ", " << max << "]";
      else if (min > -kInfinity)
        range << " >= " << min;
      wrongValue(key, "a number" + range.str());
    }
    return value.get<double>();
  }

  int integer(const char* key, int fallback, int min, int max) const {
    if (!has(key)) return fallback;
    const json& value = at(key);
    if (!value.is_number_integer() || value.get<long long>() < min || value.get<long long>() > max)
      wrongValue(key, "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
    return value.get<int>();
  }

  // An array of exactly n numbers, or nothing when `value` is not one.
  static std::optional<std::vector<double>> numbers(const json& value, std::size_t n) {
    if (!value.is_array() || value.size() != n) return std::nullopt;
    std::vector<double> result;
    for (const json& element : value) {
      if (!element.is_number() || !std::isfinite(element.get<double>())) return std::nullopt;
      result.push_back(element.get<double>());
    }
    return result;
  }

  glm::vec3 vec3(const char* key, const glm::vec3& fallback) const {
    if (!has(key)) return fallback;
    const auto v = numbers(at(key), 3);
    if (!v) wrongValue(key, "an array of 3 numbers");
    return glm::vec3(float((*v)[0]), float((*v)[1]), float((*v)[2]));
  }

  // A color: 3 numbers in [0, max].
  glm::vec3 color(const char* key, const glm::vec3& fallback, double max) const {
    if (!has(key)) return fallback;
    const auto v = numbers(at(key), 3);
    bool valid = v.has_value();
    for (std::size_t i = 0; valid && i < 3; ++i) valid = (*v)[i] >= 0.0 && (*v)[i] <= max;
    if (!valid) {
      std::ostringstream expected;
      expected << "an array of 3 numbers in [0, " << max << "]";
      wrongValue(key, expected.str());
    }
    return glm::vec3(float((*v)[0]), float((*v)[1]), float((*v)[2]));
  }

  const fs::path& file() const { return file_; }
  const std::string& path() const { return path_; }

 private:
  const json& object_;
  std::string path_;
  const fs::path& file_;
};

// The images and textures material overrides add to the scene: one image and one texture (repeat
// wrap, trilinear) per distinct file, however many materials use it.
class OverrideTextures {
 public:
  OverrideTextures(Scene& scene, const fs::path& folder) : scene_(scene), folder_(folder) {}

  // The texture index for `name` (relative to the scene file's folder, as model files are),
  // read through readInputFile and decoded (texture_image.h) the first time. Errors name `key`.
  int texture(const std::string& name, const ObjectReader& reader, const char* key) {
    const fs::path path = (folder_ / name).lexically_normal();
    const auto found = textures_.find(path);
    if (found != textures_.end()) return found->second;
    const std::string what = reader.keyPath(key) + " '" + printableExcerpt(name, 80) + "'";
    std::vector<char> bytes;
    try {
      bytes = readInputFile(path, kMaxBinaryInputBytes);
    } catch (const Error& e) {
      fail(reader.file(), what + ": " + e.what());
    }
    TextureImage image;
    image.name = path.filename().string();
    image.file = path;
    image.uri = name;
    decodeTextureImage(image, std::vector<std::uint8_t>(bytes.begin(), bytes.end()), reader.file(), what);
    Texture texture;
    texture.name = image.name;
    scene_.images.push_back(std::move(image));
    texture.image = int(scene_.images.size()) - 1;
    scene_.textures.push_back(texture);
    return textures_[path] = int(scene_.textures.size()) - 1;
  }

 private:
  Scene& scene_;
  fs::path folder_;
  std::map<fs::path, int> textures_;
};

// A texture slot override: {"file": ..., "uvScale": s or [su, sv], "texCoord": 0 or 1} and, for
// the normal and occlusion slots, "scale" or "strength". It replaces the slot's texture
// reference; uvScale becomes a KHR_texture_transform scale (tiling).
void applyTextureOverride(const ObjectReader& m, const char* key, TextureRef& ref, float* factor,
                          OverrideTextures& textures) {
  if (!m.has(key)) return;
  const char* factorKey = std::string(key) == "normalTexture"      ? "scale"
                          : std::string(key) == "occlusionTexture" ? "strength"
                                                                   : nullptr;
  const ObjectReader t = factorKey ? ObjectReader(m.at(key), m.keyPath(key), m.file(), {"file", "uvScale", "texCoord", factorKey})
                                   : ObjectReader(m.at(key), m.keyPath(key), m.file(), {"file", "uvScale", "texCoord"});
  TextureRef result;
  result.texture = textures.texture(t.string("file"), m, key);
  result.texCoord = t.integer("texCoord", 0, 0, 1);
  if (t.has("uvScale")) {
    const json& value = t.at("uvScale");
    const auto v = value.is_number() ? ObjectReader::numbers(json::array({value, value}), 2)
                                     : ObjectReader::numbers(value, 2);
    const auto usable = [](double x) { return x != 0.0 && std::abs(x) <= kMaxTextureTransformValue; };
    if (!v || !usable((*v)[0]) || !usable((*v)[1]))
      t.wrongValue("uvScale", "a nonzero number or an array of 2 nonzero numbers, within +-1e6");
    result.transform.scale = glm::vec2(float((*v)[0]), float((*v)[1]));
  }
  if (factorKey) {
    // glTF: normalTexture.scale is any number; occlusionTexture.strength is in [0, 1].
    const bool normal = std::string(factorKey) == "scale";
    *factor = float(t.number(factorKey, 1.0, normal ? -kMaxTextureTransformValue : 0.0,
                             normal ? kMaxTextureTransformValue : 1.0));
  }
  ref = result;
}

// "material": {...} overrides on top of `material`; ranges follow glTF (emissive unbounded, as
// with KHR_materials_emissive_strength; specularColor up to the extension's practical range).
void applyMaterialOverrides(const ObjectReader& parent, Material& material, OverrideTextures& textures) {
  if (!parent.has("material")) return;
  const ObjectReader m(parent.at("material"), parent.keyPath("material"), parent.file(),
                       {"baseColor", "metallic", "roughness", "specular", "specularColor", "ior", "emissive", "alpha",
                        "alphaMode", "alphaCutoff", "doubleSided", "baseColorTexture", "metallicRoughnessTexture",
                        "normalTexture", "occlusionTexture", "emissiveTexture"});
  material.baseColor = m.color("baseColor", material.baseColor, 1.0);
  material.metallic = float(m.number("metallic", material.metallic, 0.0, 1.0));
  material.roughness = float(m.number("roughness", material.roughness, 0.0, 1.0));
  material.specular = float(m.number("specular", material.specular, 0.0, 1.0));
  material.specularColor = m.color("specularColor", material.specularColor, kInfinity);
  material.ior = float(m.number("ior", material.ior, 1.0, 1000.0));
  material.emissive = m.color("emissive", material.emissive, kInfinity);
  material.alpha = float(m.number("alpha", material.alpha, 0.0, 1.0));
  if (m.has("alphaMode")) {
    const json& mode = m.at("alphaMode");
    if (mode == "OPAQUE") material.alphaMode = AlphaMode::Opaque;
    else if (mode == "MASK") material.alphaMode = AlphaMode::Mask;
    else if (mode == "BLEND") material.alphaMode = AlphaMode::Blend;
    else m.wrongValue("alphaMode", "\"OPAQUE\", \"MASK\" or \"BLEND\"");
  }
  material.alphaCutoff = float(m.number("alphaCutoff", material.alphaCutoff, 0.0));
  material.doubleSided = m.boolean("doubleSided", material.doubleSided);
  applyTextureOverride(m, "baseColorTexture", material.baseColorTexture, nullptr, textures);
  applyTextureOverride(m, "metallicRoughnessTexture", material.metallicRoughnessTexture, nullptr, textures);
  applyTextureOverride(m, "normalTexture", material.normalTexture, &material.normalScale, textures);
  applyTextureOverride(m, "occlusionTexture", material.occlusionTexture, &material.occlusionStrength, textures);
  applyTextureOverride(m, "emissiveTexture", material.emissiveTexture, nullptr, textures);
}

bool hasTexture(const Material& m) {
  return m.baseColorTexture.present() || m.metallicRoughnessTexture.present() || m.normalTexture.present() ||
         m.occlusionTexture.present() || m.emissiveTexture.present();
}

glm::mat4 modelTransform(const ObjectReader& model) {
  const glm::vec3 translation = model.vec3("translation", glm::vec3(0.0f));
  glm::quat rotation(1.0f, 0.0f, 0.0f, 0.0f);
  if (model.has("rotation")) {
    const auto q = ObjectReader::numbers(model.at("rotation"), 4);
    // glTF order x, y, z, w; glm's constructor takes w first.
    if (!q || !(std::hypot((*q)[0], (*q)[1], (*q)[2]) + std::abs((*q)[3]) > 0.0))
      model.wrongValue("rotation", "a quaternion [x, y, z, w] (not all zero)");
    rotation = glm::normalize(glm::quat(float((*q)[3]), float((*q)[0]), float((*q)[1]), float((*q)[2])));
  }
  glm::vec3 scale(1.0f);
  if (model.has("scale")) {
    const json& value = model.at("scale");
    const auto v = value.is_number() ? ObjectReader::numbers(json::array({value, value, value}), 3)
                                     : ObjectReader::numbers(value, 3);
    if (!v || (*v)[0] == 0.0 || (*v)[1] == 0.0 || (*v)[2] == 0.0)
      model.wrongValue("scale", "a nonzero number or an array of 3 nonzero numbers");
    scale = glm::vec3(float((*v)[0]), float((*v)[1]), float((*v)[2]));
  }
  return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) *
         glm::scale(glm::mat4(1.0f), scale);
}

// A built-in shape: "sphere" is a unit sphere at the origin (place and size it with translation
// and scale), finely tessellated so that its silhouette and interpolated normals are smooth at
// the bundled image sizes. Its material is a white dielectric (glTF defaults with metallic 0),
// which the model's "material" overrides.
GltfContents shapeContents(const ObjectReader& model) {
  const std::string shape = model.string("shape");
  if (shape != "sphere") model.wrongValue("shape", "\"sphere\"");
  constexpr int kRings = 96, kSegments = 192;
  const ProceduralMesh sphere = uvSphere(glm::vec3(0.0f), 1.0f, kRings, kSegments);
  Mesh mesh;
  mesh.name = shape;
  mesh.positions = sphere.positions;
  mesh.normals = sphere.normals;
  mesh.indices = sphere.indices;
  Material material;
  material.name = shape;
  material.metallic = 0.0f;
  GltfContents contents;
  contents.meshes.push_back(std::move(mesh));
  contents.materials.push_back(material);
  return contents;
}

void readModels(const ObjectReader& root, const fs::path& folder, Scene& scene, OverrideTextures& textures) {
  const json& models = root.required("models");
  if (!models.is_array() || models.empty()) root.wrongValue("models", "a non-empty array of models");
  for (std::size_t i = 0; i < models.size(); ++i) {
    const ObjectReader model(models[i], "models[" + std::to_string(i) + "]", root.file(),
                             {"file", "shape", "translation", "rotation", "scale", "material"});
    if (model.has("file") == model.has("shape"))
      fail(root.file(), model.path() + ": needs exactly one of 'file' and 'shape'");
    fs::path path;
    GltfContents contents;
    if (model.has("file")) {
      path = (folder / model.string("file")).lexically_normal();
      contents = loadGltf(path);
    } else {
      contents = shapeContents(model);
      path = "shape:" + model.string("shape");
    }
    const glm::mat4 transform = modelTransform(model);

    // The model's textures and images follow those of the models before it.
    const int materialOffset = int(scene.materials.size());
    const int textureOffset = int(scene.textures.size());
    const int imageOffset = int(scene.images.size());
    for (Texture& texture : contents.textures) {
      texture.image += imageOffset;
      scene.textures.push_back(std::move(texture));
    }
    for (TextureImage& image : contents.images) scene.images.push_back(std::move(image));
    for (Material& material : contents.materials) {
      for (TextureRef* ref : {&material.baseColorTexture, &material.metallicRoughnessTexture,
                              &material.normalTexture, &material.occlusionTexture, &material.emissiveTexture})
        if (ref->present()) ref->texture += textureOffset;
      applyMaterialOverrides(model, material, textures);
      scene.materials.push_back(material);
    }
    for (Mesh& mesh : contents.meshes) {
      transformMesh(mesh, transform);
      if (const long long v = firstVertexOutOfRange(mesh); v >= 0)
        fail(root.file(), model.path() + ": translation, rotation and scale put vertex " + std::to_string(v) +
                              " of " + path.string() +
                              (mesh.source.node >= 0 ? " node " + std::to_string(mesh.source.node) + " (mesh " +
                                                           std::to_string(mesh.source.mesh) + " primitive " +
                                                           std::to_string(mesh.source.primitive) + ")"
                                                     : std::string()) +
                              " beyond " + kMaxCoordinateText + " or out of float range");
      mesh.material += materialOffset;
      mesh.source.model = int(i);
      scene.meshes.push_back(std::move(mesh));
    }
    scene.modelFiles.push_back(path);
  }
}

// The ground's grid: kGroundCells x kGroundCells cells, graded so that they are finest in the
// middle, under the objects (the ground is centred under them and 10 bounding radii wide). The
// baker's per-vertex ambient occlusion and bent normals, which every AO mode of the engine reads,
// need vertices where the objects occlude the sky: a two-triangle square had them only at its four
// far corners, so the engine's ground showed no contact shadow at all (docs/scene-format.md).
constexpr int kGroundCells = 64;
constexpr float kGroundCentreSpacing = 0.35f;  // cell size in the middle, relative to a uniform grid's

// Position in [-1, 1] of grid line i of kGroundCells: f(t) = t (a + (1 - a) t^2), odd and
// increasing, f(1) = 1, f'(0) = a: the middle cells a, the outer ones 3 - 2a times the uniform size.
float groundGridLine(int i) {
  const float t = 2.0f * float(i) / float(kGroundCells) - 1.0f;
  const float a = kGroundCentreSpacing;
  return t * (a + (1.0f - a) * t * t);
}

// A square of side `size` at height `height`, centred under the objects, facing +Y, as a graded
// grid of triangles (above). With `texcoords`, TEXCOORD_0 spans [0, 1] over it, u along +X and v
// along +Z.
Mesh groundMesh(const glm::vec3& center, float height, float size, int material, bool texcoords) {
  Mesh ground;
  ground.name = "ground";
  ground.isGround = true;
  ground.material = material;
  ground.source = MeshSource{-1, -1, -1, -1};
  const float h = 0.5f * size;
  constexpr int lines = kGroundCells + 1;
  for (int j = 0; j < lines; ++j)
    for (int i = 0; i < lines; ++i) {
      // The outer lines exactly at +-h, so the square is the size asked for.
      const glm::vec2 corner(i == 0 ? -h : i == kGroundCells ? h : h * groundGridLine(i),
                             j == 0 ? -h : j == kGroundCells ? h : h * groundGridLine(j));
      ground.positions.emplace_back(center.x + corner.x, height, center.z + corner.y);
      ground.normals.emplace_back(0.0f, 1.0f, 0.0f);
      if (texcoords) ground.texcoords.push_back(corner / size + 0.5f);
    }
  // Counter-clockwise seen from above: with v00 at (x_i, z_j), v10 at (x_i+1, z_j), v01 at
  // (x_i, z_j+1), cross(v01 - v00, v11 - v00) points along +Y.
  for (int j = 0; j < kGroundCells; ++j)
    for (int i = 0; i < kGroundCells; ++i) {
      const auto v00 = std::uint32_t(j * lines + i), v10 = v00 + 1, v01 = v00 + lines, v11 = v01 + 1;
      ground.indices.insert(ground.indices.end(), {v00, v01, v11, v00, v11, v10});
    }
  return ground;
}

void readGround(const ObjectReader& root, Scene& scene, OverrideTextures& textures) {
  if (!root.has("ground")) return;
  const ObjectReader ground(root.at("ground"), "ground", root.file(),
                            {"enabled", "height", "size", "material"});
  if (!ground.boolean("enabled", true)) return;
  // Within kMaxSceneCoordinate, so that the ground's corners are too (Embree asserts on rays
  // beyond ~1.8e18; a 1e30 ground aborted the bake).
  const double limit = kMaxSceneCoordinate;
  const float height = float(ground.number("height", scene.bounds.min.y, -limit, limit));
  const double automaticSize = std::min(10.0 * scene.bounds.radius(), limit);
  const float size = float(ground.number("size", automaticSize, 0.0, limit));
  if (!(size > 0.0f)) ground.wrongValue("size", "a number > 0");

  // A neutral grey dielectric unless overridden.
  Material material;
  material.name = "ground";
  material.baseColor = glm::vec3(0.5f);
  material.metallic = 0.0f;
  applyMaterialOverrides(ground, material, textures);
  scene.materials.push_back(material);
  scene.meshes.push_back(
      groundMesh(scene.bounds.center(), height, size, int(scene.materials.size()) - 1, hasTexture(material)));
}

void readEnvironment(const ObjectReader& root, const fs::path& folder, Scene& scene) {
  if (!root.has("environment")) return;
  const ObjectReader environment(root.at("environment"), "environment", root.file(),
                                 {"file", "rotation", "intensity"});
  const std::string name = environment.string("file");
  scene.environment.file = (folder / name).lexically_normal();
  std::error_code error;
  if (!fs::is_regular_file(scene.environment.file, error))
    fail(root.file(), "environment.file: '" + name + "' does not exist");
  scene.environment.rotationDegrees =
      float(environment.number("rotation", 0.0, -kMaxRotationDegrees, kMaxRotationDegrees));
  // Beyond float it is inf: checkEnvironmentIntensity (scene_environment.h) names this key then.
  scene.environment.intensity = float(environment.number("intensity", 1.0, 0.0));
}

void readCamera(const ObjectReader& root, Scene& scene) {
  if (!root.has("camera")) return;
  const ObjectReader camera(root.at("camera"), "camera", root.file(),
                            {"position", "target", "up", "yfov", "znear", "zfar"});
  camera.required("position");
  camera.required("target");
  const glm::vec3 position = camera.vec3("position", glm::vec3(0.0f));
  const glm::vec3 target = camera.vec3("target", glm::vec3(0.0f));
  const glm::vec3 up = camera.vec3("up", glm::vec3(0.0f, 1.0f, 0.0f));
  if (target == position) camera.wrongValue("target", "a point different from camera.position");
  if (!(glm::length(glm::cross(target - position, up)) > 0.0f))
    camera.wrongValue("up", "a direction not parallel to the view direction");
  const double yfov = camera.number("yfov", 45.0, 0.0, 180.0);
  if (yfov <= 0.0 || yfov >= 180.0) camera.wrongValue("yfov", "degrees in (0, 180)");
  const ClipPlanes automatic = clipPlanesFor(position, scene.bounds);
  const double znear = camera.number("znear", automatic.znear, 0.0);
  if (!(znear > 0.0)) camera.wrongValue("znear", "a number > 0");
  const double zfar = camera.number("zfar", std::max(double(automatic.zfar), 2.0 * znear), 0.0);
  if (!(zfar > znear)) camera.wrongValue("zfar", "a number greater than znear");
  scene.camera = Camera::lookAt(position, target, up, float(glm::radians(yfov)), float(znear), float(zfar));
}

json parseDocument(const fs::path& file) {
  const std::string text = readJsonText(file);
  try {
    return json::parse(text);
  } catch (const json::exception& e) {
    // parse_error, and out_of_range for a number beyond double's range ("1e999").
    fail(file, std::string("invalid JSON: ") + e.what());
  }
}

}  // namespace

Scene loadSceneFile(const fs::path& file) {
  const json document = parseDocument(file);
  const ObjectReader root(document, "", file,
                          {"models", "ground", "environment", "camera", "width", "height"});
  const fs::path folder = file.parent_path();

  Scene scene;
  scene.file = file;
  OverrideTextures textures(scene, folder);
  readModels(root, folder, scene, textures);
  scene.bounds = objectBounds(scene.meshes);
  readGround(root, scene, textures);
  readEnvironment(root, folder, scene);
  readCamera(root, scene);
  scene.width = root.integer("width", kDefaultImageWidth, 1, kMaxImageSize);
  scene.height = root.integer("height", kDefaultImageHeight, 1, kMaxImageSize);
  return scene;
}

}  // namespace iblkit
