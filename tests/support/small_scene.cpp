#include "support/small_scene.h"

#include <fstream>
#include <sstream>

#include "core/image_io.h"
#include "core/procedural_mesh.h"
#include "support/gltf_builder.h"

namespace iblkit::test {

namespace fs = std::filesystem;

SmallScene writeSmallScene(const fs::path& root) {
  SmallScene small{root / "scene.json", root / "models" / "ball.glb", root / "maps" / "sky.exr"};
  const ProceduralMesh ball = uvSphere(glm::vec3(0.0f), 0.5f, 6, 8);
  GltfBuilder builder;
  builder.addPrimitiveNode(
      {{"attributes",
        {{"POSITION", builder.addFloats(ball.positions)}, {"NORMAL", builder.addFloats(ball.normals)}}},
       {"indices", builder.addIndices(ball.indices)}});
  fs::create_directories(small.model.parent_path());
  builder.write(small.model, GltfBuilder::Storage::Glb);
  Image sky(32, 16, glm::vec4(0.2f, 0.3f, 0.4f, 1.0f));
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 32; ++x) sky.at(x, y) = glm::vec4(1.0f, 0.9f, 0.8f, 1.0f);
  fs::create_directories(small.map.parent_path());
  writeExr(small.map, sky);
  std::ofstream(small.scene) << R"({"models": [{"file": "models/ball.glb", "translation": [0, 0.5, 0]}],
    "ground": {}, "environment": {"file": "maps/sky.exr"},
    "camera": {"position": [0, 1, 4], "target": [0, 0.5, 0]}, "width": 32, "height": 24})";
  return small;
}

std::string fileBytes(const fs::path& file) {
  std::ifstream stream(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << stream.rdbuf();
  return bytes.str();
}

}  // namespace iblkit::test
