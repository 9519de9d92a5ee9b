// End-to-end tests of the iblkit-trace program: a .json scene with a glTF cube and an OpenEXR
// environment written to a scratch folder, rendered small.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <vector>

#include "core/image_io.h"
#include "core/scene.h"
#include "core/scene_environment.h"
#include "reference/renderer.h"
#include "support/gltf_builder.h"
#include "support/test_paths.h"
#include "support/texture_files.h"

namespace iblkit {
namespace {

class IblkitTrace : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::scratchDir();
    test::GltfBuilder gltf;
    const test::CubeGeometry cube = test::unitCube();
    std::vector<glm::vec3> normals;
    for (const glm::vec3& p : cube.positions) normals.push_back(glm::normalize(p - glm::vec3(0.5f)));
    gltf.addPrimitiveNode(
        {{"attributes", {{"POSITION", gltf.addFloats(cube.positions)}, {"NORMAL", gltf.addFloats(normals)}}},
         {"indices", gltf.addIndices(cube.indices)}});
    gltf.write(dir_ / "cube.glb", test::GltfBuilder::Storage::Glb);
    writeExr(dir_ / "env.exr", Image(16, 8, glm::vec4(0.5f, 0.625f, 0.75f, 1.0f)));
    std::ofstream(dir_ / "scene.json") << R"({"models": [{"file": "cube.glb"}], "ground": {},
        "environment": {"file": "env.exr"}, "width": 24, "height": 16})";
  }

  // Runs iblkit-trace with `arguments` in the scratch folder; returns the exit status.
  int trace(const std::string& arguments, std::string* output) const {
    return test::runCommand(
        "cd '" + dir_.string() + "' && '" + (test::binDir() / "iblkit-trace").string() + "' " + arguments,
        output);
  }

  std::filesystem::path dir_;
};

TEST_F(IblkitTrace, WritesTheBeautyLayersAndPreview) {
  std::string output;
  ASSERT_EQ(trace("scene.json -o out.exr --png out.png --mask mask.exr --depth depth.exr --spp 4 --threads 2",
                  &output),
            0)
      << output;
  EXPECT_NE(output.find("24x16, 4 spp, "), std::string::npos) << output;
  EXPECT_NE(output.find(" Mrays/s"), std::string::npos) << output;
  const Image beauty = readExr(dir_ / "out.exr");
  EXPECT_EQ(beauty.width(), 24);
  EXPECT_EQ(beauty.height(), 16);
  // The top-left corner sees the environment itself.
  EXPECT_EQ(beauty.at(0, 0), glm::vec4(0.5f, 0.625f, 0.75f, 1.0f));
  EXPECT_EQ(readPng(dir_ / "out.png").width(), 24);
  EXPECT_GT(readExr(dir_ / "mask.exr").stats().max.r, 0.9f);
  EXPECT_GT(readExr(dir_ / "depth.exr").stats().max.r, 0.0f);
}

// --env-orientation none renders the plain environment sampler's image, the default (normal) the
// oriented one's: the same image within the noise of 64 spp, and not the same samples.
TEST_F(IblkitTrace, EnvironmentOrientationsRenderTheSameImage) {
  std::string output;
  ASSERT_EQ(trace("scene.json -o oriented.exr --spp 64 --threads 2", &output), 0) << output;
  ASSERT_EQ(trace("scene.json -o plain.exr --spp 64 --threads 2 --env-orientation none", &output), 0) << output;
  const Image oriented = readExr(dir_ / "oriented.exr"), plain = readExr(dir_ / "plain.exr");
  EXPECT_NEAR(oriented.stats().meanLuminance / plain.stats().meanLuminance, 1.0, 0.01);
  EXPECT_NE(oriented.pixels(), plain.pixels());
}

