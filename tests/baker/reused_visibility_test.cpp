#include "baker/reused_visibility.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/procedural_mesh.h"
#include "core/scene.h"
#include "support/gltf_builder.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

// The scene files' hash follows their bytes: the scene file's and each model's, a procedural
// shape's by its entry; a bake of the same files elsewhere has the same hash.
TEST(ReusedVisibility, TheSceneHashFollowsTheBytesOfEverySceneFile) {
  const fs::path root = test::scratchDir();
  const ProceduralMesh ball = uvSphere(glm::vec3(0.0f), 0.5f, 8, 16);
  const auto writeModel = [&](const fs::path& file, float scale) {
    std::vector<glm::vec3> positions = ball.positions;
    for (glm::vec3& p : positions) p *= scale;
    test::GltfBuilder builder;
    builder.addPrimitiveNode(
        {{"attributes", {{"POSITION", builder.addFloats(positions)}, {"NORMAL", builder.addFloats(ball.normals)}}},
         {"indices", builder.addIndices(ball.indices)}});
    builder.write(file, test::GltfBuilder::Storage::Glb);
  };
  for (const char* folder : {"a", "b"}) {
    fs::create_directories(root / folder);
    writeModel(root / folder / "ball.glb", 1.0f);
    std::ofstream(root / folder / "scene.json") << R"({"models": [{"file": "ball.glb"}, {"shape": "sphere"}]})";
  }
  const std::string hash = sceneContentHash(loadScene(root / "a" / "scene.json"));
  EXPECT_EQ(hash.size(), 16u);
  EXPECT_EQ(sceneContentHash(loadScene(root / "b" / "scene.json")), hash);
  writeModel(root / "b" / "ball.glb", 1.001f);  // the model's bytes
  EXPECT_NE(sceneContentHash(loadScene(root / "b" / "scene.json")), hash);
  writeModel(root / "b" / "ball.glb", 1.0f);
  std::ofstream(root / "b" / "scene.json") << R"({"models": [{"file": "ball.glb"}, {"shape": "sphere", "translation": [2, 0, 0]}]})";
  EXPECT_NE(sceneContentHash(loadScene(root / "b" / "scene.json")), hash);  // the scene file's
}

}  // namespace
}  // namespace iblkit
