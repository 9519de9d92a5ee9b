// End-to-end tests of the iblkit-bake program: the built binary on scenes written to a scratch folder.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <fstream>
#include <iterator>
#include <glm/gtc/constants.hpp>
#include <nlohmann/json.hpp>

#include "baker/visibility_attributes.h"
#include "bakefile/vertex_attributes.h"
#include "core/scene.h"
#include "core/gltf_load.h"
#include "core/image_io.h"
#include "core/latlong.h"
#include "core/procedural_mesh.h"
#include "support/gltf_builder.h"
#include "support/sun_map.h"
#include "support/test_paths.h"
#include "support/usage_error_check.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

// models/ball.glb (a UV sphere of radius 0.5 around the origin) and scene.json placing it at
// height 0.5 on the default ground.
fs::path writeBallScene(const fs::path& root) {
  const ProceduralMesh ball = uvSphere(glm::vec3(0.0f), 0.5f, 8, 16);
  test::GltfBuilder builder;
  builder.addPrimitiveNode(
      {{"attributes",
        {{"POSITION", builder.addFloats(ball.positions)}, {"NORMAL", builder.addFloats(ball.normals)}}},
       {"indices", builder.addIndices(ball.indices)}});
  fs::create_directories(root / "models");
  builder.write(root / "models" / "ball.glb", test::GltfBuilder::Storage::Glb);
  const fs::path scene = root / "scene.json";
  std::ofstream(scene) << R"({"models": [{"file": "models/ball.glb", "translation": [0, 0.5, 0],
    "material": {"baseColor": [0.8, 0.7, 0.6], "metallic": 0}}], "ground": {},
    "camera": {"position": [0, 1, 4], "target": [0, 0.5, 0]}})";
  return scene;
}

std::string bake(const std::string& arguments, int* status) {
  std::string output;
  *status = test::runCommand((test::binDir() / "iblkit-bake").string() + " " + arguments, &output);
  return output;
}

// iblkit-bake `arguments` -o `out` refused at run time: status 1, exactly the one line
// "iblkit-bake: <message>", and no `out`.
void expectRefused(const std::string& arguments, const fs::path& out, const std::string& message) {
  int status = 0;
  const std::string output = bake(arguments + " -o " + out.string(), &status);
  EXPECT_EQ(status, 1) << output;
  EXPECT_EQ(output, "iblkit-bake: " + message + "\n");
  EXPECT_FALSE(fs::exists(out));
}

// Entries of `folder` whose names contain ".tmp-" or ".old-": leftovers of an unfinished bake.
int leftovers(const fs::path& folder) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    count += name.find(".tmp-") != std::string::npos || name.find(".old-") != std::string::npos;
  }
  return count;
}

TEST(IblkitBake, WritesTheBakedSceneAndTheReport) {
  const fs::path root = test::scratchDir();
  const fs::path scene = writeBallScene(root), out = root / "out";
  int status = 0;
  const std::string log = bake(scene.string() + " -o " + out.string() + " --ao-rays 32 --seed 3", &status);
  ASSERT_EQ(status, 0) << log;
  EXPECT_EQ(leftovers(root), 0);

  const GltfContents baked = loadGltf(out / "scene.glb");
  ASSERT_EQ(baked.meshes.size(), 2u);  // the ball and the ground, in world space
  EXPECT_EQ(baked.meshes[0].vertexCount(), 2u + 7u * 16u);
  EXPECT_EQ(baked.meshes[0].bounds().min.y, 0.0f);
  EXPECT_EQ(baked.meshes[1].name, "ground");
  EXPECT_EQ(baked.materials[baked.meshes[0].material].baseColor, glm::vec3(0.8f, 0.7f, 0.6f));
  ASSERT_TRUE(baked.camera.has_value());
  EXPECT_EQ(baked.camera->position, glm::vec3(0.0f, 1.0f, 4.0f));
  std::size_t vertices = 0;
  for (const Mesh& mesh : baked.meshes) {
    vertices += mesh.vertexCount();
    ASSERT_EQ(mesh.attributes.size(), 6u) << mesh.name;
    const auto& ao = mesh.attributes.at("_AO");
    const auto& bent = mesh.attributes.at("_BENTNORMAL");
    EXPECT_EQ(ao.componentCount, 1);
    EXPECT_EQ(bent.componentCount, 3);
    EXPECT_EQ(mesh.attributes.at("_BENTLENGTH").componentCount, 1);
    ASSERT_EQ(ao.data.size(), mesh.vertexCount());
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
      EXPECT_GE(ao.data[v], 0.0f);
      EXPECT_LE(ao.data[v], 1.0f);
      EXPECT_NEAR(glm::length(glm::vec3(bent.data[3 * v], bent.data[3 * v + 1], bent.data[3 * v + 2])), 1.0f,
                  1e-5f);
      // t0 = Y0 * (pi/N) * escaping rays = Y0 * pi * AO.
      EXPECT_NEAR(transferFromAttributes(mesh, v)[0], 0.282094792f * 3.14159265f * ao.data[v], 1e-5f);
    }
  }
  // The ball's top pole is open sky, the ground under it is shadowed.
  EXPECT_EQ(baked.meshes[0].attributes.at("_AO").data[0], 1.0f);

  nlohmann::json report;
  std::ifstream(out / "bake.json") >> report;
  EXPECT_EQ(report["version"], "iblkit-bake 1");
  EXPECT_EQ(report["inputs"]["scene"], scene.string());
  EXPECT_TRUE(report["inputs"]["environment"].is_null());
  EXPECT_EQ(report["parameters"]["ao_rays"], 32);
  EXPECT_EQ(report["parameters"]["ao_distance"], 0.0);
  EXPECT_EQ(report["parameters"]["seed"], 3);
  EXPECT_EQ(report["counts"]["vertices"], vertices);
  EXPECT_EQ(report["counts"]["rays"], 32 * vertices);
  // The grey albedo per mesh (meshDiffuseAlbedo): the ball's (0.8, 0.7, 0.6) as Rec. 709 luminance.
  ASSERT_EQ(report["mesh_albedos"].size(), 2u);
  EXPECT_NEAR(report["mesh_albedos"][0].get<float>(), 0.2126f * 0.8f + 0.7152f * 0.7f + 0.0722f * 0.6f, 1e-6f);
  for (const char* stage : {"load_s", "visibility_s", "write_scene_s"})
    EXPECT_GE(report["timings"][stage], 0.0) << stage;
  EXPECT_GT(report["rays_per_second"], 0.0);
}

