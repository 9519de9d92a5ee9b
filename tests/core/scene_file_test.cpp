#include "core/scene_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "support/gltf_builder.h"
#include "support/texture_files.h"
#include "support/test_paths.h"
#include "support/warning_capture.h"

namespace iblkit {
namespace {

using nlohmann::json;

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// A scene folder: models/cube.gltf (the unit cube, one material), hdri/sky.exr (a stand-in file:
// scenes only check that it exists) and scenes/, where each test writes its .json.
class SceneFile : public ::testing::Test {
 protected:
  void SetUp() override {
    std::filesystem::create_directories(root / "models");
    std::filesystem::create_directories(root / "hdri");
    std::filesystem::create_directories(root / "scenes");
    test::GltfBuilder builder;
    const test::CubeGeometry cube = test::unitCube();
    builder.document()["materials"] = {
        {{"name", "white"}, {"pbrMetallicRoughness", {{"roughnessFactor", 0.25}}}}};
    builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(cube.positions)}}},
                              {"indices", builder.addIndices(cube.indices)},
                              {"material", 0}});
    builder.write(root / "models" / "cube.gltf", test::GltfBuilder::Storage::BinFile);
    std::ofstream(root / "hdri" / "sky.exr") << "stand-in";
  }

  Scene load(const json& document) {
    const std::filesystem::path path = root / "scenes" / "scene.json";
    std::ofstream(path) << document.dump(2);
    return loadSceneFile(path);
  }

  // The message after "<scene.json path>: ".
  std::string error(const json& document) {
    try {
      load(document);
    } catch (const Error& e) {
      const std::string prefix = (root / "scenes" / "scene.json").string() + ": ";
      const std::string message = e.what();
      return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
    }
    return "(no error)";
  }

  static json cubeModel() { return {{"file", "../models/cube.gltf"}}; }

  test::WarningCapture warnings;  // the cube has no normals: generated with a warning
  std::filesystem::path root = test::scratchDir();
};

