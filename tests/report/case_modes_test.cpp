#include "report/case_modes.h"

#include <gtest/gtest.h>

#include "support/test_paths.h"

namespace iblkit {
namespace {

const std::vector<std::string> kModes = {"mirror", "sh", "full", "full-gltf-ao", "prt", "irradiance",
                                         "lights-shadowed", "full-both-ao"};

Scene sceneOf(std::vector<Material> materials) {
  Scene scene;
  scene.materials = std::move(materials);
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    scene.meshes.emplace_back();
    scene.meshes.back().material = int(i);
  }
  return scene;
}

Material material(float metallic, float specular, float roughness = 0.5f) {
  Material result;
  result.metallic = metallic;
  result.specular = specular;
  result.roughness = roughness;
  return result;
}

TEST(CaseModes, GltfOcclusionModesOnlyWhereAMaterialHasAnOcclusionTexture) {
  SceneLobes lobes;
  lobes.occlusionTexture = true;
  EXPECT_EQ(caseModes(kModes, lobes), kModes);
  lobes.occlusionTexture = false;
  EXPECT_EQ(caseModes(kModes, lobes),
            (std::vector<std::string>{"mirror", "sh", "full", "prt", "irradiance", "lights-shadowed"}));
  EXPECT_EQ(caseModes({"full-both-ao"}, lobes), std::vector<std::string>{});
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

// The lone mirror sphere (metallic 1): no diffuse lobe, so none of the diffuse-only modes; the
// modes that shade both lobes stay, and so does mirror.
TEST(CaseModes, AMetallicSceneIsNotScoredInDiffuseOnlyModes) {
  const SceneLobes lobes = sceneLobes(sceneOf({material(1.0f, 1.0f, 0.0f)}));
  EXPECT_FALSE(lobes.diffuse);
  EXPECT_TRUE(lobes.specular);
  EXPECT_EQ(caseModes(kModes, lobes), (std::vector<std::string>{"mirror", "full", "lights-shadowed"}));
  EXPECT_EQ(modeNotApplicable("sh", lobes), "no diffuse lobe: every material is metallic");
  EXPECT_EQ(modeNotApplicable("full", lobes), "");
}

// A pure Lambert scene (metallic 0, specular 0): no mirror; one specular material anywhere
// brings it back, one dielectric the diffuse modes.
TEST(CaseModes, ALambertSceneIsNotScoredInMirrorAndOneMaterialOfEachLobeBringsItsModesBack) {
  const SceneLobes lambert = sceneLobes(sceneOf({material(0.0f, 0.0f, 1.0f), material(0.0f, 0.0f, 1.0f)}));
  EXPECT_TRUE(lambert.diffuse);
  EXPECT_FALSE(lambert.specular);
  EXPECT_EQ(caseModes(kModes, lambert), (std::vector<std::string>{"sh", "full", "prt", "irradiance", "lights-shadowed"}));
  EXPECT_TRUE(sceneLobes(sceneOf({material(0.0f, 0.0f), material(0.0f, 1.0f)})).specular);  // a dielectric's F0
  EXPECT_TRUE(sceneLobes(sceneOf({material(1.0f, 1.0f), material(0.5f, 0.0f)})).diffuse);
  Material blackSpecular = material(0.0f, 1.0f);
  blackSpecular.specularColor = glm::vec3(0.0f);
  EXPECT_FALSE(sceneLobes(sceneOf({blackSpecular})).specular);
}

// Only the materials the meshes use count; a textured metallic factor may hold anything.
TEST(CaseModes, UnusedMaterialsDoNotCountAndTexturedFactorsCountAsBoth) {
  Scene scene = sceneOf({material(1.0f, 1.0f)});
  scene.materials.push_back(material(0.0f, 0.0f));  // no mesh uses it
  EXPECT_FALSE(sceneLobes(scene).diffuse);
  Material textured = material(1.0f, 0.0f);
  textured.metallicRoughnessTexture.texture = 0;
  EXPECT_TRUE(sceneLobes(sceneOf({textured})).diffuse);
  EXPECT_TRUE(sceneLobes(Scene{}).diffuse);  // nothing known: nothing left out
  EXPECT_TRUE(sceneLobes(Scene{}).specular);
}

// The bundled scenes as the report reads them.
TEST(CaseModes, BundledScenes) {
  const auto scenes = test::assetsDir() / "scenes";
  const SceneLobes mirror = sceneLobes(loadScene(scenes / "mirror_sphere.json"));
  EXPECT_FALSE(mirror.diffuse);
  EXPECT_TRUE(mirror.specular);
  const SceneLobes diffuse = sceneLobes(loadScene(scenes / "diffuse_sphere.json"));
  EXPECT_TRUE(diffuse.diffuse);
  EXPECT_FALSE(diffuse.specular);
  const SceneLobes suzi = sceneLobes(loadScene(scenes / "suzi.json"));
  EXPECT_TRUE(suzi.diffuse);  // Lambert too, on a Lambert ground
  EXPECT_FALSE(suzi.specular);
}

}  // namespace
}  // namespace iblkit