TEST(IblkitBake, ReplacesAnEarlierOutputOnlyAfterSuccess) {
  const fs::path root = test::scratchDir();
  const fs::path scene = writeBallScene(root), out = root / "out";
  fs::create_directories(out);
  std::ofstream(out / "stale.txt") << "from an earlier bake";
  std::ofstream(out / "bake.json") << "{}";  // what marks a bake folder (else --force is needed)
  int status = 0;
  std::string log = bake(scene.string() + " -o " + out.string() + " --ao-rays 4 --ao-distance 0.1", &status);
  ASSERT_EQ(status, 0) << log;
  EXPECT_FALSE(fs::exists(out / "stale.txt"));
  EXPECT_TRUE(fs::exists(out / "scene.glb"));
  EXPECT_EQ(leftovers(root), 0);

  // A failing bake keeps the previous output as it was.
  log = bake((root / "missing.json").string() + " -o " + out.string(), &status);
  EXPECT_EQ(status, 1);
  EXPECT_TRUE(fs::exists(out / "scene.glb"));
  EXPECT_EQ(leftovers(root), 0);
}

TEST(IblkitBake, BadScenesGiveOneLineErrorsAndNoOutput) {
  const fs::path root = test::scratchDir();
  for (const char* model : {"nan_position.gltf", "points_only.gltf"})
    fs::copy_file(test::dataDir() / "bad" / model, root / model);
  const struct {
    const char* model;
    std::string error;
  } cases[] = {
      {"nan_position.gltf",
       "nan_position.gltf: mesh 0 primitive 0: non-finite vertex position (vertex 1 in node 0, after its "
       "transforms: scale, translation or matrix)"},
      {"points_only.gltf", "points_only.gltf: no triangle meshes"},
  };
  for (const auto& c : cases) {
    const fs::path scene = root / (std::string(c.model) + ".json");
    std::ofstream(scene) << R"({"models": [{"file": ")" << c.model << R"("}], "ground": {}})";
    int status = 0;
    const std::string log = bake(scene.string() + " -o " + (root / "out").string(), &status);
    EXPECT_EQ(status, 1);
    // The error is the last line (the loader may warn before it: points_only.gltf's points).
    EXPECT_TRUE(log.ends_with("\niblkit-bake: " + (root / c.error).string() + "\n") ||
                log == "iblkit-bake: " + (root / c.error).string() + "\n")
        << log;
    EXPECT_FALSE(fs::exists(root / "out"));
    EXPECT_EQ(leftovers(root), 0);
  }
}