TEST_F(SceneFile, FullSceneDescription) {
  const float s = std::sqrt(0.5f);
  const Scene scene =
      load({{"models",
             {{{"file", "../models/cube.gltf"},
               {"translation", {10, 0, 0}},
               {"rotation", {0, s, 0, s}},
               {"scale", 2},
               {"material", {{"baseColor", {0.5, 0.25, 1}}, {"metallic", 1}, {"specular", 0.5}, {"ior", 1.33}}}},
              {{"file", "../models/cube.gltf"}, {"scale", {1, 3, 1}}}}},
            {"ground", {{"material", {{"roughness", 0.75}}}}},
            {"environment", {{"file", "../hdri/sky.exr"}, {"rotation", 90}, {"intensity", 2}}},
            {"camera", {{"position", {0, 1, 10}}, {"target", {0, 1, 0}}, {"yfov", 30}}},
            {"width", 320},
            {"height", 200}});
  ASSERT_EQ(scene.meshes.size(), 3u);  // two cubes and the ground
  ASSERT_EQ(scene.modelFiles.size(), 2u);
  EXPECT_EQ(scene.modelFiles[0], (root / "models" / "cube.gltf").lexically_normal());

  // First cube: scale 2, then 90 degrees about +Y ((x, y, z) -> (z, y, -x)), then +10 in x.
  const Mesh& first = scene.meshes[0];
  expectNear(first.positions[7], glm::vec3(12, 2, -2));  // corner (1, 1, 1)
  expectNear(first.normals[7], glm::normalize(glm::vec3(1, 1, -1)));
  EXPECT_EQ(first.source.model, 0);
  EXPECT_EQ(scene.meshes[1].source.model, 1);
  expectNear(scene.meshes[1].positions[7], glm::vec3(1, 3, 1));

  // Each model gets its own copy of its materials, with the overrides applied.
  ASSERT_EQ(scene.materials.size(), 3u);
  const Material& overridden = scene.materials[first.material];
  EXPECT_EQ(overridden.baseColor, glm::vec3(0.5f, 0.25f, 1.0f));
  EXPECT_EQ(overridden.metallic, 1.0f);
  EXPECT_EQ(overridden.roughness, 0.25f);  // from the file
  EXPECT_EQ(overridden.specular, 0.5f);
  EXPECT_EQ(overridden.ior, 1.33f);
  EXPECT_EQ(scene.materials[scene.meshes[1].material].ior, 1.5f);
  EXPECT_EQ(scene.materials[scene.meshes[1].material].baseColor, glm::vec3(1.0f));

  // The ground: under the objects (default height = lowest point), 10 bounding radii wide.
  expectNear(scene.bounds.min, glm::vec3(0, 0, -2));
  expectNear(scene.bounds.max, glm::vec3(12, 3, 1));
  const Mesh& ground = scene.meshes[2];
  EXPECT_TRUE(ground.isGround);
  EXPECT_EQ(ground.source.model, -1);
  const Bounds groundBounds = ground.bounds();
  EXPECT_FLOAT_EQ(groundBounds.min.y, 0.0f);
  EXPECT_FLOAT_EQ(groundBounds.max.y, 0.0f);
  EXPECT_FLOAT_EQ(groundBounds.max.x - groundBounds.min.x, 10.0f * scene.bounds.radius());
  expectNear(groundBounds.center(), glm::vec3(6, 0, -0.5f));
  for (std::size_t t = 0; t < ground.triangleCount(); ++t) {
    const glm::vec3& a = ground.positions[ground.indices[3 * t]];
    const glm::vec3 n = glm::cross(ground.positions[ground.indices[3 * t + 1]] - a,
                                   ground.positions[ground.indices[3 * t + 2]] - a);
    EXPECT_GT(n.y, 0.0f);  // front face up
  }
  // A grid that tiles the square: its triangles' areas add up to the square's, and it is finer in
  // the middle, under the objects, than at the rim (the baker's per-vertex AO needs vertices where
  // the objects occlude the sky; four corners have none).
  double area = 0.0;
  float middleEdge = 1e30f, rimEdge = 0.0f;
  const float side = groundBounds.max.x - groundBounds.min.x;
  for (std::size_t t = 0; t < ground.triangleCount(); ++t) {
    const glm::vec3& a = ground.positions[ground.indices[3 * t]];
    const glm::vec3& b = ground.positions[ground.indices[3 * t + 1]];
    const glm::vec3& c = ground.positions[ground.indices[3 * t + 2]];
    area += 0.5 * double(glm::length(glm::cross(b - a, c - a)));
    const float edge = glm::length(b - a);
    const float fromCentre = std::max(std::abs(a.x - groundBounds.center().x), std::abs(a.z - groundBounds.center().z));
    if (fromCentre < 0.05f * side) middleEdge = std::min(middleEdge, edge);
    if (fromCentre > 0.45f * side) rimEdge = std::max(rimEdge, edge);
  }
  EXPECT_NEAR(area, double(side) * double(side), 1e-4 * double(side) * double(side));
  EXPECT_GE(ground.positions.size(), 1000u);
  EXPECT_LT(middleEdge * 3.0f, rimEdge) << middleEdge << " " << rimEdge;
  EXPECT_LT(middleEdge, 0.02f * side);
  const Material& groundMaterial = scene.materials.at(ground.material);
  EXPECT_EQ(groundMaterial.baseColor, glm::vec3(0.5f));
  EXPECT_EQ(groundMaterial.metallic, 0.0f);
  EXPECT_EQ(groundMaterial.roughness, 0.75f);

  EXPECT_EQ(scene.environment.file, (root / "hdri" / "sky.exr").lexically_normal());
  EXPECT_EQ(scene.environment.rotationDegrees, 90.0f);
  EXPECT_EQ(scene.environment.intensity, 2.0f);
  ASSERT_TRUE(scene.camera.has_value());
  expectNear(scene.camera->forward, glm::vec3(0, 0, -1));
  EXPECT_FLOAT_EQ(scene.camera->yfovRadians, glm::radians(30.0f));
  const ClipPlanes clip = clipPlanesFor(glm::vec3(0, 1, 10), scene.bounds);
  EXPECT_FLOAT_EQ(scene.camera->znear, clip.znear);
  EXPECT_FLOAT_EQ(scene.camera->zfar, clip.zfar);
  EXPECT_EQ(scene.width, 320);
  EXPECT_EQ(scene.height, 200);
}

