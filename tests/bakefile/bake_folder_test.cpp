#include "bakefile/bake_folder.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "bakefile/bake_layout.h"
#include "bakefile/bake_record.h"
#include "bakefile/scene_glb.h"
#include "core/image_io.h"
#include "support/bake_fixture.h"
#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

// A bake folder written through the bakefile writers, as iblkit-bake writes it (docs/baker.md),
// from the in-memory test bake, with the environment saved as an OpenEXR file that bake.json names.
fs::path writeBakeFolder(const std::string& name, const BakedScene& bake,
                         const std::string& version = kBakeVersion) {
  const fs::path folder = test::scratchDir() / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  writeSceneGlb(bake.scene, folder / kBakeSceneFile);
  writeEnvironmentStages(folder, bake.env);
  const fs::path environment = folder / "sky.exr";
  writeExr(environment, bake.env.latLong, {.pixelType = PixelType::Float});
  nlohmann::json record = makeBakeRecord(
      {.scene = "test",
       .environment = environment,
       .environmentFormat = "latlong",
       .environmentRotationDegrees = 30.0f,
       .environmentIntensity = 2.0f},
      nlohmann::json::object());
  record["version"] = version;
  writeBakeRecord(folder / kBakeRecordFile, record);
  return folder;
}

TEST(BakedScene, ReadsBackWhatTheBakerWrote) {
  const BakedScene original = test::makeTestBake({.ground = true, .rings = 8, .segments = 16});
  const BakedScene bake = readBakeFolder(writeBakeFolder("bake_ok", original));
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
  EXPECT_EQ(bake.env.shWindowCutoff, original.env.shWindowCutoff);
  ASSERT_EQ(bake.env.specular.levels.size(), original.env.specular.levels.size());
  EXPECT_EQ(bake.env.specular.roughness.size(), original.env.specular.roughness.size());
  EXPECT_EQ(bake.env.specular.levels[2].faces[3].at(1, 2), original.env.specular.levels[2].faces[3].at(1, 2));
  EXPECT_EQ(bake.env.brdfLut.width(), original.env.brdfLut.width());
  EXPECT_EQ(bake.env.latLong.at(5, 7), original.env.latLong.at(5, 7));
  EXPECT_EQ(bake.env.rotationDegrees, 30.0f);
  EXPECT_EQ(bake.env.intensity, 2.0f);
  ASSERT_EQ(bake.env.irradiance.size, original.env.irradiance.size);
  EXPECT_EQ(bake.env.irradiance.faces[4].pixels(), original.env.irradiance.faces[4].pixels());
}

// env/irradiance.exr is optional: without it the stages have no irradiance cube (size 0).
TEST(BakedScene, ABakeWithoutTheIrradianceCubeReadsWithout) {
  const fs::path folder = writeBakeFolder("bake_no_cube", test::makeTestBake({.rings = 8, .segments = 16}));
  ASSERT_TRUE(fs::remove(folder / kBakeIrradianceFile));
  EXPECT_EQ(readBakeFolder(folder).env.irradiance.size, 0);
}

TEST(BakedScene, MissingOrIncompleteOrWrongVersionIsAnErrorNamingTheFile) {
  const BakedScene original = test::makeTestBake({.rings = 4, .segments = 8});
  const fs::path missing = test::scratchDir() / "no_such_bake";
  EXPECT_EQ(test::errorMessage([&] { readBakeFolder(missing); }), missing.string() + ": no such bake folder");

  const fs::path incomplete = writeBakeFolder("bake_incomplete", original);
  fs::remove(incomplete / "env" / "specular.exr");
  EXPECT_EQ(test::errorMessage([&] { readBakeFolder(incomplete); }),
            (incomplete / "env" / "specular.exr").string() + ": missing (incomplete bake folder?)");

  const fs::path old = writeBakeFolder("bake_old", original, "iblkit-bake 0");
  EXPECT_EQ(
      test::errorMessage([&] { readBakeFolder(old); }),
      (old / "bake.json").string() + ": version 'iblkit-bake 0' is not supported (expected 'iblkit-bake 1')");
}

TEST(BakeRecord, WritesTheInputsItReadsBack) {
  const fs::path file = test::scratchDir() / "bake_record.json";
  writeBakeRecord(file, makeBakeRecord({.scene = "/a/scene.json",
                                        .environment = "/b/map.exr",
                                        .environmentFormat = "mirrorball",
                                        .environmentRotationDegrees = -45.0f,
                                        .environmentIntensity = 0.5f},
                                       {{"ao_rays", 7}}));
  const BakeInputs inputs = readBakeRecord(file);
  EXPECT_EQ(inputs.scene, fs::path("/a/scene.json"));
  EXPECT_EQ(inputs.environment, fs::path("/b/map.exr"));
  EXPECT_EQ(inputs.environmentFormat, "mirrorball");
  EXPECT_EQ(inputs.environmentRotationDegrees, -45.0f);
  EXPECT_EQ(inputs.environmentIntensity, 0.5f);
  std::ifstream stream(file);
  EXPECT_EQ(nlohmann::json::parse(stream).at("parameters").at("ao_rays"), 7);
}

// Inputs of a bake of scene "s" under `environment` (empty: none), the other fields as default.
BakeInputs inputsOf(const fs::path& environment) {
  BakeInputs inputs;
  inputs.scene = "s";
  inputs.environment = environment;
  return inputs;
}