TEST(IblkitBake, WritesTheEnvironmentStagesWhenThereIsAnEnvironment) {
  const fs::path root = test::scratchDir();
  const fs::path scene = writeBallScene(root), out = root / "out", env = root / "sky.exr";
  // A small smooth sky with a bright spot; 16 x 8 keeps the specular chain quick.
  writeExr(env,
           latLongFromRadiance(32, 16, 2,
                               [](const glm::vec3& d) {
                                 return glm::vec3(0.5f + 0.5f * std::max(d.y, 0.0f)) +
                                        glm::vec3(20.0f) * std::pow(std::max(d.x, 0.0f), 8.0f);
                               }),
           {.pixelType = PixelType::Float});
  int status = 0;
  const std::string log = bake(scene.string() + " --env " + env.string() + " -o " + out.string() +
                                   " --ao-rays 8 --specular-samples 64 --lut-size 16",
                               &status);
  ASSERT_EQ(status, 0) << log;
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(out / "bake.json"));
  EXPECT_EQ(report["outputs"], nlohmann::json({"scene.glb", "bake.json", "env/sh9.json", "env/irradiance.exr",
                                               "env/specular.exr", "env/brdf_lut.exr", "env/lights.json",
                                               "env/residual_sh9.json", "env/residual_specular.exr",
                                               "env/residual_irradiance.exr"}));
  for (const nlohmann::json& file : report["outputs"])
    EXPECT_TRUE(fs::is_regular_file(out / file.get<std::string>())) << file;
  // The SH9 irradiance of this smooth sky is close to the brute-force cube, not exact (the bright
  // spot has energy above band 2).
  const float shError = report["environment"]["sh9_irradiance_error"]["mean_relative"];
  EXPECT_GT(shError, 0.0f);
  EXPECT_LT(shError, 0.2f);
  ExrInfo irradianceInfo;
  EXPECT_EQ(readExr(out / "env" / "irradiance.exr", &irradianceInfo).width(), 16);
  EXPECT_EQ(irradianceInfo.envmap, EnvmapLayout::Cube);
  for (const char* stage : {"sh9_s", "irradiance_s", "specular_s", "brdf_lut_s", "visibility_rays_s",
                            "lights_s", "residual_sh9_s", "residual_specular_s"})
    EXPECT_GE(report["timings"][stage], 0.0) << stage;
  EXPECT_EQ(report["environment"]["specular_face_size"], 8);  // a quarter of the map's width
  EXPECT_EQ(report["environment"]["specular_roughness_per_level"].size(), 4u);
  const nlohmann::json sh = nlohmann::json::parse(std::ifstream(out / "env" / "sh9.json"));
  ASSERT_EQ(sh["L"].size(), 9u);
  EXPECT_GT(sh["L"][0][0].get<float>(), 0.0f);
  ExrInfo info;
  readExr(out / "env" / "specular.exr", &info);
  EXPECT_EQ(info.envmap, EnvmapLayout::Cube);
  EXPECT_EQ(readExr(out / "env" / "brdf_lut.exr").width(), 16);
}