// mediancut samples the map unbiasedly (the image's mean is mis's within the noise of 64 spp);
// lights with 16 point lights renders the biased approximation; both show the map itself where
// the camera sees it.
TEST_F(IblkitTrace, MedianCutStrategiesRender) {
  std::string output;
  ASSERT_EQ(trace("scene.json -o mis.exr --spp 64 --threads 2", &output), 0) << output;
  ASSERT_EQ(trace("scene.json -o mediancut.exr --spp 64 --threads 2 --env-sampling mediancut --env-lights 16",
                  &output),
            0)
      << output;
  ASSERT_EQ(
      trace("scene.json -o lights.exr --spp 64 --threads 2 --env-sampling lights --env-lights 16", &output),
      0)
      << output;
  const Image mis = readExr(dir_ / "mis.exr"), medianCut = readExr(dir_ / "mediancut.exr"),
              lights = readExr(dir_ / "lights.exr");
  EXPECT_NEAR(medianCut.stats().meanLuminance / mis.stats().meanLuminance, 1.0, 0.01);
  for (const Image* image : {&medianCut, &lights}) {
    EXPECT_EQ(image->at(0, 0), glm::vec4(0.5f, 0.625f, 0.75f, 1.0f));
    EXPECT_TRUE(std::isfinite(image->stats().meanLuminance));
  }
  EXPECT_GT(lights.stats().meanLuminance, 0.0f);
}

TEST_F(IblkitTrace, OverridesSizeAndEnvironment) {
  writeExr(dir_ / "red.exr", Image(16, 8, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f)));
  std::string output;
  ASSERT_EQ(
      trace("scene.json -o out.exr --width 8 --height 4 --spp 1 --env red.exr --env-intensity 2", &output), 0)
      << output;
  const Image beauty = readExr(dir_ / "out.exr");
  EXPECT_EQ(beauty.width(), 8);
  EXPECT_EQ(beauty.at(0, 0), glm::vec4(2.0f, 0.0f, 0.0f, 1.0f));
}

// A map with NaN pixels is repaired by the loader and a black one leaves only emission: both
// render finite images, with a warning naming the file.
TEST_F(IblkitTrace, BrokenAndBlackEnvironmentsRenderWithoutNaN) {
  writeExr(dir_ / "black.exr", Image(16, 8, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)));
  const std::pair<std::string, std::string> cases[] = {
      {(test::dataDir() / "bad" / "nan_pixels.exr").string(),
       "warning: 3 NaN, 1 Inf and 2 negative pixel values"},
      {"black.exr", "black.exr: warning: environment is black everywhere: only emission will show"},
  };
  for (const auto& [environment, warning] : cases) {
    std::string output;
    ASSERT_EQ(trace("scene.json -o out.exr --spp 2 --env '" + environment + "'", &output), 0) << output;
    EXPECT_NE(output.find(warning), std::string::npos) << output;
    const Image image = readExr(dir_ / "out.exr");
    for (const glm::vec4& pixel : image.pixels())
      ASSERT_TRUE(std::isfinite(pixel.r) && std::isfinite(pixel.g) && std::isfinite(pixel.b)) << environment;
  }
}

// --filter gaussian reaches the renderer: the object's mask gets softer edges than with box.
TEST_F(IblkitTrace, GaussianFilterSoftensEdges) {
  std::string output;
  ASSERT_EQ(trace("scene.json -o box.exr --mask box_mask.exr --spp 16 --filter box", &output), 0) << output;
  ASSERT_EQ(trace("scene.json -o gauss.exr --mask gauss_mask.exr --spp 16 --filter gaussian", &output), 0)
      << output;
  const auto partial = [](const Image& mask) {
    int count = 0;
    for (const glm::vec4& m : mask.pixels()) count += m.r > 0.0f && m.r < 1.0f;
    return count;
  };
  EXPECT_GT(partial(readExr(dir_ / "gauss_mask.exr")), partial(readExr(dir_ / "box_mask.exr")));
}

