#include "bakefile/scene_glb.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "core/gltf_load.h"
#include "core/procedural_mesh.h"
#include "core/scene.h"
#include "support/error_capture.h"
#include "support/gltf_builder.h"
#include "support/test_paths.h"
#include "support/texture_files.h"

namespace iblkit {
namespace {

// Two meshes (a sphere with texture coordinates and two custom attributes, and a ground), two
// materials (one emitting brighter than glTF's [0, 1] emissiveFactor) and a camera.
Scene bakedScene() {
  Scene scene;
  Mesh sphere = toMesh(uvSphere(glm::vec3(0.5f, 1.0f, -0.25f), 0.75f, 6, 8), "sphere", 1);
  for (std::size_t v = 0; v < sphere.vertexCount(); ++v) {
    sphere.texcoords.emplace_back(float(v) / 64.0f, 1.0f - float(v) / 128.0f);
    sphere.attributes["_AO"].data.push_back(float(v) / float(sphere.vertexCount()));
    for (int c = 0; c < 3; ++c) sphere.attributes["_SHT0"].data.push_back(float(3 * v + c) * 0.25f - 3.0f);
  }
  sphere.attributes["_AO"].componentCount = 1;
  sphere.attributes["_SHT0"].componentCount = 3;
  Mesh ground = toMesh(plane(glm::vec3(0.0f), 10.0f), "ground", 0);
  ground.isGround = true;
  scene.meshes = {sphere, ground};
  Material grey;
  grey.name = "ground";
  grey.baseColor = glm::vec3(0.5f);
  grey.metallic = 0.0f;
  Material lamp;
  lamp.name = "lamp";
  lamp.baseColor = glm::vec3(0.9f, 0.2f, 0.1f);
  lamp.roughness = 0.35f;
  lamp.specular = 0.5f;
  lamp.specularColor = glm::vec3(1.0f, 0.8f, 0.6f);
  lamp.emissive = glm::vec3(4.0f, 2.0f, 0.0f);
  scene.materials = {grey, lamp};
  scene.camera = Camera::lookAt(glm::vec3(1.0f, 2.0f, 6.0f), glm::vec3(0.0f, 0.5f, 0.0f), glm::vec3(0, 1, 0),
                                glm::radians(40.0f), 0.05f, 80.0f);
  scene.width = 640;
  scene.height = 360;
  return scene;
}

using nlohmann::json;

// A w x h RGBA image, encoded: a checker of two colours with alpha falling along x, so that
// every channel varies.
std::vector<std::uint8_t> rgbaPattern(int w, int h) {
  std::vector<std::uint8_t> rgba(std::size_t(w) * h * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool odd = (x + y) % 2;
      std::uint8_t* p = &rgba[(std::size_t(y) * w + x) * 4];
      p[0] = odd ? 230 : 20;
      p[1] = odd ? 40 : 200;
      p[2] = std::uint8_t(60 + 10 * y);
      p[3] = std::uint8_t(255 - 20 * x);
    }
  return rgba;
}

// The writer copies image bytes, so the test needs real files whose bytes it knows.
std::vector<std::uint8_t> encodePng(int w, int h) { return test::encodePng(w, h, rgbaPattern(w, h)); }
std::vector<std::uint8_t> encodeJpeg(int w, int h) { return test::encodeJpeg(w, h, rgbaPattern(w, h), 90); }
std::vector<std::uint8_t> encodeWebp(int w, int h) { return test::encodeWebp(w, h, rgbaPattern(w, h)); }

TextureImage image(std::string name, std::string mimeType, std::vector<std::uint8_t> encoded, int w, int h) {
  TextureImage result;
  result.name = std::move(name);
  result.mimeType = std::move(mimeType);
  result.encoded = std::move(encoded);
  result.width = w;
  result.height = h;
  return result;
}

// bakedScene() with textures in every slot: a PNG and a JPEG image, three textures with differing
// samplers, every slot of the lamp filled (texCoord 0 and 1, a KHR_texture_transform, normal scale,
// occlusion strength), MASK and BLEND, doubleSided, and the sphere's TEXCOORD_1 and TANGENT.
Scene texturedScene() {
  Scene scene = bakedScene();
  scene.images = {image("checker", "image/png", encodePng(4, 4), 4, 4),
                  image("ao", "image/jpeg", encodeJpeg(8, 8), 8, 8),
                  image("tiles", "image/webp", encodeWebp(2, 4), 2, 4)};
  Texture nearest;
  nearest.name = "nearest";
  nearest.image = 0;
  nearest.sampler = {.wrapS = TextureWrap::ClampToEdge,
                     .wrapT = TextureWrap::MirroredRepeat,
                     .magFilter = TextureFilter::Nearest,
                     .minFilter = TextureFilter::Nearest,
                     .mipmaps = false};
  Texture trilinear;  // the default sampler
  trilinear.image = 1;
  Texture mipNearest;
  mipNearest.image = 0;
  mipNearest.sampler.minFilter = TextureFilter::Linear;
  mipNearest.sampler.mipFilter = TextureFilter::Nearest;
  Texture webp;
  webp.image = 2;
  scene.textures = {nearest, trilinear, mipNearest, webp};

  Material& lamp = scene.materials[1];
  lamp.alpha = 0.75f;
  lamp.baseColorTexture.texture = 0;
  lamp.baseColorTexture.transform = {.offset = glm::vec2(0.25f, -0.5f), .rotation = 0.5f, .scale = glm::vec2(2.0f, 3.0f)};
  lamp.metallicRoughnessTexture = {.texture = 2, .texCoord = 1, .transform = {}};
  lamp.normalTexture = {.texture = 1, .texCoord = 0, .transform = {}};
  lamp.normalScale = 0.75f;
  lamp.occlusionTexture = {.texture = 1, .texCoord = 1, .transform = {}};
  lamp.occlusionStrength = 0.625f;
  lamp.emissiveTexture = {.texture = 3, .texCoord = 0, .transform = {}};
  lamp.alphaMode = AlphaMode::Mask;
  lamp.alphaCutoff = 0.375f;
  lamp.doubleSided = true;
  lamp.ior = 1.33f;  // KHR_materials_ior, written only where it is not 1.5
  scene.materials[0].alphaMode = AlphaMode::Blend;

  Mesh& sphere = scene.meshes[0];
  for (std::size_t v = 0; v < sphere.vertexCount(); ++v) {
    sphere.texcoords1.emplace_back(0.5f - float(v) / 256.0f, float(v) / 32.0f);
    const glm::vec3 n = sphere.normals[v];
    const glm::vec3 t = glm::normalize(glm::cross(glm::abs(n.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0), n));
    sphere.tangents.emplace_back(t, v % 2 ? -1.0f : 1.0f);
    sphere.colors.emplace_back(float(v % 5) / 4.0f, 0.25f, 1.0f - float(v % 3) / 2.0f, float(v % 2) * 0.5f + 0.5f);
  }
  return scene;
}

// A .glb's JSON and BIN chunks (glTF 2.0 section 4.4), read by hand rather than by our loader.
struct GlbChunks {
  json document;
  std::vector<std::uint8_t> bin;
};

GlbChunks readGlb(const std::filesystem::path& file) {
  std::ifstream stream(file, std::ios::binary);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(stream), {}};
  const auto u32 = [&](std::size_t at) {
    std::uint32_t value;
    std::memcpy(&value, bytes.data() + at, 4);
    return value;
  };
  GlbChunks chunks;
  const std::uint32_t jsonLength = u32(12);
  chunks.document = json::parse(bytes.begin() + 20, bytes.begin() + 20 + jsonLength);
  const std::uint32_t binLength = u32(20 + jsonLength);
  chunks.bin.assign(bytes.begin() + 28 + jsonLength, bytes.begin() + 28 + jsonLength + binLength);
  return chunks;
}

// The bytes of image `index`'s buffer view.
std::vector<std::uint8_t> imageBytes(const GlbChunks& glb, int index) {
  const json& view = glb.document["bufferViews"][glb.document["images"][index]["bufferView"].get<int>()];
  const std::size_t offset = view.value("byteOffset", 0), length = view["byteLength"];
  return {glb.bin.begin() + offset, glb.bin.begin() + offset + length};
}

TEST(BakedSceneGltf, LoadsBackAsTheSameMeshesMaterialsAndCamera) {
  const Scene scene = bakedScene();
  const std::filesystem::path file = test::scratchDir() / "scene.glb";
  writeSceneGlb(scene, file);
  const GltfContents back = loadGltf(file);

  ASSERT_EQ(back.meshes.size(), scene.meshes.size());
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh &written = scene.meshes[m], &read = back.meshes[m];
    EXPECT_EQ(read.name, written.name);
    EXPECT_EQ(read.positions, written.positions);
    // The loader re-normalises normals, which may change their last bit.
    ASSERT_EQ(read.normals.size(), written.normals.size());
    for (std::size_t v = 0; v < read.normals.size(); ++v)
      EXPECT_LT(glm::distance(read.normals[v], written.normals[v]), 1e-6f) << written.name << " vertex " << v;
    EXPECT_EQ(read.texcoords, written.texcoords);
    EXPECT_EQ(read.indices, written.indices);
    EXPECT_EQ(read.material, written.material);
    EXPECT_EQ(read.isGround, written.isGround) << written.name;
    ASSERT_EQ(read.attributes.size(), written.attributes.size());
    for (const auto& [name, attribute] : written.attributes) {
      ASSERT_TRUE(read.attributes.count(name)) << name;
      EXPECT_EQ(read.attributes.at(name).componentCount, attribute.componentCount) << name;
      EXPECT_EQ(read.attributes.at(name).data, attribute.data) << name;
    }
  }