TEST_F(SceneFile, Defaults) {
  const Scene scene = load({{"models", {cubeModel()}}});
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_FALSE(scene.camera.has_value());
  EXPECT_TRUE(scene.environment.file.empty());
  EXPECT_EQ(scene.environment.intensity, 1.0f);
  EXPECT_EQ(scene.width, kDefaultImageWidth);
  EXPECT_EQ(scene.height, kDefaultImageHeight);
  EXPECT_EQ(scene.meshes[0].positions[7], glm::vec3(1, 1, 1));

  const Scene withGround = load({{"models", {cubeModel()}}, {"ground", {{"height", -1}, {"size", 4}}}});
  const Bounds ground = withGround.meshes.at(1).bounds();
  EXPECT_EQ(ground.min, glm::vec3(-1.5f, -1.0f, -1.5f));
  EXPECT_EQ(ground.max, glm::vec3(2.5f, -1.0f, 2.5f));
  EXPECT_EQ(load({{"models", {cubeModel()}}, {"ground", {{"enabled", false}}}}).meshes.size(), 1u);
}

TEST_F(SceneFile, BuiltInSphereShape) {
  const Scene scene = load({{"models",
                             {{{"shape", "sphere"},
                               {"translation", {0, 2, 0}},
                               {"scale", 0.5},
                               {"material", {{"metallic", 1}, {"roughness", 0}}}}}}});
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& sphere = scene.meshes[0];
  for (std::size_t i = 0; i < sphere.positions.size(); ++i) {
    ASSERT_NEAR(glm::length(sphere.positions[i] - glm::vec3(0, 2, 0)), 0.5f, 1e-5f);
    ASSERT_NEAR(glm::dot(sphere.normals[i], (sphere.positions[i] - glm::vec3(0, 2, 0)) / 0.5f), 1.0f, 1e-5f);
  }
  expectNear(scene.bounds.min, glm::vec3(-0.5f, 1.5f, -0.5f));
  expectNear(scene.bounds.max, glm::vec3(0.5f, 2.5f, 0.5f));
  const Material& material = scene.materials.at(std::size_t(sphere.material));
  EXPECT_EQ(material.baseColor, glm::vec3(1.0f));
  EXPECT_EQ(material.metallic, 1.0f);
  EXPECT_EQ(material.roughness, 0.0f);

  EXPECT_EQ(error({{"models", {{{"shape", "cube"}}}}}), "models[0].shape: expected \"sphere\"");
  EXPECT_EQ(error({{"models", {{{"shape", "sphere"}, {"file", "../models/cube.gltf"}}}}}),
            "models[0]: needs exactly one of 'file' and 'shape'");
  EXPECT_EQ(error({{"models", {json::object()}}}), "models[0]: needs exactly one of 'file' and 'shape'");
}

TEST_F(SceneFile, NegativeScaleMirrorsWithOutwardNormals) {
  const Scene scene = load({{"models", {{{"file", "../models/cube.gltf"}, {"scale", {-1, 1, 1}}}}}});
  const Mesh& m = scene.meshes.at(0);
  expectNear(m.normals[7], glm::normalize(glm::vec3(-1, 1, 1)));  // corner (1, 1, 1) -> (-1, 1, 1)
  for (std::size_t t = 0; t < m.triangleCount(); ++t) {
    const glm::vec3& a = m.positions[m.indices[3 * t]];
    const glm::vec3 n =
        glm::cross(m.positions[m.indices[3 * t + 1]] - a, m.positions[m.indices[3 * t + 2]] - a);
    const glm::vec3 outward =
        (a + m.positions[m.indices[3 * t + 1]] + m.positions[m.indices[3 * t + 2]]) / 3.0f -
        glm::vec3(-0.5f, 0.5f, 0.5f);
    EXPECT_GT(glm::dot(n, outward), 0.0f) << "triangle " << t;
  }
}

