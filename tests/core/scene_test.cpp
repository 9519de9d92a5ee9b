#include "core/scene.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "support/gltf_builder.h"
#include "support/texture_files.h"
#include "support/test_paths.h"
#include "support/warning_capture.h"

namespace iblkit {
namespace {

class SceneLoad : public ::testing::Test {
 protected:
  // A triangle glTF under `name`, with or without a camera.
  std::filesystem::path writeTriangle(const std::string& name, bool camera) {
    test::GltfBuilder builder;
    const std::vector<glm::vec3> triangle = {glm::vec3(0, 0, 0), glm::vec3(2, 0, 0), glm::vec3(0, 2, 0)};
    builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(triangle)}}}});
    if (camera) {
      builder.document()["cameras"] = {
          {{"type", "perspective"}, {"perspective", {{"yfov", 0.6}, {"znear", 0.1}, {"zfar", 100}}}}};
      builder.addNode({{"camera", 0}, {"translation", {0, 0, 9}}});
    }
    const std::filesystem::path path = scratch / name;
    builder.write(path, name.ends_with(".gltf") ? test::GltfBuilder::Storage::DataUri
                                                : test::GltfBuilder::Storage::Glb);
    return path;
  }

  test::WarningCapture warnings;
  std::filesystem::path scratch = test::scratchDir();
};

TEST_F(SceneLoad, GltfFilesAreScenesOfTheirOwn) {
  const Scene scene = loadScene(writeTriangle("MODEL.GLB", true));
  ASSERT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.modelFiles.size(), 1u);
  EXPECT_EQ(scene.modelFiles[0], scratch / "MODEL.GLB");
  EXPECT_EQ(scene.bounds.min, glm::vec3(0, 0, 0));
  EXPECT_EQ(scene.bounds.max, glm::vec3(2, 2, 0));
  EXPECT_TRUE(scene.environment.file.empty());
  EXPECT_EQ(scene.width, kDefaultImageWidth);
  ASSERT_TRUE(scene.camera.has_value());
  EXPECT_EQ(sceneCamera(scene, 2.0f).position, glm::vec3(0, 0, 9));
}

TEST_F(SceneLoad, SceneCameraFramesScenesWithoutOne) {
  const Scene scene = loadScene(writeTriangle("model.gltf", false));
  EXPECT_FALSE(scene.camera.has_value());
  const Camera framed = frameBounds(scene.bounds, 1.5f);
  const Camera camera = sceneCamera(scene, 1.5f);
  EXPECT_EQ(camera.position, framed.position);
  EXPECT_EQ(camera.forward, framed.forward);
  EXPECT_EQ(camera.zfar, framed.zfar);
}

// A slot reading a TEXCOORD set the mesh lacks reads uv (0, 0): the set is filled, with a warning,
// so that every program can index it; a normal-mapped mesh also gets its tangents generated.
TEST_F(SceneLoad, MissingTexcoordsAreFilledForTexturedSlots) {
  test::GltfBuilder builder;
  const std::vector<glm::vec3> triangle = {glm::vec3(0, 0, 0), glm::vec3(2, 0, 0), glm::vec3(0, 2, 0)};
  builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(triangle)}}}, {"material", 0}});
  const std::vector<std::uint8_t> png = test::encodePng(2, 2, test::quadPixels());
  builder.addImage(png, "image/png");
  builder.document()["textures"] = {{{"source", 0}}};
  builder.document()["materials"] = {{{"name", "stone"}, {"normalTexture", {{"index", 0}, {"texCoord", 1}}}}};
  const std::filesystem::path path = scratch / "model.glb";
  builder.write(path, test::GltfBuilder::Storage::Glb);
  const Scene scene = loadScene(path);
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_TRUE(scene.meshes[0].texcoords.empty());
  EXPECT_EQ(scene.meshes[0].texcoords1, std::vector<glm::vec2>(3, glm::vec2(0.0f)));
  EXPECT_EQ(scene.meshes[0].tangents.size(), 3u);
  EXPECT_TRUE(warnings.contains(path.string() + ": warning: mesh 0 primitive 0: material 'stone' reads TEXCOORD_1, "
                                                "which the mesh does not have; its textures read uv (0, 0)"));
  ASSERT_EQ(scene.images.size(), 1u);
  EXPECT_EQ(scene.images[0].encoded, png);
}