// The light options are recorded with the counts they gave; env/lights.json holds the lights.
TEST(IblkitBake, SunAndMedianCutOptionsAreRecordedWithTheLightCounts) {
  const fs::path root = test::scratchDir();
  const fs::path scene = writeBallScene(root), out = root / "out", env = root / "sunny.exr";
  // A dim sky and one bright texel: the automatic threshold gives it one sun.
  Image sunny(32, 16, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
  sunny.at(20, 4) = glm::vec4(5e3f, 5e3f, 5e3f, 1.0f);
  writeExr(env, sunny, {.pixelType = PixelType::Float});
  const std::string common = scene.string() + " --env " + env.string() + " -o " + out.string() +
                             " --ao-rays 4 --specular-samples 16 --lut-size 8";
  int status = 0;
  std::string log = bake(common + " --median-cut-levels 3", &status);
  ASSERT_EQ(status, 0) << log;
  nlohmann::json report = nlohmann::json::parse(std::ifstream(out / "bake.json"));
  EXPECT_EQ(report["parameters"]["sun_threshold"], "auto");
  EXPECT_EQ(report["parameters"]["max_suns"], 4);
  EXPECT_EQ(report["parameters"]["median_cut_levels"], 3);
  EXPECT_EQ(report["environment"]["lights"]["suns"], 1);
  EXPECT_EQ(report["environment"]["lights"]["median_cut"], 8);
  nlohmann::json lights = nlohmann::json::parse(std::ifstream(out / "env" / "lights.json"));
  EXPECT_EQ(lights["suns"].size(), 1u);
  EXPECT_EQ(lights["medianCut"].size(), 8u);
  EXPECT_EQ(lights["sunThreshold"].get<float>(),
            report["environment"]["lights"]["sun_threshold"].get<float>());

  log = bake(common + " --sun-threshold 1e4 --max-suns 2", &status);
  ASSERT_EQ(status, 0) << log;
  report = nlohmann::json::parse(std::ifstream(out / "bake.json"));
  EXPECT_EQ(report["parameters"]["sun_threshold"], "1e4");
  EXPECT_EQ(report["environment"]["lights"]["sun_threshold"], 1e4);
  EXPECT_EQ(report["environment"]["lights"]["suns"], 0);  // the texel is below 1e4
  EXPECT_EQ(report["environment"]["lights"]["median_cut"], 16);
  log = bake(common + " --max-suns 0", &status);
  ASSERT_EQ(status, 0) << log;
  report = nlohmann::json::parse(std::ifstream(out / "bake.json"));
  EXPECT_EQ(report["environment"]["lights"]["suns"], 0);
}

TEST(IblkitBake, BadLightOptionsAreRefusedWithoutOutput) {
  const fs::path root = test::scratchDir();
  const fs::path scene = writeBallScene(root), out = root / "out", env = root / "sky.exr";
  writeExr(env, Image(16, 8, glm::vec4(1.0f)), {});
  const std::string common = scene.string() + " --env " + env.string() + " -o " + out.string();
  for (const char* bad : {"-1", "0", "nan", "inf", "bright", "5x"}) {
    int status = 0;
    const std::string log = bake(common + " --sun-threshold " + bad, &status);
    EXPECT_EQ(status, 2) << bad;
    EXPECT_EQ(log, std::string("iblkit-bake: --sun-threshold: expected auto or a positive luminance, got '") +
                       bad + "'\n");
  }
  int status = 0;
  EXPECT_NE(bake(common + " --max-suns 65", &status).find("--max-suns"), std::string::npos);
  EXPECT_EQ(status, 2);
  EXPECT_NE(bake(common + " --median-cut-levels 13", &status).find("--median-cut-levels"), std::string::npos);
  EXPECT_EQ(status, 2);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(leftovers(root), 0);
}

TEST(IblkitBake, BadShWindowIsRefusedWithoutOutput) {
  const fs::path root = test::scratchDir();
  const fs::path scene = writeBallScene(root), out = root / "out", env = root / "sky.exr";
  writeExr(env, Image(16, 8, glm::vec4(1.0f)), {});
  int status = 0;
  const std::string log =
      bake(scene.string() + " --env " + env.string() + " -o " + out.string() + " --sh-window wide", &status);
  EXPECT_EQ(status, 2);  // a usage error (cli/program.h)
  EXPECT_EQ(log, "iblkit-bake: --sh-window: expected auto, none or a positive number of bands, got 'wide'\n");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(leftovers(root), 0);
}

// --specular-size sets the face size of both specular chains' sharpest level (auto: a quarter of the
// map's width); anything but auto or a power of two up to 4096 is refused before any work (8192
// ran out of memory).
TEST(IblkitBake, SpecularSizeSetsBothChainsAndBadSizesAreRefused) {
  const fs::path root = test::scratchDir();
  const fs::path scene = writeBallScene(root), out = root / "out", env = root / "sky.exr";
  writeExr(env, Image(64, 32, glm::vec4(1.0f)), {});
  const std::string common =
      scene.string() + " --env " + env.string() + " -o " + out.string() + " --ao-rays 4 --specular-samples 16 --lut-size 8";
  int status = 0;
  for (const auto& [size, face] : {std::pair{"auto", 16}, std::pair{"4", 4}, std::pair{"32", 32}}) {
    const std::string log = bake(common + " --specular-size " + size, &status);
    ASSERT_EQ(status, 0) << log;
    const nlohmann::json report = nlohmann::json::parse(std::ifstream(out / "bake.json"));
    EXPECT_EQ(report["parameters"]["specular_size"], size);
    EXPECT_EQ(report["environment"]["specular_face_size"], face) << size;
    for (const char* chain : {"specular.exr", "residual_specular.exr"}) {
      ExrInfo info;
      EXPECT_EQ(readExr(out / "env" / chain, &info).width(), face) << chain;
      EXPECT_EQ(info.levels, std::bit_width(unsigned(face)) + 2) << chain;  // + OpenEXR's 1 x 3 and 1 x 1
    }
  }
  fs::remove_all(out);
  for (const char* bad : {"0", "24", "8192", "16384", "-8", "big", "8x"}) {
    const std::string log = bake(common + " --specular-size " + bad, &status);
    EXPECT_EQ(status, 2) << bad;
    EXPECT_EQ(log, std::string("iblkit-bake: --specular-size: expected auto or a power of two from 1 to 4096, got '") +
                       bad + "'\n");
  }
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(leftovers(root), 0);
}

// --env-rotation and --env-intensity replace the scene's (docs/conventions.md), in the stages and
// in bake.json, whose rotation the engine reads.
TEST(IblkitBake, EnvironmentOverridesReplaceTheScenesAndAreRecorded) {
  const fs::path root = test::scratchDir();
  const fs::path scene = root / "rotated.json", out = root / "out", env = root / "sky.exr";
  writeBallScene(root);
  std::ofstream(scene) << R"({"models": [{"file": "models/ball.glb"}], "ground": {},
    "environment": {"file": "sky.exr", "rotation": 30, "intensity": 2}})";
  writeExr(env, Image(16, 8, glm::vec4(1.0f)), {});
  int status = 0;
  std::string log = bake(
      scene.string() + " -o " + out.string() + " --ao-rays 4 --specular-samples 16 --lut-size 8", &status);
  ASSERT_EQ(status, 0) << log;
  nlohmann::json report = nlohmann::json::parse(std::ifstream(out / "bake.json"));
  EXPECT_EQ(report["parameters"]["environment_rotation_degrees"], 30.0);
  EXPECT_EQ(report["parameters"]["environment_intensity"], 2.0);
  log = bake(scene.string() + " -o " + out.string() +
                 " --ao-rays 4 --specular-samples 16 --lut-size 8 --env-rotation 90 --env-intensity 0.5",
             &status);
  ASSERT_EQ(status, 0) << log;
  report = nlohmann::json::parse(std::ifstream(out / "bake.json"));
  EXPECT_EQ(report["parameters"]["environment_rotation_degrees"], 90.0);
  EXPECT_EQ(report["parameters"]["environment_intensity"], 0.5);
  // A uniform map of radiance 1 at intensity 0.5 (not the scene's 2): SH9's DC term is
  // 0.5 * Y00 * 4 pi = 0.5 * 2 sqrt(pi).
  const nlohmann::json sh = nlohmann::json::parse(std::ifstream(out / "env" / "sh9.json"));
  EXPECT_NEAR(sh["L"][0][0].get<float>(), std::sqrt(glm::pi<float>()), 0.01f * std::sqrt(glm::pi<float>()));

  log = bake(scene.string() + " -o " + out.string() + " --env-intensity -1", &status);
  EXPECT_EQ(status, 2);
  EXPECT_EQ(log, "iblkit-bake: --env-intensity: must be finite and >= 0\n");
}