TEST_F(SceneFile, UnknownKeysAndWrongTypesNameTheKeyPath) {
  const json model = cubeModel();
  EXPECT_EQ(error({{"models", {{{"file", "../models/cube.gltf"}, {"scael", 2}}}}}),
            "models[0].scael: unknown key (expected one of: file, shape, translation, rotation, scale, material)");
  EXPECT_EQ(error({{"models", {model}}, {"camrea", {}}}),
            "camrea: unknown key (expected one of: models, ground, environment, camera, width, height)");
  EXPECT_EQ(error({{"models", {model}}, {"ground", {{"material", {{"colour", {1, 1, 1}}}}}}}),
            "ground.material.colour: unknown key (expected one of: baseColor, metallic, roughness, specular, "
            "specularColor, ior, emissive, alpha, alphaMode, alphaCutoff, doubleSided, baseColorTexture, "
            "metallicRoughnessTexture, normalTexture, occlusionTexture, emissiveTexture)");
  EXPECT_EQ(error({{"models", {{{"file", "../models/cube.gltf"}, {"scale", "big"}}}}}),
            "models[0].scale: expected a nonzero number or an array of 3 nonzero numbers");
  EXPECT_EQ(error({{"models", {{{"file", "../models/cube.gltf"}, {"scale", {1, 0, 1}}}}}}),
            "models[0].scale: expected a nonzero number or an array of 3 nonzero numbers");
  EXPECT_EQ(error({{"models", {{{"file", "../models/cube.gltf"}, {"translation", {1, 2}}}}}}),
            "models[0].translation: expected an array of 3 numbers");
  EXPECT_EQ(error({{"models", {{{"file", "../models/cube.gltf"}, {"rotation", {0, 0, 0, 0}}}}}}),
            "models[0].rotation: expected a quaternion [x, y, z, w] (not all zero)");
  EXPECT_EQ(error({{"models", {{{"file", "../models/cube.gltf"}, {"material", {{"roughness", 2}}}}}}}),
            "models[0].material.roughness: expected a number in [0, 1]");
  EXPECT_EQ(error({{"models", {{{"file", "../models/cube.gltf"}, {"material", {{"ior", 0.5}}}}}}}),
            "models[0].material.ior: expected a number in [1, 1000]");
  EXPECT_EQ(error({{"models", {{{"file", "../models/cube.gltf"}, {"material", {{"baseColor", {1, 1}}}}}}}}),
            "models[0].material.baseColor: expected an array of 3 numbers in [0, 1]");
  EXPECT_EQ(error({{"models", {{{"translation", {0, 0, 0}}}}}}), "models[0]: needs exactly one of 'file' and 'shape'");
  EXPECT_EQ(error({{"models", json::array()}}), "models: expected a non-empty array of models");
  EXPECT_EQ(error(json::object()), "the document: missing required key 'models'");
  EXPECT_EQ(error(json::array()), "the document: expected an object");
  EXPECT_EQ(error({{"models", {model}}, {"width", 0}}), "width: expected an integer in [1, 16384]");
  EXPECT_EQ(error({{"models", {model}}, {"height", 1.5}}), "height: expected an integer in [1, 16384]");
  EXPECT_EQ(error({{"models", {model}}, {"ground", {{"enabled", 1}}}}),
            "ground.enabled: expected true or false");
  EXPECT_EQ(error({{"models", {model}}, {"environment", {{"file", "../hdri/missing.exr"}}}}),
            "environment.file: '../hdri/missing.exr' does not exist");
  EXPECT_EQ(error({{"models", {model}}, {"environment", {{"file", "../hdri/sky.exr"}, {"intensity", -1}}}}),
            "environment.intensity: expected a number >= 0");
  EXPECT_EQ(error({{"models", {model}}, {"camera", {{"position", {0, 0, 5}}}}}),
            "camera: missing required key 'target'");
  EXPECT_EQ(error({{"models", {model}}, {"camera", {{"position", {0, 5, 0}}, {"target", {0, 0, 0}}}}}),
            "camera.up: expected a direction not parallel to the view direction");
  EXPECT_EQ(error({{"models", {model}},
                   {"camera", {{"position", {0, 0, 5}}, {"target", {0, 0, 0}}, {"yfov", 180}}}}),
            "camera.yfov: expected degrees in (0, 180)");
}

TEST_F(SceneFile, BrokenFilesAreErrors) {
  const std::filesystem::path path = root / "scenes" / "broken.json";
  std::ofstream(path) << "{\"models\": [";
  try {
    loadSceneFile(path);
    FAIL() << "loaded";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path.string() + ": invalid JSON: [json.exception.parse_error", 0),
              0u)
        << e.what();
  }
  // A model that fails to load names the model file.
  try {
    load({{"models", {{{"file", "../models/missing.gltf"}}}}});
    FAIL() << "loaded";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), (root / "models" / "missing.gltf").string() + ": cannot open: No such file or directory");
  }
}