// The texture options on an untextured scene: nothing to switch off, no texture level to pick,
// so the image is bit for bit the default one.
TEST_F(IblkitTrace, TextureOptionsLeaveAnUntexturedSceneAlone) {
  std::string output;
  ASSERT_EQ(trace("scene.json -o a.exr --spp 2 --threads 2", &output), 0) << output;
  ASSERT_EQ(trace("scene.json -o b.exr --spp 2 --threads 2 --no-textures --texture-footprint 0", &output), 0)
      << output;
  EXPECT_EQ(readExr(dir_ / "a.exr").pixels(), readExr(dir_ / "b.exr").pixels());
}

// A glb quad [-1, 1]^2 facing a camera at z = 3 that it fills exactly, black, MASK, its PNG base
// colour texture 4 x 4 with the centre 2 x 2 texels at alpha 0 (NEAREST): the pixels through the
// hole are exactly the environment, read, decoded and filtered by the loader and the tracer.
TEST_F(IblkitTrace, MaskedHoleInAGlbShowsTheEnvironment) {
  test::GltfBuilder gltf;
  const std::vector<glm::vec3> positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  const std::vector<glm::vec3> normals(4, glm::vec3(0, 0, 1));
  const std::vector<glm::vec2> uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  std::vector<std::uint8_t> rgba;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const bool hole = (x == 1 || x == 2) && (y == 1 || y == 2);
      rgba.insert(rgba.end(), {255, 255, 255, std::uint8_t(hole ? 0 : 255)});
    }
  const int image = gltf.addImage(test::encodePng(4, 4, rgba), "image/png");
  nlohmann::json& doc = gltf.document();
  doc["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9728}}};
  doc["textures"] = {{{"source", image}, {"sampler", 0}}};
  doc["materials"] = {
      {{"pbrMetallicRoughness",
        {{"baseColorFactor", {0, 0, 0, 1}}, {"metallicFactor", 0}, {"baseColorTexture", {{"index", 0}}}}},
       {"alphaMode", "MASK"},
       {"doubleSided", true}}};
  gltf.addPrimitiveNode({{"attributes",
                          {{"POSITION", gltf.addFloats(positions)},
                           {"NORMAL", gltf.addFloats(normals)},
                           {"TEXCOORD_0", gltf.addFloats(uvs)}}},
                         {"indices", gltf.addIndices({0, 1, 2, 0, 2, 3})},
                         {"material", 0}});
  doc["cameras"] = {
      {{"type", "perspective"},
       {"perspective", {{"yfov", 2.0 * std::atan(1.0 / 3.0)}, {"znear", 0.1}, {"aspectRatio", 1.0}}}}};
  gltf.addNode({{"camera", 0}, {"translation", {0, 0, 3}}});
  gltf.write(dir_ / "holed.glb", test::GltfBuilder::Storage::Glb);

  std::string output;
  ASSERT_EQ(trace("holed.glb --env env.exr -o holed.exr --width 16 --height 16 --spp 4 --threads 2", &output),
            0)
      << output;
  const Image beauty = readExr(dir_ / "holed.exr");
  const glm::vec4 sky(0.5f, 0.625f, 0.75f, 1.0f);
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) {
      if (i % 4 == 0 || i % 4 == 3 || j % 4 == 0 || j % 4 == 3) continue;  // astride a texel edge
      const bool hole = (i / 4 == 1 || i / 4 == 2) && (j / 4 == 1 || j / 4 == 2);
      if (hole)
        EXPECT_EQ(beauty.at(i, j), sky) << i << ", " << j;
      else
        EXPECT_LT(beauty.at(i, j).g, 0.1f) << i << ", " << j;  // the black card (its specular layer only)
    }
}