// Every program's command-line errors: one line naming the program, status 2 (cli/program.h).
TEST(IblkitBake, ABadOptionIsOneLineAndStatusTwo) {
  test::expectUsageError(
      (test::binDir() / "iblkit-bake").string() + " scene.json -o out --env-format cubecross",
      "iblkit-bake: --env-format: unknown environment format 'cubecross' (expected one of "
      "latlong, mirrorball, angular)");
}

TEST(IblkitBake, VisibilityOptionsAreRecorded) {
  const fs::path root = test::scratchDir();
  const fs::path scene = writeBallScene(root), out = root / "out";
  int status = 0;
  const std::string log = bake(scene.string() + " -o " + out.string() +
                                   " --ao-rays 16 --bounces 2 --ao-area --ao-distance 3 --ao-falloff 1",
                               &status);
  ASSERT_EQ(status, 0) << log;
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(out / "bake.json"));
  EXPECT_EQ(report["parameters"]["bounces"], 2);
  EXPECT_EQ(report["parameters"]["ao_area"], true);
  EXPECT_EQ(report["parameters"]["ao_falloff"], 1.0);
  EXPECT_EQ(report["parameters"]["ao_distance"], 3.0);
  EXPECT_EQ(report["counts"]["bounce_rays"], 2 * report["counts"]["rays"].get<std::size_t>());
  for (const char* stage : {"visibility_build_s", "visibility_rays_s", "bounces_s"})
    EXPECT_GT(report["timings"][stage], 0.0) << stage;
}

std::string fileBytes(const fs::path& file) {
  std::ifstream stream(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>{});
}

// A small sky with a sun (test::sunnySky), 64 x 32.
fs::path writeSunnySky(const fs::path& file) {
  const EnvironmentMap sky = test::sunnySky(
      64, {test::SunDisk{.direction = glm::normalize(glm::vec3(0.5f, 0.7f, 0.3f)), .angularRadius = 0.05f}});
  writeExr(file, sky.image(), {.pixelType = PixelType::Float});
  return file;
}

// The bake folders `a` and `b` list the same ten outputs, and every one but bake.json (timings) has
// the same bytes.
void expectSameBake(const fs::path& a, const fs::path& b) {
  const nlohmann::json first = nlohmann::json::parse(std::ifstream(a / "bake.json"));
  const nlohmann::json second = nlohmann::json::parse(std::ifstream(b / "bake.json"));
  ASSERT_EQ(first["outputs"].size(), 10u);
  EXPECT_EQ(second["outputs"], first["outputs"]);
  for (const nlohmann::json& file : first["outputs"]) {
    const std::string name = file.get<std::string>();
    if (name == "bake.json") continue;
    const std::string bytes = fileBytes(a / name);
    EXPECT_FALSE(bytes.empty()) << name;
    EXPECT_TRUE(bytes == fileBytes(b / name)) << name;
  }
}