// models/quad.gltf: a textured unit quad (its own baseColorTexture, maps/albedo.png beside it).
void writeTexturedQuad(const std::filesystem::path& models) {
  std::filesystem::create_directories(models / "maps");
  test::writeFileBytes(models / "maps" / "albedo.png", test::encodePng(2, 2, test::quadPixels()));
  test::GltfBuilder builder;
  const std::vector<glm::vec3> positions = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(1, 1, 0), glm::vec3(0, 1, 0)};
  const std::vector<glm::vec2> uvs = {glm::vec2(0, 1), glm::vec2(1, 1), glm::vec2(1, 0), glm::vec2(0, 0)};
  builder.addPrimitiveNode({{"attributes",
                             {{"POSITION", builder.addFloats(positions)},
                              {"NORMAL", builder.addFloats(std::vector<glm::vec3>(4, glm::vec3(0, 0, 1)))},
                              {"TEXCOORD_0", builder.addFloats(uvs)}}},
                            {"indices", builder.addIndices({0, 1, 2, 0, 2, 3})},
                            {"material", 0}});
  builder.document()["images"] = {{{"uri", "maps/albedo.png"}}};
  builder.document()["textures"] = {{{"source", 0}}};
  builder.document()["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  builder.write(models / "quad.gltf", test::GltfBuilder::Storage::BinFile);
}

TEST_F(SceneFile, MaterialOverridesAssignTextures) {
  writeTexturedQuad(root / "models");
  std::filesystem::create_directories(root / "normals");
  const std::vector<std::uint8_t> normal(4 * 4 * 4, 128);
  test::writeFileBytes(root / "normals" / "0001.webp", test::encodeWebp(4, 4, normal));
  const json normalMap = {{"file", "../normals/0001.webp"}, {"scale", 0.5}, {"uvScale", {4, 2}}};
  const Scene scene = load(
      {{"models",
        {{{"file", "../models/quad.gltf"}},
         {{"file", "../models/quad.gltf"}, {"material", {{"normalTexture", normalMap}, {"doubleSided", true}}}},
         {{"shape", "sphere"},
          {"material", {{"normalTexture", {{"file", "../normals/0001.webp"}}}, {"alphaMode", "MASK"}}}}}},
       {"ground", {{"material", {{"occlusionTexture", {{"file", "../normals/0001.webp"}, {"strength", 0.25}, {"uvScale", 8}}}}}}}});

  // Each model loads its own copy of quad.gltf's texture; the override file is read once.
  ASSERT_EQ(scene.images.size(), 3u);
  ASSERT_EQ(scene.textures.size(), 3u);
  EXPECT_EQ(scene.images[2].file, root / "normals" / "0001.webp");
  EXPECT_EQ(scene.images[2].mimeType, "image/webp");
  EXPECT_EQ(scene.images[2].width, 4);
  for (int t = 0; t < 3; ++t) EXPECT_EQ(scene.textures[t].image, t);
  const TextureSampler& sampler = scene.textures[2].sampler;  // repeat, trilinear
  EXPECT_EQ(sampler.wrapS, TextureWrap::Repeat);
  EXPECT_EQ(sampler.wrapT, TextureWrap::Repeat);
  EXPECT_TRUE(sampler.mipmaps);

  ASSERT_EQ(scene.materials.size(), 4u);
  EXPECT_EQ(scene.materials[0].baseColorTexture.texture, 0);
  EXPECT_FALSE(scene.materials[0].normalTexture.present());
  const Material& second = scene.materials[1];
  EXPECT_EQ(second.baseColorTexture.texture, 1);  // offset past model 0's texture
  EXPECT_EQ(second.normalTexture.texture, 2);
  EXPECT_EQ(second.normalTexture.texCoord, 0);
  EXPECT_EQ(second.normalTexture.transform.scale, glm::vec2(4.0f, 2.0f));
  EXPECT_EQ(second.normalScale, 0.5f);
  EXPECT_TRUE(second.doubleSided);
  EXPECT_EQ(scene.materials[2].normalTexture.texture, 2);
  EXPECT_TRUE(scene.materials[2].normalTexture.transform.identity());
  EXPECT_EQ(scene.materials[2].alphaMode, AlphaMode::Mask);
  const Material& ground = scene.materials[3];
  EXPECT_EQ(ground.occlusionTexture.texture, 2);
  EXPECT_EQ(ground.occlusionStrength, 0.25f);
  EXPECT_EQ(ground.occlusionTexture.transform.scale, glm::vec2(8.0f));
  // A textured ground gets uvs spanning [0, 1], u along +X, v along +Z.
  const Mesh& groundMesh = scene.meshes.back();
  ASSERT_TRUE(groundMesh.isGround);
  ASSERT_EQ(groundMesh.texcoords.size(), groundMesh.positions.size());
  for (std::size_t i = 0; i < groundMesh.positions.size(); ++i) {
    const glm::vec3& p = groundMesh.positions[i];
    const glm::vec3 size = groundMesh.bounds().max - groundMesh.bounds().min;
    EXPECT_NEAR(groundMesh.texcoords[i].x, (p.x - groundMesh.bounds().min.x) / size.x, 1e-5f);
    EXPECT_NEAR(groundMesh.texcoords[i].y, (p.z - groundMesh.bounds().min.z) / size.z, 1e-5f);
  }
  EXPECT_EQ(scene.meshes[0].material, 0);
  EXPECT_EQ(scene.meshes[1].material, 1);
}