std::vector<char> bytesOf(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A render split into passes (--pass I --passes N --sum) and merged (--merge) is the single run of
// the same samples, file for file (beauty and variance); a render of more samples continues one
// of fewer (samples 0..3 of --spp 4 and 4..7 of --spp 8 are --spp 8).
TEST_F(IblkitTrace, SplitPassesMergeIntoTheSingleRunByteForByte) {
  std::string output;
  const std::string common = "scene.json --spp 8 --threads 2";
  ASSERT_EQ(trace(common + " -o single.exr --variance single_variance.exr --sum single.sum", &output), 0)
      << output;
  for (int pass = 0; pass < 3; ++pass)
    ASSERT_EQ(trace(common + " --passes 3 --pass " + std::to_string(pass) + " --sum pass" +
                        std::to_string(pass) + ".sum",
                    &output),
              0)
        << output;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out.exr"));
  ASSERT_EQ(trace("--merge pass2.sum pass0.sum pass1.sum -o merged.exr --variance merged_variance.exr --sum "
                  "merged.sum",
                  &output),
            0)
      << output;
  EXPECT_EQ(output, "24x16, 8 spp merged from 3 files\n");
  EXPECT_EQ(bytesOf(dir_ / "merged.exr"), bytesOf(dir_ / "single.exr"));
  EXPECT_EQ(bytesOf(dir_ / "merged_variance.exr"), bytesOf(dir_ / "single_variance.exr"));
  EXPECT_EQ(bytesOf(dir_ / "merged.sum"), bytesOf(dir_ / "single.sum"));

  ASSERT_EQ(trace("scene.json --spp 4 --threads 1 --sum first.sum", &output), 0) << output;
  ASSERT_EQ(trace(common + " --pass 1 --passes 2 --sum second.sum", &output), 0) << output;
  ASSERT_EQ(trace("--merge first.sum second.sum -o continued.exr", &output), 0) << output;
  EXPECT_EQ(bytesOf(dir_ / "continued.exr"), bytesOf(dir_ / "single.exr"));
  // A merge with a pass missing is the mean of the samples it has, with a warning.
  ASSERT_EQ(trace("--merge pass0.sum pass2.sum -o gap.exr", &output), 0) << output;
  EXPECT_NE(output.find("--merge: warning: the samples merged are 0..1, 5..7, not one range from 0"),
            std::string::npos)
      << output;

  // Another seed is another render, and the same pass twice is refused; nothing is written.
  ASSERT_EQ(trace(common + " --seed 5 --passes 3 --pass 1 --sum other.sum", &output), 0) << output;
  EXPECT_EQ(trace("--merge pass0.sum other.sum -o refused.exr", &output), 1);
  EXPECT_EQ(output.rfind("iblkit-trace: other.sum: is a pass of another render", 0), 0u) << output;
  EXPECT_EQ(trace("--merge pass0.sum pass1.sum pass0.sum -o refused.exr", &output), 1);
  EXPECT_EQ(
      output,
      "iblkit-trace: pass0.sum: samples 0..1 overlap samples 0..4 already merged (the same pass twice?)\n");
  EXPECT_FALSE(std::filesystem::exists(dir_ / "refused.exr"));
}

// The program is the library, bit for bit: what the report, the scorer's tests and the sampling
// study measure in process is what users get from iblkit-trace. The program turns its options into
// the library's settings (its defaults, the map's sampler, the camera's aspect, the textures); a
// default that drifts, or a program built differently from the libraries the tests link (other
// flags, link-time optimisation), shows here. The bundled bunny under the sunny sky (the ground
// and its occlusion, every strategy mis uses, two light samples at the camera vertex) and the
// textured pmndrs model under studio, against the same render in this process, byte for byte.
TEST_F(IblkitTrace, TheProgramRendersWhatTheLibraryRendersBitForBit) {
  if (!std::filesystem::exists(test::assetsDir() / "models" / "pmndrs.glb"))
    GTEST_SKIP() << "assets not fetched";
  for (const char* name : {"bunny", "pmndrs"}) {
    const std::filesystem::path file = test::assetsDir() / "scenes" / (std::string(name) + ".json");
    std::string arguments = file.string();  // (appended, not "'" + ...: GCC 12's -Wrestrict misfires)
    arguments.insert(arguments.begin(), '\'');
    arguments += std::string("' -o ") + name +
                 ".exr --width 64 --height 36 --spp 4 --threads 2 --camera-light-samples 2";
    std::string output;
    ASSERT_EQ(trace(arguments, &output), 0) << output;

    Scene scene = loadScene(file);
    const EnvironmentMap environment = loadSceneEnvironment(scene);
    const EnvironmentSampler sampler(environment);
    const Camera camera = sceneCamera(scene, 64.0f / 36.0f);
    const RenderScene renderScene(std::move(scene));
    IntegratorSettings integratorSettings;
    integratorSettings.cameraLightSamples = 2;
    const Integrator integrator(renderScene, environment, sampler, integratorSettings);
    RenderSettings settings;
    settings.width = 64;
    settings.height = 36;
    settings.samplesPerPixel = 4;
    settings.threads = 2;
    // Compared as files: readExr would set the few negative pixels of 4 spp to 0 (a sample of the
    // ground's control variate can be negative, docs/reference-tracer.md).
    const std::filesystem::path library = dir_ / (std::string(name) + "-library.exr");
    writeExr(library, render(integrator, camera, settings).beauty, {.pixelType = PixelType::Float});
    EXPECT_TRUE(bytesOf(dir_ / (std::string(name) + ".exr")) == bytesOf(library))
        << name << ": iblkit-trace's image is not the library's";
  }
}

// --noise-split: the halves' mean as the beauty, and their noise as JSON and on stdout.
TEST_F(IblkitTrace, NoiseSplitWritesTheMeanAndTheHalvesNoise) {
  std::string output;
  ASSERT_EQ(
      trace("scene.json -o out.exr --spp 8 --threads 2 --camera-light-samples 4 --noise-split noise.json",
            &output),
      0)
      << output;
  EXPECT_NE(output.find("24x16, 8 spp, "), std::string::npos) << output;
  EXPECT_NE(output.find("noise split: relMSE of the mean "), std::string::npos) << output;
  EXPECT_EQ(readExr(dir_ / "out.exr").width(), 24);
  std::ifstream json(dir_ / "noise.json");
  const std::string text((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
  for (const char* key :
       {"\"relMseEstimate\"", "\"halvesMeanFlip\"", "\"byFirstHit\"", "\"object\"", "\"ground\""})
    EXPECT_NE(text.find(key), std::string::npos) << key << " in " << text;
}

TEST_F(IblkitTrace, BadArgumentsGiveOneLineErrors) {
  struct Case {
    std::string arguments;
    int status;  // 2: the command line, 1: a file (cli/program.h)
    std::string message;
  };
  const Case cases[] = {
      {"scene.json -o out.exr --spp 0", 2, "iblkit-trace: --spp: must be in 1..16777216, not 0\n"},
      {"scene.json -o out.exr --spp 16777217", 2,
       "iblkit-trace: --spp: must be in 1..16777216, not 16777217\n"},
      {"scene.json -o out.exr --width 20000", 2, "iblkit-trace: --width: must be in 1..16384, not 20000\n"},
      {"scene.json -o out.exr --height -4", 2, "iblkit-trace: --height: must be in 1..16384, not -4\n"},
      {"scene.json -o out.exr --threads -1", 2, "iblkit-trace: --threads: must be in 0..1024, not -1\n"},
      {"scene.json -o out.exr --threads 70000", 2,
       "iblkit-trace: --threads: must be in 0..1024, not 70000\n"},
      // Checked before anything is read: the range error, not the missing scene.
      {"missing.json -o out.exr --spp 0", 2, "iblkit-trace: --spp: must be in 1..16777216, not 0\n"},
      {"scene.json -o out.exr --integrator bidir", 2,
       "iblkit-trace: --integrator: unknown integrator 'bidir' (expected one of path, direct, ao)\n"},
      {"scene.json -o out.exr --env-sampling light", 2,
       "iblkit-trace: --env-sampling: unknown strategy 'light' (expected one of uniform, cosine, brdf, env, "
       "mis, mediancut, lights)\n"},
      {"scene.json -o out.exr --env-sampling lights --env-lights 48", 2,
       "iblkit-trace: --env-lights: must be a power of 2 in 1..4096, not 48\n"},
      {"scene.json -o out.exr --env-sampling mediancut --env-lights 8192", 2,
       "iblkit-trace: --env-lights: must be a power of 2 in 1..4096, not 8192\n"},
      {"scene.json -o out.exr --env-orientation up", 2,
       "iblkit-trace: --env-orientation: unknown orientation 'up' (expected one of none, normal)\n"},
      {"scene.json -o out.exr --env-lights 16", 2,
       "iblkit-trace: --env-lights: needs --env-sampling mediancut or lights\n"},
      {"scene.json -o out.exr --env missing.exr", 1,
       "iblkit-trace: missing.exr: cannot open: No such file or directory\n"},
      {"scene.json -o out.exr --filter tent", 2,
       "iblkit-trace: --filter: unknown filter 'tent' (expected one of box, gaussian)\n"},
      {"scene.json -o nowhere/out.exr", 1, "iblkit-trace: nowhere/out.exr: folder does not exist\n"},
      {"scene.json -o out.exr --bent-normal b.exr", 2,
       "iblkit-trace: --bent-normal: needs --integrator ao\n"},
      {"scene.json -o out.exr --texture-footprint -1", 2,
       "iblkit-trace: --texture-footprint: must be >= 0 (pixels)\n"},
      {"scene.json -o out.exr --camera-light-samples 0", 2,
       "iblkit-trace: --camera-light-samples: must be in 1..64, not 0\n"},
      {"scene.json -o out.exr --spp 5 --noise-split noise.json", 2,
       "iblkit-trace: --noise-split: needs an even --spp (half of it for each half)\n"},
      {"scene.json -o out.exr --noise-split noise.json --passes 2 --pass 0", 2,
       "iblkit-trace: --noise-split: renders its own two halves; it does not go with --pass or --sum\n"},
      {"scene.json", 2, "iblkit-trace: --output is required\n"},
      {"-o out.exr", 2, "iblkit-trace: scene is required\n"},
      {"scene.json -o out.exr --pass 1", 2, "iblkit-trace: --pass requires --passes\n"},
      {"scene.json -o out.exr --pass 4 --passes 4 --spp 8", 2,
       "iblkit-trace: --pass: must be in 0..3, not 4\n"},
      {"scene.json -o out.exr --pass 0 --passes 9 --spp 8", 2,
       "iblkit-trace: --passes: must be in 1..8 (the --spp), not 9\n"},
      {"scene.json --pass 0 --passes 2 --time 1 --sum s.sum", 2,
       "iblkit-trace: --passes: cannot split a --time render\n"},
      {"--merge a.sum", 2, "iblkit-trace: --merge: needs an output (-o, --sum, --variance or --png)\n"},
      {"scene.json --merge a.sum -o out.exr", 2, "iblkit-trace: scene: does not apply to --merge\n"},
      {"--merge a.sum -o out.exr --spp 4", 2, "iblkit-trace: --spp: does not apply to --merge\n"},
      {"--merge a.sum --pass 1 --passes 2 -o out.exr", 2, "iblkit-trace: --pass excludes --merge\n"},
      {"--merge missing.sum -o out.exr", 1,
       "iblkit-trace: missing.sum: cannot open: No such file or directory\n"},
      {"scene.json --sum scene.json", 1,
       "iblkit-trace: scene.json: output is the same file as the input scene.json\n"},
      {"scene.json -o out.exr --no-such-option", 2,
       "iblkit-trace: The following argument was not expected: --no-such-option\n"},
  };
  for (const auto& [arguments, status, expected] : cases) {
    std::string output;
    EXPECT_EQ(trace(arguments, &output), status) << arguments;
    EXPECT_EQ(output, expected) << arguments;
  }
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out.exr"));
}

}  // namespace
}  // namespace iblkit