  ASSERT_EQ(back.materials.size(), 2u);
  const Material& lamp = back.materials[1];
  EXPECT_EQ(lamp.name, "lamp");
  EXPECT_EQ(lamp.baseColor, glm::vec3(0.9f, 0.2f, 0.1f));
  EXPECT_EQ(lamp.metallic, 1.0f);
  EXPECT_EQ(lamp.roughness, 0.35f);
  EXPECT_EQ(lamp.specular, 0.5f);
  EXPECT_EQ(lamp.specularColor, glm::vec3(1.0f, 0.8f, 0.6f));
  EXPECT_EQ(lamp.emissive, glm::vec3(4.0f, 2.0f, 0.0f));  // factor (1, 0.5, 0) times strength 4
  EXPECT_EQ(back.materials[0].metallic, 0.0f);
  EXPECT_EQ(back.materials[0].emissive, glm::vec3(0.0f));

  ASSERT_TRUE(back.camera.has_value());
  const Camera &expected = *scene.camera, &camera = *back.camera;
  EXPECT_LT(glm::distance(camera.position, expected.position), 1e-5f);
  EXPECT_LT(glm::distance(camera.forward, expected.forward), 1e-5f);
  EXPECT_LT(glm::distance(camera.up, expected.up), 1e-5f);
  EXPECT_FLOAT_EQ(camera.yfovRadians, expected.yfovRadians);
  EXPECT_FLOAT_EQ(camera.znear, 0.05f);
  EXPECT_FLOAT_EQ(camera.zfar, 80.0f);
}