// --visibility-from takes the per-vertex visibility of another bake of the scene (here one with
// --visibility-only, under no map) instead of tracing it: the bake is the same, byte for byte, as
// one that traces it, the suns' bounce (which reads the map) included.
TEST(IblkitBake, VisibilityFromAnotherBakeIsTheSameBakeByteForByte) {
  const fs::path root = test::scratchDir();
  const fs::path scene = writeBallScene(root), env = writeSunnySky(root / "sky.exr");
  const std::string options = " --ao-rays 16 --bounces 1 --ao-area --specular-samples 64 --lut-size 16";
  int status = 0;
  std::string log = bake(scene.string() + " --env " + env.string() + options + " -o " + (root / "full").string(), &status);
  ASSERT_EQ(status, 0) << log;
  log = bake(scene.string() + options + " --visibility-only -o " + (root / "visibility").string(), &status);
  ASSERT_EQ(status, 0) << log;
  const nlohmann::json visibility = nlohmann::json::parse(std::ifstream(root / "visibility" / "bake.json"));
  EXPECT_EQ(visibility["outputs"], nlohmann::json({"scene.glb", "bake.json"}));
  EXPECT_FALSE(fs::exists(root / "visibility" / "env"));
  log = bake(scene.string() + " --env " + env.string() + options + " --visibility-from " +
                 (root / "visibility").string() + " -o " + (root / "reused").string(),
             &status);
  ASSERT_EQ(status, 0) << log;
  const nlohmann::json full = nlohmann::json::parse(std::ifstream(root / "full" / "bake.json"));
  const nlohmann::json reused = nlohmann::json::parse(std::ifstream(root / "reused" / "bake.json"));
  expectSameBake(root / "full", root / "reused");
  EXPECT_EQ(reused["visibility_from"], (root / "visibility").string());
  EXPECT_EQ(reused["counts"]["rays"], 0);
  EXPECT_EQ(reused["counts"]["vertices"], full["counts"]["vertices"]);
  // The map has a sun, so the byte comparison covers its bounce, traced on the reused visibility.
  const Scene baked = loadScene(root / "reused" / "scene.glb");
  EXPECT_TRUE(baked.meshes.front().attributes.contains(kSunBounceAttribute));
  EXPECT_GT(full["counts"]["sun_bounce_rays"].get<std::size_t>(), 0u);
}

// A visibility baked with other options, or of another scene, is refused with one line naming the
// file, and nothing is written.
TEST(IblkitBake, VisibilityFromRefusesOtherOptionsAndOtherScenes) {
  const fs::path root = test::scratchDir();
  const fs::path scene = writeBallScene(root), out = root / "out", visibility = root / "visibility";
  int status = 0;
  std::string log = bake(scene.string() + " --ao-rays 16 --visibility-only -o " + visibility.string(), &status);
  ASSERT_EQ(status, 0) << log;
  const auto refused = [&](const std::string& arguments, const std::string& message) {
    expectRefused(arguments, out, message);
  };
  refused(scene.string() + " --ao-rays 8 --visibility-from " + visibility.string(),
          (visibility / "bake.json").string() +
              ": visibility baked with ao_rays 16, not 8 (--visibility-from needs the same visibility options)");
  refused(scene.string() + " --ao-rays 16 --bounces 1 --visibility-from " + visibility.string(),
          (visibility / "bake.json").string() +
              ": visibility baked with bounces 0, not 1 (--visibility-from needs the same visibility options)");
  // The same ball in another colour: the same meshes, but the bounces reflect another albedo. The
  // scene files' hash (scene_hash) tells them apart.
  const fs::path recoloured = root / "recoloured.json";
  std::ofstream(recoloured) << R"({"models": [{"file": "models/ball.glb", "translation": [0, 0.5, 0],
    "material": {"baseColor": [0.2, 0.7, 0.6], "metallic": 0}}], "ground": {},
    "camera": {"position": [0, 1, 4], "target": [0, 0.5, 0]}})";
  refused(recoloured.string() + " --ao-rays 16 --visibility-from " + visibility.string(),
          (visibility / "bake.json").string() + ": baked from other scene files than " + recoloured.string() +
              " (its scene_hash differs: the scene, a model or a texture is not the same)");
  // Meshes that differ under a matching hash (a bake.json edited by hand) are refused too: the same
  // ball a little higher, its hash written into the first bake's record.
  const fs::path moved = root / "moved.json", movedBake = root / "moved_visibility";
  std::ofstream(moved) << R"({"models": [{"file": "models/ball.glb", "translation": [0, 0.6, 0]}], "ground": {}})";
  log = bake(moved.string() + " --ao-rays 16 --visibility-only -o " + movedBake.string(), &status);
  ASSERT_EQ(status, 0) << log;
  nlohmann::json record = nlohmann::json::parse(std::ifstream(visibility / "bake.json"));
  record["scene_hash"] = nlohmann::json::parse(std::ifstream(movedBake / "bake.json"))["scene_hash"];
  std::ofstream(visibility / "bake.json") << record.dump(2);
  const std::string output =
      bake(moved.string() + " --ao-rays 16 --visibility-from " + visibility.string() + " -o " + out.string(), &status);
  EXPECT_EQ(status, 1) << output;
  EXPECT_EQ(output.rfind("iblkit-bake: " + (visibility / "scene.glb").string() + ": mesh ", 0), 0u) << output;
  EXPECT_NE(output.find("is not the scene's (not a bake of this scene)\n"), std::string::npos) << output;
  EXPECT_FALSE(fs::exists(out));
  refused(scene.string() + " --ao-rays 16 --visibility-from " + (root / "absent").string(),
          (root / "absent").string() + ": no such bake folder");
  // A source whose bake.json is broken: one line naming it (its inputs and parameters are read from
  // one reading of the file).
  const fs::path broken = root / "broken";
  fs::copy(visibility, broken);
  const fs::path brokenRecord = broken / "bake.json";
  const nlohmann::json whole = nlohmann::json::parse(std::ifstream(brokenRecord));
  std::ofstream(brokenRecord) << whole.dump(2).substr(0, 40);
  const std::string truncated =
      bake(scene.string() + " --ao-rays 16 --visibility-from " + broken.string() + " -o " + out.string(), &status);
  EXPECT_EQ(status, 1) << truncated;
  EXPECT_EQ(truncated.rfind("iblkit-bake: " + brokenRecord.string() + ": not valid JSON: ", 0), 0u) << truncated;
  EXPECT_FALSE(fs::exists(out));
  for (const nlohmann::json& parameters : {nlohmann::json(), nlohmann::json(3)}) {
    nlohmann::json edited = whole;
    if (parameters.is_null())
      edited.erase("parameters");
    else
      edited["parameters"] = parameters;
    std::ofstream(brokenRecord) << edited.dump(2);
    refused(scene.string() + " --ao-rays 16 --visibility-from " + broken.string(), brokenRecord.string() + ": no parameters");
  }
  test::expectUsageError((test::binDir() / "iblkit-bake").string() + " " + scene.string() +
                             " --visibility-only --visibility-from " + visibility.string() + " -o " + out.string(),
                         "iblkit-bake: --visibility-only excludes --visibility-from");
  EXPECT_EQ(leftovers(root), 0);
}

