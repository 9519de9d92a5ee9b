#include "bakefile/scene_glb.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/gltf_load.h"
#include "core/procedural_mesh.h"
#include "core/scene.h"
#include "support/error_capture.h"
#include "support/test_paths.h"

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

}  // namespace
}  // namespace iblkit