// The ground's extras.isGround survives the round trip, so a baked scene is framed by the bounds of
// its objects alone, exactly as the scene it was baked from.
TEST(BakedSceneGltf, GroundIsLeftOutOfTheFramingBoundsAfterLoading) {
  Scene scene = bakedScene();
  scene.camera.reset();
  const std::filesystem::path file = test::scratchDir() / "framing.glb";
  writeSceneGlb(scene, file);
  const Scene back = loadScene(file);
  const Bounds original = objectBounds(scene.meshes);
  EXPECT_EQ(back.bounds.min, original.min);
  EXPECT_EQ(back.bounds.max, original.max);
  EXPECT_LT(back.bounds.radius(), 1.5f);  // the sphere's box (half diagonal 1.3), not the 10-wide ground
  const Camera framed = sceneCamera(back, 16.0f / 9.0f), expected = frameBounds(original, 16.0f / 9.0f);
  EXPECT_EQ(framed.position, expected.position);
  EXPECT_EQ(framed.forward, expected.forward);
}

TEST(BakedSceneGltf, ContainerIsFourByteAlignedGlb) {
  const std::filesystem::path file = test::scratchDir() / "scene.glb";
  writeSceneGlb(bakedScene(), file);
  const auto size = std::filesystem::file_size(file);
  EXPECT_EQ(size % 4, 0u);
  EXPECT_FALSE(std::filesystem::exists(file.string() + ".tmp"));
}

