#include "baker/visibility_attributes.h"

#include <gtest/gtest.h>

#include "support/error_capture.h"

namespace iblkit {
namespace {

// Two vertices with distinct values everywhere, so any mix-up of components shows.
MeshVisibility twoVertices() {
  MeshVisibility v;
  v.ambientOcclusion = {0.25f, 0.75f};
  v.bentNormals = {{0.0f, 1.0f, 0.0f}, {0.6f, 0.8f, 0.0f}};
  v.bentNormalLengths = {0.5f, 0.125f};
  for (int i = 0; i < 2; ++i) {
    ShBasis9 t;
    for (int k = 0; k < kShCoefficients; ++k) t[k] = float(10 * i + k);
    v.transfer.push_back(t);
  }
  return v;
}

TEST(VisibilityAttributes, PacksAoBentNormalAndTransferIntoVec3Triples) {
  std::vector<Mesh> meshes(1);
  meshes[0].name = "pair";
  meshes[0].positions.resize(2);
  meshes[0].attributes["_AO"] = {1, {9.0f, 9.0f}};  // replaced
  attachVisibilityAttributes(meshes, {twoVertices()});
  const auto& a = meshes[0].attributes;
  ASSERT_EQ(a.size(), 6u);
  EXPECT_EQ(a.at("_AO").componentCount, 1);
  EXPECT_EQ(a.at("_AO").data, (std::vector<float>{0.25f, 0.75f}));
  EXPECT_EQ(a.at("_BENTNORMAL").componentCount, 3);
  EXPECT_EQ(a.at("_BENTNORMAL").data, (std::vector<float>{0.0f, 1.0f, 0.0f, 0.6f, 0.8f, 0.0f}));
  EXPECT_EQ(a.at("_BENTLENGTH").data, (std::vector<float>{0.5f, 0.125f}));
  EXPECT_EQ(a.at("_SHT0").data, (std::vector<float>{0, 1, 2, 10, 11, 12}));
  EXPECT_EQ(a.at("_SHT1").data, (std::vector<float>{3, 4, 5, 13, 14, 15}));
  EXPECT_EQ(a.at("_SHT2").data, (std::vector<float>{6, 7, 8, 16, 17, 18}));
  EXPECT_EQ(transferFromAttributes(meshes[0], 1), twoVertices().transfer[1]);
}

TEST(VisibilityAttributes, MismatchedCountsAndMissingAttributesAreErrors) {
  std::vector<Mesh> meshes(1);
  meshes[0].name = "triple";
  meshes[0].positions.resize(3);
  EXPECT_EQ(test::errorMessage([&] { attachVisibilityAttributes(meshes, {}); }),
            "vertex visibility attributes: 0 results for 1 meshes");
  EXPECT_EQ(test::errorMessage([&] { attachVisibilityAttributes(meshes, {twoVertices()}); }),
            "vertex visibility attributes: mesh 0 has 3 vertices but its results have a different count");
  EXPECT_EQ(test::errorMessage([&] { transferFromAttributes(meshes[0], 0); }),
            "vertex visibility attributes: mesh 'triple' has no _SHT0");
}

}  // namespace
}  // namespace iblkit
