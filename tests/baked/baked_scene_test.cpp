#include "engine/baked/baked_scene.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "baker/baked_scene_gltf.h"
#include "baker/brdf_lut.h"
#include "baker/environment_sh.h"
#include "core/image_io.h"
#include "support/bake_fixture.h"
#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

// A bake folder written file by file as iblkit-bake writes it (docs/baker.md), from the in-memory
// test bake, with the environment saved as an OpenEXR file that bake.json names.
fs::path writeBakeFolder(const std::string& name, const BakedScene& bake,
                         const std::string& version = kBakeVersion) {
  const fs::path folder = test::scratchDir() / name;
  fs::remove_all(folder);
  fs::create_directories(folder / "env");
  writeSceneGlb(bake.scene, folder / "scene.glb");
  writeSh9Json(folder / "env" / "sh9.json", bake.env.sh9, bake.env.shWindowCutoff);
  writeSpecularCubeExr(folder / "env" / "specular.exr", bake.env.specular);
  writeBrdfLutExr(folder / "env" / "brdf_lut.exr", bake.env.brdfLut);
  const fs::path environment = folder / "sky.exr";
  writeExr(environment, bake.env.latLong, {.pixelType = PixelType::Float});
  const nlohmann::json record = {
      {"version", version},
      {"inputs", {{"scene", "test"}, {"environment", environment.string()}}},
      {"parameters",
       {{"env_format", "latlong"}, {"environment_rotation_degrees", 30.0}, {"environment_intensity", 2.0}}}};
  std::ofstream(folder / "bake.json") << record.dump(2);
  return folder;
}

TEST(BakedScene, ReadsBackWhatTheBakerWrote) {
  const BakedScene original = test::makeTestBake({.ground = true, .rings = 8, .segments = 16});
  const BakedScene bake = loadBake(writeBakeFolder("bake_ok", original));
  EXPECT_FALSE(bake.bakedInMemory);
  ASSERT_EQ(bake.scene.meshes.size(), 2u);
  EXPECT_FALSE(bake.scene.meshes[0].isGround);
  EXPECT_TRUE(bake.scene.meshes[1].isGround);
  EXPECT_EQ(bake.scene.meshes[0].attributes.at("_AO").data,
            original.scene.meshes[0].attributes.at("_AO").data);
  EXPECT_EQ(bake.scene.meshes[1].attributes.at("_SHT2").data,
            original.scene.meshes[1].attributes.at("_SHT2").data);
  for (int k = 0; k < kShCoefficients; ++k)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(bake.env.sh9.coefficients[std::size_t(k)][c],
                  original.env.sh9.coefficients[std::size_t(k)][c], 1e-6f);
  ASSERT_EQ(bake.env.specular.levels.size(), original.env.specular.levels.size());
  EXPECT_EQ(bake.env.specular.roughness.size(), original.env.specular.roughness.size());
  EXPECT_EQ(bake.env.specular.levels[2].faces[3].at(1, 2), original.env.specular.levels[2].faces[3].at(1, 2));
  EXPECT_EQ(bake.env.brdfLut.width(), original.env.brdfLut.width());
  EXPECT_EQ(bake.env.latLong.at(5, 7), original.env.latLong.at(5, 7));
  EXPECT_EQ(bake.env.rotationDegrees, 30.0f);
  EXPECT_EQ(bake.env.intensity, 2.0f);
}

TEST(BakedScene, MissingOrIncompleteOrWrongVersionIsAnErrorNamingTheFile) {
  const BakedScene original = test::makeTestBake({.rings = 4, .segments = 8});
  const fs::path missing = test::scratchDir() / "no_such_bake";
  EXPECT_EQ(test::errorMessage([&] { loadBake(missing); }), missing.string() + ": no such bake folder");

  const fs::path incomplete = writeBakeFolder("bake_incomplete", original);
  fs::remove(incomplete / "env" / "specular.exr");
  EXPECT_EQ(test::errorMessage([&] { loadBake(incomplete); }),
            (incomplete / "env" / "specular.exr").string() + ": missing (incomplete bake folder?)");

  const fs::path old = writeBakeFolder("bake_old", original, "iblkit-bake 0");
  EXPECT_EQ(
      test::errorMessage([&] { loadBake(old); }),
      (old / "bake.json").string() + ": version 'iblkit-bake 0' is not supported (expected 'iblkit-bake 1')");
}

TEST(BakedScene, PrepareEnvironmentMatchesTheBakerStages) {
  const EnvironmentMap sky = test::testSky();
  const EnvironmentStages stages =
      prepareEnvironment(sky, {.specularSamples = 16, .lutSize = 8, .lutSamples = 16});
  EXPECT_EQ(stages.latLong.width(), 64);
  EXPECT_EQ(stages.specular.levels.front().size, 16);  // width / 4
  EXPECT_EQ(stages.specular.levels.back().size, 1);
  EXPECT_EQ(stages.brdfLut.width(), 8);
  // The SH9 stage is the baker's projection with its automatic ringing window.
  const SphericalHarmonics9 projected = projectEnvironmentSh9(sky);
  // (Equal up to the order of TBB's parallel sums.)
  EXPECT_NEAR(stages.shWindowCutoff, automaticShWindowCutoff(projected), 1e-3f);
  const SphericalHarmonics9 windowed = windowSh9(projected, stages.shWindowCutoff);
  for (int k = 0; k < kShCoefficients; ++k)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(stages.sh9.coefficients[std::size_t(k)][c], windowed.coefficients[std::size_t(k)][c], 1e-5f);
}

}  // namespace
}  // namespace iblkit