TEST(BakedSceneGltf, BadScenesAreErrorsAndLeaveNoFile) {
  const std::filesystem::path file = test::scratchDir() / "bad.glb";
  Scene nan = bakedScene();
  nan.meshes[0].attributes["_AO"].data[5] = std::nanf("");
  EXPECT_EQ(test::errorMessage([&] { writeSceneGlb(nan, file); }),
            file.string() + ": mesh 0 (sphere) attribute _AO has a non-finite value");
  Scene short_ = bakedScene();
  short_.meshes[0].attributes["_SHT0"].data.pop_back();
  EXPECT_EQ(test::errorMessage([&] { writeSceneGlb(short_, file); }),
            file.string() + ": mesh 0 (sphere) attribute _SHT0 has 125 values for 42 vertices");
  Scene noMaterial = bakedScene();
  noMaterial.meshes[1].material = 2;
  EXPECT_EQ(test::errorMessage([&] { writeSceneGlb(noMaterial, file); }),
            file.string() + ": mesh 1 (ground): material 2 does not exist");
  Scene empty;
  EXPECT_EQ(test::errorMessage([&] { writeSceneGlb(empty, file); }),
            file.string() + ": the scene has no meshes");
  EXPECT_FALSE(std::filesystem::exists(file));
}

// The images' bytes are the encoded files themselves (not re-encoded), and every sampler, texture,
// slot, alpha setting and vertex set is in the JSON as glTF 2.0 spells it; read here by hand, so a
// reader that forgave a mistake could not hide it.
TEST(BakedSceneGltf, TexturedSceneKeepsImageBytesSamplersAndEverySlot) {
  const Scene scene = texturedScene();
  const std::filesystem::path file = test::scratchDir() / "textured.glb";
  writeSceneGlb(scene, file);
  const GlbChunks glb = readGlb(file);
  const json& doc = glb.document;

  ASSERT_EQ(doc["images"].size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(imageBytes(glb, i), scene.images[i].encoded) << "image " << i;
    EXPECT_EQ(doc["images"][i]["mimeType"], scene.images[i].mimeType);
    EXPECT_EQ(doc["images"][i]["name"], scene.images[i].name);
    EXPECT_EQ(doc["bufferViews"][doc["images"][i]["bufferView"].get<int>()]["byteOffset"].get<int>() % 4, 0);
  }
  ASSERT_EQ(doc["textures"].size(), 4u);
  EXPECT_EQ(doc["textures"][0], json::parse(R"({"name": "nearest", "source": 0, "sampler": 0})"));
  EXPECT_EQ(doc["textures"][1]["source"], 1);
  EXPECT_EQ(doc["samplers"][0], json::parse(R"({"magFilter": 9728, "minFilter": 9728, "wrapS": 33071, "wrapT": 33648})"));
  EXPECT_EQ(doc["samplers"][1], json::parse(R"({"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497})"));
  EXPECT_EQ(doc["samplers"][2]["minFilter"], 9985);  // LINEAR_MIPMAP_NEAREST

  const json& lamp = doc["materials"][1];
  EXPECT_EQ(lamp["pbrMetallicRoughness"]["baseColorFactor"][3], 0.75);
  EXPECT_EQ(lamp["pbrMetallicRoughness"]["baseColorTexture"],
            json::parse(R"({"index": 0, "extensions": {"KHR_texture_transform":
                            {"offset": [0.25, -0.5], "rotation": 0.5, "scale": [2.0, 3.0]}}})"));
  EXPECT_EQ(lamp["pbrMetallicRoughness"]["metallicRoughnessTexture"], json::parse(R"({"index": 2, "texCoord": 1})"));
  EXPECT_EQ(lamp["normalTexture"], json::parse(R"({"index": 1, "scale": 0.75})"));
  EXPECT_EQ(lamp["occlusionTexture"], json::parse(R"({"index": 1, "texCoord": 1, "strength": 0.625})"));
  EXPECT_EQ(lamp["emissiveTexture"], json::parse(R"({"index": 3})"));
  EXPECT_EQ(doc["textures"][3]["extensions"]["EXT_texture_webp"]["source"], 2);
  EXPECT_EQ(lamp["alphaMode"], "MASK");
  EXPECT_EQ(lamp["alphaCutoff"], 0.375);
  EXPECT_EQ(lamp["doubleSided"], true);
  EXPECT_EQ(doc["materials"][0]["alphaMode"], "BLEND");
  EXPECT_FALSE(doc["materials"][0].contains("doubleSided"));
  EXPECT_FALSE(doc["materials"][0].contains("alphaCutoff"));
  EXPECT_NE(std::find(doc["extensionsUsed"].begin(), doc["extensionsUsed"].end(), "KHR_texture_transform"),
            doc["extensionsUsed"].end());
  EXPECT_EQ(doc["extensionsRequired"], json::parse(R"(["EXT_texture_webp"])"));

  const json& sphere = doc["meshes"][0]["primitives"][0]["attributes"];
  ASSERT_TRUE(sphere.contains("TEXCOORD_1"));
  ASSERT_TRUE(sphere.contains("TANGENT"));
  EXPECT_EQ(doc["accessors"][sphere["TANGENT"].get<int>()]["type"], "VEC4");
  const json& tangentView = doc["bufferViews"][doc["accessors"][sphere["TANGENT"].get<int>()]["bufferView"].get<int>()];
  std::vector<glm::vec4> tangents(scene.meshes[0].vertexCount());
  ASSERT_EQ(tangentView["byteLength"].get<std::size_t>(), tangents.size() * sizeof(glm::vec4));
  std::memcpy(tangents.data(), glb.bin.data() + tangentView["byteOffset"].get<std::size_t>(),
              tangents.size() * sizeof(glm::vec4));
  EXPECT_EQ(tangents, scene.meshes[0].tangents);
  EXPECT_FALSE(doc["meshes"][1]["primitives"][0]["attributes"].contains("TANGENT"));  // the ground has none
  EXPECT_FALSE(doc["meshes"][1]["primitives"][0]["attributes"].contains("TEXCOORD_1"));
}