// A normal-mapped quad with its image upright (glTF uv v = 1 - y), with or without TANGENT, under
// a node with `scale`.
std::filesystem::path writeNormalMappedQuad(const std::filesystem::path& path, bool withTangents,
                                            glm::vec3 scale) {
  test::GltfBuilder builder;
  const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<glm::vec3> normals(4, glm::vec3(0, 0, 1));
  const std::vector<glm::vec2> uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  nlohmann::json attributes = {{"POSITION", builder.addFloats(positions)},
                               {"NORMAL", builder.addFloats(normals)},
                               {"TEXCOORD_0", builder.addFloats(uvs)}};
  // A file tangent deliberately unlike the generated one (along +y, w = -1), to see it kept.
  if (withTangents) attributes["TANGENT"] = builder.addFloats(std::vector<glm::vec4>(4, glm::vec4(0, 1, 0, -1)));
  const int mesh = builder.addMesh({{{"attributes", attributes},
                                     {"indices", builder.addIndices({0, 1, 2, 0, 2, 3})},
                                     {"material", 0}}});
  builder.addNode({{"mesh", mesh}, {"scale", {scale.x, scale.y, scale.z}}});
  builder.addImage(test::encodePng(2, 2, test::quadPixels()), "image/png");
  builder.document()["textures"] = {{{"source", 0}}};
  builder.document()["materials"] = {{{"name", "bumpy"}, {"normalTexture", {{"index", 0}}}}};
  builder.write(path, test::GltfBuilder::Storage::Glb);
  return path;
}

TEST_F(SceneLoad, NormalMappedMeshesGetTangentsAlongPlusU) {
  const Scene scene = loadScene(writeNormalMappedQuad(scratch / "quad.glb", false, glm::vec3(1.0f)));
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& mesh = scene.meshes[0];
  ASSERT_EQ(mesh.tangents.size(), 4u);
  for (const glm::vec4& t : mesh.tangents) {
    EXPECT_NEAR(glm::distance(glm::vec3(t), glm::vec3(1, 0, 0)), 0.0f, 1e-5f);
    EXPECT_EQ(t.w, 1.0f);
  }
}

TEST_F(SceneLoad, TangentsOfAMirroredNodeKeepTheBitangentUpTheImage) {
  // Mirrored in x: +u now runs along -x, and up the image is still +y, so w becomes -1, whether the
  // tangents are generated after the transform or come from the file and are transformed.
  const Scene generated = loadScene(writeNormalMappedQuad(scratch / "mirrored.glb", false, glm::vec3(-1, 1, 1)));
  ASSERT_EQ(generated.meshes[0].tangents.size(), 4u);
  for (std::size_t v = 0; v < 4; ++v) {
    const glm::vec4 t = generated.meshes[0].tangents[v];
    EXPECT_NEAR(glm::distance(glm::vec3(t), glm::vec3(-1, 0, 0)), 0.0f, 1e-5f);
    EXPECT_EQ(t.w, -1.0f);
    const glm::vec3 bitangent = t.w * glm::cross(generated.meshes[0].normals[v], glm::vec3(t));
    EXPECT_NEAR(glm::distance(bitangent, glm::vec3(0, 1, 0)), 0.0f, 1e-5f);
  }
}

TEST_F(SceneLoad, FileTangentsAreKept) {
  const Scene scene = loadScene(writeNormalMappedQuad(scratch / "tangents.glb", true, glm::vec3(1.0f)));
  ASSERT_EQ(scene.meshes[0].tangents.size(), 4u);
  for (const glm::vec4& t : scene.meshes[0].tangents) EXPECT_EQ(t, glm::vec4(0, 1, 0, -1));
  // Under a mirror in x the file's (0, 1, 0, -1) keeps its direction and flips w: its bitangent
  // -cross(z, y) = +x becomes the mirrored -x.
  const Scene mirrored = loadScene(writeNormalMappedQuad(scratch / "tangents-mirrored.glb", true, glm::vec3(-1, 1, 1)));
  for (const glm::vec4& t : mirrored.meshes[0].tangents) EXPECT_EQ(t, glm::vec4(0, 1, 0, 1));
}

TEST_F(SceneLoad, UnknownExtensionIsAnError) {
  const std::filesystem::path path = scratch / "model.obj";
  std::ofstream(path) << "v 0 0 0\n";
  try {
    loadScene(path);
    FAIL() << "loaded";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              path.string() + ": unknown scene type '.obj' (expected .json, .gltf or .glb)");
  }
}

TEST(ObjectBounds, ExcludeTheGround) {
  Mesh object, ground;
  object.positions = {glm::vec3(1, 2, 3), glm::vec3(4, 5, 6)};
  ground.positions = {glm::vec3(-100, 0, -100), glm::vec3(100, 0, 100)};
  ground.isGround = true;
  const Bounds b = objectBounds({object, ground});
  EXPECT_EQ(b.min, glm::vec3(1, 2, 3));
  EXPECT_EQ(b.max, glm::vec3(4, 5, 6));
}

TEST_F(SceneLoad, RealAssetIsFramed) {
  const std::filesystem::path bunny = test::assetsDir() / "models" / "bunny.glb";
  if (!std::filesystem::exists(bunny)) GTEST_SKIP() << "assets not fetched: " << bunny;
  const Scene scene = loadScene(bunny);
  EXPECT_FALSE(scene.camera.has_value());
  const Camera camera = sceneCamera(scene, float(scene.width) / float(scene.height));
  EXPECT_GT(glm::length(camera.position - scene.bounds.center()), scene.bounds.radius());
}

}  // namespace
}  // namespace iblkit