// A map's environment stages baked once (--environment-only, no scene) and copied into a scene's
// bake (--environment-from) make the same bake as one that computes them: every file but bake.json's
// timings, byte for byte, the suns' bounce from the lights read back included.
TEST(IblkitBake, EnvironmentFromAnotherBakeIsTheSameBakeByteForByte) {
  const fs::path root = test::scratchDir();
  const fs::path scene = writeBallScene(root), env = writeSunnySky(root / "sky.exr");
  const std::string options = " --ao-rays 16 --specular-samples 64 --lut-size 16 --env-rotation 30 --env-intensity 2";
  int status = 0;
  std::string log = bake(scene.string() + " --env " + env.string() + options + " -o " + (root / "full").string(), &status);
  ASSERT_EQ(status, 0) << log;
  log = bake("--env " + env.string() + options + " --environment-only -o " + (root / "environment").string(), &status);
  ASSERT_EQ(status, 0) << log;
  const nlohmann::json environment = nlohmann::json::parse(std::ifstream(root / "environment" / "bake.json"));
  EXPECT_FALSE(fs::exists(root / "environment" / "scene.glb"));
  EXPECT_EQ(environment["outputs"].size(), 9u);  // the full bake's but scene.glb
  EXPECT_EQ(environment["inputs"]["scene"], "");
  log = bake(scene.string() + " --env " + env.string() + options + " --environment-from " +
                 (root / "environment").string() + " -o " + (root / "reused").string(),
             &status);
  ASSERT_EQ(status, 0) << log;
  const nlohmann::json full = nlohmann::json::parse(std::ifstream(root / "full" / "bake.json"));
  const nlohmann::json reused = nlohmann::json::parse(std::ifstream(root / "reused" / "bake.json"));
  expectSameBake(root / "full", root / "reused");
  EXPECT_EQ(reused["environment"], full["environment"]);
  EXPECT_EQ(reused["parameters"], full["parameters"]);
  EXPECT_EQ(reused["environment_hash"], full["environment_hash"]);
  EXPECT_EQ(reused["environment_from"], (root / "environment").string());
  EXPECT_FALSE(full.contains("environment_from"));
  EXPECT_FALSE(reused["timings"].contains("specular_s"));
  // The map has a sun, so the byte comparison covers its bounce, traced from the lights read back.
  EXPECT_GT(reused["counts"]["sun_bounce_rays"].get<std::size_t>(), 0u);
  // A full bake serves as the source too, and so does an environment-only bake named by a scene.
  log = bake(scene.string() + " --env " + env.string() + options + " --environment-only -o " +
                 (root / "scene_environment").string(),
             &status);
  ASSERT_EQ(status, 0) << log;
  for (const char* from : {"full", "scene_environment"}) {
    const fs::path out = root / (std::string("from_") + from);
    log = bake(scene.string() + " --env " + env.string() + options + " --environment-from " + (root / from).string() +
                   " -o " + out.string(),
               &status);
    ASSERT_EQ(status, 0) << log;
    EXPECT_TRUE(fileBytes(out / "scene.glb") == fileBytes(root / "full" / "scene.glb")) << from;
    EXPECT_TRUE(fileBytes(out / "env/specular.exr") == fileBytes(root / "full" / "env/specular.exr")) << from;
  }
}