// A WebP image is the texture's EXT_texture_webp source, with no fallback, so the extension is
// required (EXT_texture_webp's README); the bytes are copied as for the other formats.
TEST(BakedSceneGltf, WebpTexturesUseAndRequireExtTextureWebp) {
  Scene scene = bakedScene();
  const std::vector<std::uint8_t> riff = {'R', 'I', 'F', 'F', 4, 0, 0, 0, 'W', 'E', 'B', 'P', 1, 2, 3};
  scene.images = {image("normal", "image/webp", riff, 1, 1), image("checker", "image/png", encodePng(2, 2), 2, 2)};
  Texture webp, png;
  webp.image = 0;
  png.image = 1;
  scene.textures = {webp, png};
  scene.materials[1].normalTexture.texture = 0;
  scene.materials[1].baseColorTexture.texture = 1;
  const std::filesystem::path file = test::scratchDir() / "webp.glb";
  writeSceneGlb(scene, file);
  const GlbChunks glb = readGlb(file);
  EXPECT_EQ(imageBytes(glb, 0), riff);
  EXPECT_EQ(glb.document["textures"][0], json::parse(R"({"sampler": 0, "extensions": {"EXT_texture_webp": {"source": 0}}})"));
  EXPECT_EQ(glb.document["textures"][1]["source"], 1);
  EXPECT_EQ(glb.document["extensionsRequired"], json::parse(R"(["EXT_texture_webp"])"));
  const json& used = glb.document["extensionsUsed"];
  EXPECT_NE(std::find(used.begin(), used.end(), "EXT_texture_webp"), used.end());
}