TEST(BakeRecord, ARelativeEnvironmentIsRelativeToTheBakeAndNoneMeansNoStages) {
  const fs::path folder = test::scratchDir() / "bake_relative";
  fs::create_directories(folder);
  writeBakeRecord(folder / kBakeRecordFile, makeBakeRecord(inputsOf("map.exr"), {}));
  EXPECT_EQ(readBakeRecord(folder / kBakeRecordFile).environment, folder / "map.exr");
  writeBakeRecord(folder / kBakeRecordFile, makeBakeRecord(inputsOf(""), {}));
  EXPECT_TRUE(readBakeRecord(folder / kBakeRecordFile).environment.empty());
  EXPECT_EQ(test::errorMessage([&] { readEnvironmentStages(folder, readBakeRecord(folder / kBakeRecordFile)); }),
            (folder / kBakeRecordFile).string() + ": the bake has no environment stages (bake with --env)");
}

// The SH transfer's interreflection bounces (the baker's parameters.bounces) come back as
// transferBounces, which decides the engine's multi-bounce fit; a bake without them reads 0, and
// anything but an integer in 0..16 is an error naming the file.
TEST(BakeRecord, TheTransfersBouncesAreReadBackAndChecked) {
  const fs::path file = test::scratchDir() / "bake_record_bounces.json";
  writeBakeRecord(file, makeBakeRecord(inputsOf("map.exr"), {{"bounces", 3}}));
  EXPECT_EQ(readBakeRecord(file).transferBounces, 3);
  writeBakeRecord(file, makeBakeRecord(inputsOf("map.exr"), {{"ao_rays", 7}}));
  EXPECT_EQ(readBakeRecord(file).transferBounces, 0);
  for (const nlohmann::json& bad : {nlohmann::json(-1), nlohmann::json(17), nlohmann::json(1.5), nlohmann::json("2")}) {
    writeBakeRecord(file, makeBakeRecord(inputsOf("map.exr"), {{"bounces", bad}}));
    EXPECT_EQ(test::errorMessage([&] { readBakeRecord(file); }),
              file.string() + ": parameters.bounces: expected an integer in 0..16, got " + bad.dump());
  }
  // A long value is quoted cut, so the error stays one short line.
  writeBakeRecord(file, makeBakeRecord(inputsOf("map.exr"), {{"bounces", std::string(10000, 'x')}}));
  const std::string message = test::errorMessage([&] { readBakeRecord(file); });
  EXPECT_LT(message.size(), file.string().size() + 120) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

// fuzz/fuzz_bake_record found it: a version that is not a string escaped as nlohmann's type_error,
// a message naming no file.
TEST(BakeRecord, AVersionThatIsNotAStringIsAnErrorNamingTheFile) {
  const fs::path file = test::scratchDir() / kBakeRecordFile;
  std::ofstream(file) << R"({"version": 1, "inputs": {"scene": "s", "environment": null}})";
  EXPECT_EQ(test::errorMessage([&] { readBakeRecord(file); }),
            file.string() + ": version '1' is not supported (expected 'iblkit-bake 1')");
}

// The suns' bounce is optional, but one that is there must be what a bake writes.
TEST(BakedScene, ASunBounceOutOfShapeOrRangeIsAnErrorNamingTheFile) {
  BakedScene original = test::makeTestBake({.rings = 4, .segments = 8});
  for (Mesh& mesh : original.scene.meshes)
    mesh.attributes[kSunBounceAttribute] = {4, std::vector<float>(4 * mesh.vertexCount(), 0.25f)};
  EXPECT_EQ(readBakeFolder(writeBakeFolder("bake_sun_bounce", original)).scene.meshes[0].attributes.at(kSunBounceAttribute).data,
            original.scene.meshes[0].attributes.at(kSunBounceAttribute).data);
  const std::string mesh = original.scene.meshes[0].name;
  BakedScene bright = original;
  bright.scene.meshes[0].attributes[kSunBounceAttribute].data[5] = 1e30f;
  const fs::path brightFolder = writeBakeFolder("bake_sun_bounce_bright", bright);
  EXPECT_EQ(test::errorMessage([&] { readBakeFolder(brightFolder); }),
            (brightFolder / kBakeSceneFile).string() + ": mesh '" + mesh +
                "': _SUNBOUNCE holds 1e+30, outside [0, 3.01]");
  BakedScene negative = original;
  negative.scene.meshes[0].attributes[kSunBounceAttribute].data[0] = -0.5f;
  const fs::path negativeFolder = writeBakeFolder("bake_sun_bounce_negative", negative);
  EXPECT_EQ(test::errorMessage([&] { readBakeFolder(negativeFolder); }),
            (negativeFolder / kBakeSceneFile).string() + ": mesh '" + mesh +
                "': _SUNBOUNCE holds -0.5, outside [0, 3.01]");
  BakedScene vec3 = original;
  vec3.scene.meshes[0].attributes[kSunBounceAttribute] = {3, std::vector<float>(3 * vec3.scene.meshes[0].vertexCount(), 0.0f)};
  const fs::path vec3Folder = writeBakeFolder("bake_sun_bounce_vec3", vec3);
  EXPECT_EQ(test::errorMessage([&] { readBakeFolder(vec3Folder); }),
            (vec3Folder / kBakeSceneFile).string() + ": mesh '" + mesh + "': _SUNBOUNCE is not four values per vertex");
}

}  // namespace
}  // namespace iblkit