// Environment stages of another map, of the same map under other options, or no environment at all
// are refused with one line naming the file, and nothing is written.
TEST(IblkitBake, EnvironmentFromRefusesOtherMapsAndOtherOptions) {
  const fs::path root = test::scratchDir();
  const fs::path scene = writeBallScene(root), env = writeSunnySky(root / "sky.exr"), out = root / "out",
                 environment = root / "environment";
  const std::string options = " --specular-samples 16 --lut-size 8";
  int status = 0;
  std::string log = bake("--env " + env.string() + options + " --environment-only -o " + environment.string(), &status);
  ASSERT_EQ(status, 0) << log;
  const auto refused = [&](const std::string& arguments, const std::string& message) {
    expectRefused(arguments, out, message);
  };
  const std::string record = (environment / "bake.json").string();
  const std::string bakeOf = scene.string() + " --ao-rays 4 --env " + env.string();
  const std::string from = " --environment-from " + environment.string();
  const std::string needs = " (--environment-from needs the same map and environment options)";
  refused(bakeOf + " --specular-samples 32 --lut-size 8" + from,
          record + ": environment baked with specular_samples 16, not 32" + needs);
  refused(bakeOf + " --specular-samples 16 --lut-size 16" + from,
          record + ": environment baked with lut_size 8, not 16" + needs);
  refused(bakeOf + options + " --max-suns 1" + from, record + ": environment baked with max_suns 4, not 1" + needs);
  refused(bakeOf + options + " --env-rotation 90" + from,
          record + ": environment baked with environment_rotation_degrees 0.0, not 90.0" + needs);
  refused(bakeOf + options + " --env-intensity 0.5" + from,
          record + ": environment baked with environment_intensity 1.0, not 0.5" + needs);
  // A bake from before lut_size was recorded.
  const fs::path older = root / "older";
  fs::copy(environment, older, fs::copy_options::recursive);
  nlohmann::json olderRecord = nlohmann::json::parse(std::ifstream(older / "bake.json"));
  olderRecord["parameters"].erase("lut_size");
  std::ofstream(older / "bake.json") << olderRecord.dump(2);
  refused(bakeOf + options + " --environment-from " + older.string(),
          (older / "bake.json").string() +
              ": no parameter lut_size (a bake from before it was recorded?); --environment-from needs the same map "
              "and environment options");
  // The same map's bytes under another name are the same map; one texel changed is another.
  const fs::path copy = root / "copy.exr", changed = root / "changed.exr";
  fs::copy_file(env, copy);
  log = bake(scene.string() + " --ao-rays 4 --env " + copy.string() + options + from + " -o " + (root / "copied").string(),
             &status);
  EXPECT_EQ(status, 0) << log;
  Image sky = readExr(env);
  sky.at(3, 3).r += 1.0f;
  writeExr(changed, sky);
  refused(scene.string() + " --ao-rays 4 --env " + changed.string() + options + from,
          record + ": baked from another map than this bake's (its environment_hash differs: another file, or the "
                   "map changed since)");
  // A bake without an environment, a folder that is none, a scene without a map.
  const fs::path visibility = root / "visibility";
  log = bake(scene.string() + " --ao-rays 4 --visibility-only -o " + visibility.string(), &status);
  ASSERT_EQ(status, 0) << log;
  refused(bakeOf + options + " --environment-from " + visibility.string(),
          (visibility / "bake.json").string() +
              ": the bake has no environment stages (--environment-from needs a bake with a map)");
  refused(bakeOf + options + " --environment-from " + (root / "absent").string(),
          (root / "absent").string() + ": no such bake folder");
  refused(scene.string() + " --ao-rays 4" + options + from,
          scene.string() + ": the scene names no environment map (--environment-from needs one; give --env FILE)");
  const std::string program = (test::binDir() / "iblkit-bake").string() + " ";
  test::expectUsageError(program + "--environment-only -o " + out.string(),
                         "iblkit-bake: --env: required by --environment-only without a scene");
  test::expectUsageError(program + "--env " + env.string() + " -o " + out.string(),
                         "iblkit-bake: scene: required (only --environment-only bakes without a scene, the map from --env)");
  test::expectUsageError(program + scene.string() + " --environment-only --visibility-only -o " + out.string(),
                         "iblkit-bake: --visibility-only excludes --environment-only");
  test::expectUsageError(program + scene.string() + " --environment-only" + from + " -o " + out.string(),
                         "iblkit-bake: --environment-only excludes --environment-from");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(leftovers(root), 0);
}

TEST(IblkitBake, FalloffWithoutADistanceIsRefusedWithoutOutput) {
  const fs::path root = test::scratchDir();
  const fs::path scene = writeBallScene(root), out = root / "out";
  int status = 0;
  const std::string log = bake(scene.string() + " -o " + out.string() + " --ao-falloff 2", &status);
  EXPECT_EQ(status, 1);
  EXPECT_EQ(log, "iblkit-bake: vertex visibility: a falloff needs a maximum distance (--ao-distance > 0)\n");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(leftovers(root), 0);
}

}  // namespace
}  // namespace iblkit