void expectSameSampler(const TextureSampler& a, const TextureSampler& b, const std::string& what) {
  EXPECT_EQ(a.wrapS, b.wrapS) << what;
  EXPECT_EQ(a.wrapT, b.wrapT) << what;
  EXPECT_EQ(a.magFilter, b.magFilter) << what;
  EXPECT_EQ(a.minFilter, b.minFilter) << what;
  EXPECT_EQ(a.mipmaps, b.mipmaps) << what;
  if (a.mipmaps) {
    EXPECT_EQ(a.mipFilter, b.mipFilter) << what;
  }
}

void expectSameRef(const TextureRef& a, const TextureRef& b, const std::string& what) {
  EXPECT_EQ(a.texture, b.texture) << what;
  EXPECT_EQ(a.texCoord, b.texCoord) << what;
  EXPECT_EQ(a.transform.offset, b.transform.offset) << what;
  EXPECT_EQ(a.transform.rotation, b.transform.rotation) << what;
  EXPECT_EQ(a.transform.scale, b.transform.scale) << what;
}

void expectSameMaterial(const Material& a, const Material& b) {
  const std::string& what = a.name;
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.baseColor, b.baseColor) << what;
  EXPECT_EQ(a.alpha, b.alpha) << what;
  EXPECT_EQ(a.metallic, b.metallic) << what;
  EXPECT_EQ(a.roughness, b.roughness) << what;
  EXPECT_EQ(a.emissive, b.emissive) << what;
  EXPECT_EQ(a.ior, b.ior) << what;
  expectSameRef(a.baseColorTexture, b.baseColorTexture, what + " baseColorTexture");
  expectSameRef(a.metallicRoughnessTexture, b.metallicRoughnessTexture, what + " metallicRoughnessTexture");
  expectSameRef(a.normalTexture, b.normalTexture, what + " normalTexture");
  expectSameRef(a.occlusionTexture, b.occlusionTexture, what + " occlusionTexture");
  expectSameRef(a.emissiveTexture, b.emissiveTexture, what + " emissiveTexture");
  EXPECT_EQ(a.normalScale, b.normalScale) << what;
  EXPECT_EQ(a.occlusionStrength, b.occlusionStrength) << what;
  EXPECT_EQ(a.alphaMode, b.alphaMode) << what;
  if (a.alphaMode == AlphaMode::Mask) {
    EXPECT_EQ(a.alphaCutoff, b.alphaCutoff) << what;
  }
  EXPECT_EQ(a.doubleSided, b.doubleSided) << what;
}

// The bake's own loader reads scene.glb back to the same textures, images (bytes and pixels) and
// material slots, and the same TEXCOORD_1 and TANGENT.
TEST(BakedSceneGltf, TexturedSceneLoadsBackAsTheSameTexturesAndMaterials) {
  const Scene scene = texturedScene();
  const std::filesystem::path file = test::scratchDir() / "textured.glb";
  writeSceneGlb(scene, file);
  const GltfContents back = loadGltf(file);

  ASSERT_EQ(back.images.size(), scene.images.size());
  for (std::size_t i = 0; i < scene.images.size(); ++i) {
    EXPECT_EQ(back.images[i].encoded, scene.images[i].encoded) << "image " << i;
    EXPECT_EQ(back.images[i].mimeType, scene.images[i].mimeType) << "image " << i;
    EXPECT_EQ(back.images[i].name, scene.images[i].name) << "image " << i;
    EXPECT_EQ(back.images[i].width, scene.images[i].width) << "image " << i;
    EXPECT_EQ(back.images[i].height, scene.images[i].height) << "image " << i;
  }
  EXPECT_EQ(back.images[0].rgba, rgbaPattern(4, 4));  // PNG and lossless WebP keep every byte
  EXPECT_EQ(back.images[2].rgba, rgbaPattern(2, 4));
  ASSERT_EQ(back.textures.size(), scene.textures.size());
  for (std::size_t t = 0; t < scene.textures.size(); ++t) {
    EXPECT_EQ(back.textures[t].image, scene.textures[t].image) << "texture " << t;
    expectSameSampler(back.textures[t].sampler, scene.textures[t].sampler, "texture " + std::to_string(t));
  }
  ASSERT_GE(back.materials.size(), scene.materials.size());
  for (std::size_t m = 0; m < scene.materials.size(); ++m) expectSameMaterial(scene.materials[m], back.materials[m]);

  ASSERT_EQ(back.meshes.size(), scene.meshes.size());
  EXPECT_EQ(back.meshes[0].texcoords1, scene.meshes[0].texcoords1);
  EXPECT_EQ(back.meshes[0].colors, scene.meshes[0].colors);  // COLOR_0, VEC4 float
  EXPECT_TRUE(back.meshes[1].colors.empty());
  ASSERT_EQ(back.meshes[0].tangents.size(), scene.meshes[0].tangents.size());
  for (std::size_t v = 0; v < scene.meshes[0].tangents.size(); ++v)
    EXPECT_LT(glm::distance(back.meshes[0].tangents[v], scene.meshes[0].tangents[v]), 1e-6f) << "vertex " << v;
}

