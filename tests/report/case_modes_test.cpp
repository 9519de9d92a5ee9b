#include "report/case_modes.h"

#include <gtest/gtest.h>

namespace iblkit {
namespace {

const std::vector<std::string> kModes = {"sh", "full", "full-gltf-ao", "prt", "full-both-ao"};

TEST(CaseModes, GltfOcclusionModesOnlyWhereAMaterialHasAnOcclusionTexture) {
  EXPECT_EQ(caseModes(kModes, true), kModes);
  EXPECT_EQ(caseModes(kModes, false), (std::vector<std::string>{"sh", "full", "prt"}));
  EXPECT_EQ(caseModes({"full-both-ao"}, false), std::vector<std::string>{});
}

TEST(CaseModes, AnOcclusionTextureInAnyMaterialCounts) {
  Scene scene;
  scene.materials.resize(3);
  EXPECT_FALSE(hasOcclusionTexture(scene));
  scene.materials[1].baseColorTexture.texture = 0;
  scene.materials[2].normalTexture.texture = 0;
  EXPECT_FALSE(hasOcclusionTexture(scene));  // other slots do not make glTF occlusion
  scene.materials[2].occlusionTexture.texture = 1;
  EXPECT_TRUE(hasOcclusionTexture(scene));
}

}  // namespace
}  // namespace iblkit