TEST_F(SceneFile, BadTextureOverridesNameTheKey) {
  std::filesystem::create_directories(root / "normals");
  test::writeFileBytes(root / "normals" / "broken.webp", {'R', 'I', 'F', 'F', 4, 0, 0, 0, 'W', 'E', 'B', 'P', 'V', 'P', '8', ' '});
  const auto withNormal = [&](const json& texture) {
    return json{{"models", {{{"shape", "sphere"}, {"material", {{"normalTexture", texture}}}}}}};
  };
  EXPECT_EQ(error(withNormal({{"file", "../normals/missing.webp"}})),
            "models[0].material.normalTexture '../normals/missing.webp': " + (root / "normals" / "missing.webp").string() +
                ": cannot open: No such file or directory");
  EXPECT_EQ(error(withNormal({{"file", "../normals/broken.webp"}})),
            "models[0].material.normalTexture '../normals/broken.webp': WebP does not decode (bitstream error)");
  EXPECT_EQ(error(withNormal({{"uvScale", 2}})), "models[0].material.normalTexture: missing required key 'file'");
  EXPECT_EQ(error(withNormal({{"file", "x.png"}, {"strength", 1}})),
            "models[0].material.normalTexture.strength: unknown key (expected one of: file, uvScale, texCoord, scale)");
  test::writeFileBytes(root / "normals" / "flat.png", test::encodePng(2, 2, test::quadPixels()));
  EXPECT_EQ(error(withNormal({{"file", "../normals/flat.png"}, {"uvScale", {0, 1}}})),
            "models[0].material.normalTexture.uvScale: expected a nonzero number or an array of 2 nonzero numbers, "
            "within +-1e6");
  // 1e39 is a finite double but an infinite float scale.
  EXPECT_EQ(error(withNormal({{"file", "../normals/flat.png"}, {"uvScale", 1e39}})),
            "models[0].material.normalTexture.uvScale: expected a nonzero number or an array of 2 nonzero numbers, "
            "within +-1e6");
  EXPECT_NE(error(withNormal({{"file", "../normals/flat.png"}, {"scale", 1e39}})).find("models[0].material.normalTexture.scale"),
            std::string::npos);
  EXPECT_EQ(error(withNormal({{"file", "../normals/flat.png"}, {"texCoord", 2}})),
            "models[0].material.normalTexture.texCoord: expected an integer in [0, 1]");
  EXPECT_EQ(error({{"models", {{{"shape", "sphere"}, {"material", {{"alphaMode", "CLIP"}}}}}}}),
            "models[0].material.alphaMode: expected \"OPAQUE\", \"MASK\" or \"BLEND\"");
}

}  // namespace
}  // namespace iblkit