TEST(BakedSceneGltf, BadTextureReferencesAreErrorsAndLeaveNoFile) {
  const std::filesystem::path file = test::scratchDir() / "bad_texture.glb";
  Scene slot = texturedScene();
  slot.materials[1].occlusionTexture.texture = 4;
  EXPECT_EQ(test::errorMessage([&] { writeSceneGlb(slot, file); }),
            file.string() + ": material 1 (lamp) occlusionTexture: texture 4 does not exist");
  Scene texCoord = texturedScene();
  texCoord.materials[1].normalTexture.texCoord = 2;
  EXPECT_EQ(test::errorMessage([&] { writeSceneGlb(texCoord, file); }),
            file.string() + ": material 1 (lamp) normalTexture: texCoord 2 is not 0 or 1");
  Scene source = texturedScene();
  source.textures[2].image = 3;
  EXPECT_EQ(test::errorMessage([&] { writeSceneGlb(source, file); }),
            file.string() + ": texture 2: image 3 does not exist");
  Scene noBytes = texturedScene();
  noBytes.images[1].encoded.clear();
  EXPECT_EQ(test::errorMessage([&] { writeSceneGlb(noBytes, file); }),
            file.string() + ": image 1 (ao) has no encoded bytes to copy");
  Scene tangents = texturedScene();
  tangents.meshes[0].tangents.pop_back();
  EXPECT_EQ(test::errorMessage([&] { writeSceneGlb(tangents, file); }),
            file.string() + ": mesh 0 (sphere): normals, texture coordinates, tangents or colours do not match the "
                            "42 vertices");
  Scene colors = texturedScene();
  colors.meshes[0].colors.pop_back();
  EXPECT_EQ(test::errorMessage([&] { writeSceneGlb(colors, file); }),
            file.string() + ": mesh 0 (sphere): normals, texture coordinates, tangents or colours do not match the "
                            "42 vertices");
  EXPECT_FALSE(std::filesystem::exists(file));
}

// The real iblkit-bake on a textured glb (one image embedded in a buffer view, one a file beside
// it): the bake's scene.glb holds both images' bytes unchanged, the sampler and the slots.
TEST(BakedSceneGltf, IblkitBakeKeepsATexturedGltfsImagesAndSlots) {
  const std::filesystem::path dir = test::scratchDir() / "bake_textured";
  std::filesystem::create_directories(dir);
  const std::vector<std::uint8_t> png = encodePng(4, 4), jpeg = encodeJpeg(8, 8);
  std::ofstream(dir / "wood.jpg", std::ios::binary).write(reinterpret_cast<const char*>(jpeg.data()), jpeg.size());

  test::GltfBuilder builder;
  const std::vector<glm::vec3> positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
  const std::vector<glm::vec3> normals(4, glm::vec3(0, 1, 0));
  const std::vector<glm::vec2> uvs = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  builder.addPrimitiveNode({{"attributes",
                             {{"POSITION", builder.addFloats(positions)},
                              {"NORMAL", builder.addFloats(normals)},
                              {"TEXCOORD_0", builder.addFloats(uvs)}}},
                            {"indices", builder.addIndices({0, 2, 1, 0, 3, 2})},
                            {"material", 0}});
  json& doc = builder.document();
  doc["images"] = {{{"bufferView", builder.addBufferView(png.data(), png.size())}, {"mimeType", "image/png"}},
                   {{"uri", "wood.jpg"}}};
  doc["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9984}, {"wrapS", 33648}, {"wrapT", 33071}}};
  doc["textures"] = {{{"source", 0}, {"sampler", 0}}, {{"source", 1}}};
  doc["materials"] = {{{"name", "tiles"},
                       {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0.0}}},
                       {"occlusionTexture", {{"index", 1}, {"strength", 0.5}}},
                       {"alphaMode", "MASK"},
                       {"doubleSided", true}}};
  builder.write(dir / "tiles.glb", test::GltfBuilder::Storage::Glb);

  std::string output;
  const int status = test::runCommand("timeout 120 " + test::shellQuoted(test::binDir() / "iblkit-bake") + " " +
                                          test::shellQuoted(dir / "tiles.glb") + " -o " +
                                          test::shellQuoted(dir / "baked") + " --ao-rays 4 2>&1",
                                      &output);
  ASSERT_EQ(status, 0) << output;
  const GlbChunks glb = readGlb(dir / "baked" / "scene.glb");
  ASSERT_TRUE(glb.document.contains("images")) << glb.document.dump();
  ASSERT_EQ(glb.document["images"].size(), 2u);
  EXPECT_EQ(imageBytes(glb, 0), png);
  EXPECT_EQ(imageBytes(glb, 1), jpeg);
  EXPECT_EQ(glb.document["images"][1]["mimeType"], "image/jpeg");
  EXPECT_EQ(glb.document["samplers"][0],
            json::parse(R"({"magFilter": 9728, "minFilter": 9984, "wrapS": 33648, "wrapT": 33071})"));
  const json& material = glb.document["materials"][0];
  EXPECT_EQ(glb.document["textures"][material["pbrMetallicRoughness"]["baseColorTexture"]["index"].get<int>()]["source"], 0);
  EXPECT_EQ(material["occlusionTexture"]["strength"], 0.5);
  EXPECT_EQ(material["alphaMode"], "MASK");
  EXPECT_EQ(material["doubleSided"], true);
  const json& attributes = glb.document["meshes"][0]["primitives"][0]["attributes"];
  EXPECT_TRUE(attributes.contains("TEXCOORD_0"));
  EXPECT_TRUE(attributes.contains("_AO"));
}

// The bundled pmndrs.glb (CC0, assets/fetch.sh): the bake's scene.glb holds its JPEG byte for byte,
// its sampler and its material's doubleSided and baseColorTexture.
TEST(BakedSceneGltf, IblkitBakeKeepsTheBundledPmndrsTexture) {
  const std::filesystem::path model = test::assetsDir() / "models" / "pmndrs.glb";
  ASSERT_TRUE(std::filesystem::is_regular_file(model)) << "run assets/fetch.sh";
  const std::filesystem::path out = test::scratchDir() / "pmndrs";
  std::string output;
  ASSERT_EQ(test::runCommand("timeout 120 " + test::shellQuoted(test::binDir() / "iblkit-bake") + " " +
                                 test::shellQuoted(model) + " -o " + test::shellQuoted(out) + " --ao-rays 4 2>&1",
                             &output),
            0)
      << output;
  const GlbChunks source = readGlb(model), baked = readGlb(out / "scene.glb");
  ASSERT_EQ(baked.document["images"].size(), source.document["images"].size());
  EXPECT_EQ(imageBytes(baked, 0), imageBytes(source, 0));
  EXPECT_EQ(baked.document["images"][0]["mimeType"], "image/jpeg");
  EXPECT_EQ(baked.document["samplers"][0], source.document["samplers"][0]);
  const json& material = baked.document["materials"][0];
  EXPECT_EQ(material["doubleSided"], true);
  EXPECT_EQ(material["pbrMetallicRoughness"]["baseColorTexture"]["index"], 0);
  EXPECT_TRUE(baked.document["meshes"][0]["primitives"][0]["attributes"].contains("TEXCOORD_0"));
}

}  // namespace
}  // namespace iblkit
