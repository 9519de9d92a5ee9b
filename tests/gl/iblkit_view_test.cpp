// End-to-end tests of iblkit-view --headless (build/bin), on a scene baked by iblkit-bake, and its
// alignment with iblkit-trace.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include "bakefile/scene_glb.h"
#include "core/image_io.h"
#include "support/bake_fixture.h"
#include "support/gltf_builder.h"
#include "support/test_paths.h"
#include "support/texture_files.h"
#include "support/usage_error_check.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

// Built with += : GCC 12 gives a false -Wrestrict on "'" + std::string (its bug 105329).
std::string quoted(const fs::path& path) {
  std::string text = "'";
  text += path.string();
  text += "'";
  return text;
}

struct ProgramRun {
  int status = 0;
  std::string output;
};

ProgramRun run(const std::string& program, const std::string& arguments) {
  ProgramRun result;
  result.status = test::runCommand(quoted(test::binDir() / program) + " " + arguments, &result.output);
  return result;
}

struct Fixture {
  fs::path scene, environment, bake;
};

// A sphere on a ground plane with a camera, as .glb, an environment file, and its iblkit-bake folder,
// in `folder` (the test's scratch folder: test::scratchDir() empties it on every call).
Fixture makeFixture(const fs::path& folder) {
  Fixture made;
  Material plastic;
  plastic.baseColor = glm::vec3(0.6f, 0.5f, 0.4f);
  plastic.metallic = 0.0f;
  plastic.roughness = 0.5f;
  BakedScene scene = test::makeTestBake(
      {.sphereMaterial = plastic, .ground = true, .aoRays = 1, .rings = 24, .segments = 48});
  made.scene = folder / "scene.glb";
  writeSceneGlb(scene.scene, made.scene);
  made.environment = folder / "sky.exr";
  writeExr(made.environment, scene.env.latLong, {.pixelType = PixelType::Float});
  made.bake = folder / "bake";
  const ProgramRun bake =
      run("iblkit-bake", quoted(made.scene) + " --env " + quoted(made.environment) + " -o " +
                             quoted(made.bake) + " --ao-rays 16 --specular-samples 32 --lut-size 16");
  EXPECT_EQ(bake.status, 0) << bake.output;
  return made;
}

constexpr const char* kSize = " --width 128 --height 96";

constexpr const char* kEveryMode[] = {"unlit", "mirror",     "sh",   "irradiance", "irradiance-ao-bent", "sh-ao",
                                      "sh-ao-bent", "prt", "full", "lights", "lights-shadowed"};

// Every mode, from one run (--mode with a list, -o with {mode}).
TEST(IblkitView, RendersEveryModeToExrWithCoverageAlpha) {
  const fs::path dir = test::scratchDir();
  const Fixture fixture = makeFixture(dir);
  std::string list;
  for (const char* mode : kEveryMode) {
    if (!list.empty()) list += ',';
    list += mode;
  }
  // The irradiance modes read the bake's env/irradiance.exr.
  const ProgramRun r = run("iblkit-view", quoted(fixture.bake) + " --headless -o " + quoted(dir / "view_{mode}.exr") +
                                              kSize + " --mode " + list + " --samples 4");
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* mode : kEveryMode) {
    const Image image = readExr(dir / (std::string("view_") + mode + ".exr"));
    ASSERT_EQ(image.width(), 128);
    int covered = 0;
    for (const glm::vec4& p : image.pixels()) {
      ASSERT_TRUE(std::isfinite(p.r + p.g + p.b)) << mode;
      if (p.a == 1.0f) {
        ++covered;
        EXPECT_GT(p.r + p.g + p.b, 1e-3f) << mode;
      }
    }
    EXPECT_GT(covered, 1000) << mode;
  }
}

std::string fileBytes(const fs::path& file) {
  std::ifstream stream(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>{});
}

// Several modes in one run (what the report runs per case) write, byte for byte, the files that a
// run per mode writes, layers included, and --bench times each of them.
TEST(IblkitView, SeveralModesInOneRunAreTheRunsOfOneModeEach) {
  const fs::path dir = test::scratchDir();
  const Fixture fixture = makeFixture(dir);
  const std::string options = std::string(kSize) + " --samples 4 --sample-shading --supersample 2";
  const ProgramRun together =
      run("iblkit-view", quoted(fixture.bake) + " --headless -o " + quoted(dir / "together_{mode}.exr") + " --normal " +
                             quoted(dir / "together_{mode}_normal.exr") + " --depth " +
                             quoted(dir / "together_{mode}_depth.exr") + options +
                             " --mode sh,lights-shadowed,full --bench 2");
  ASSERT_EQ(together.status, 0) << together.output;
  for (const std::string mode : {"sh", "lights-shadowed", "full"}) {
    const ProgramRun alone = run("iblkit-view", quoted(fixture.bake) + " --headless -o " +
                                                    quoted(dir / ("alone_" + mode + ".exr")) + " --normal " +
                                                    quoted(dir / ("alone_" + mode + "_normal.exr")) + " --depth " +
                                                    quoted(dir / ("alone_" + mode + "_depth.exr")) + options +
                                                    " --mode " + mode);
    ASSERT_EQ(alone.status, 0) << alone.output;
    for (const std::string suffix : {".exr", "_normal.exr", "_depth.exr"}) {
      const std::string a = fileBytes(dir / ("together_" + mode + suffix)), b = fileBytes(dir / ("alone_" + mode + suffix));
      EXPECT_FALSE(a.empty()) << mode << suffix;
      EXPECT_TRUE(a == b) << mode << suffix;
    }
    EXPECT_NE(together.output.find("\n  " + mode + " "), std::string::npos) << together.output;
  }
  EXPECT_NE(fileBytes(dir / "together_sh.exr"), fileBytes(dir / "together_full.exr"));
}

// --supersample K renders K x K pixels per output pixel and box-filters them down; with
// --sample-shading every MSAA sample is shaded. Both keep the output size and the image's mean,
// and average the shading inside the object (not only at its edges), which plain MSAA does not.
TEST(IblkitView, SupersamplingAndSampleShadingAverageTheShadingOverThePixel) {
  const fs::path dir = test::scratchDir();
  const Fixture fixture = makeFixture(dir);
  auto render = [&](const std::string& name, const std::string& options) {
    const fs::path out = dir / (name + ".exr");
    const ProgramRun r =
        run("iblkit-view", quoted(fixture.bake) + " --headless --mode mirror -o " + quoted(out) + kSize + options);
    EXPECT_EQ(r.status, 0) << r.output;
    return readExr(out);
  };
  const Image plain = render("plain", " --samples 4");
  const Image shaded = render("shaded", " --samples 4 --sample-shading");
  const Image super = render("super", " --samples 4 --sample-shading --supersample 2");
  ASSERT_EQ(super.width(), 128);
  ASSERT_EQ(super.height(), 96);
  auto interiorDifference = [&](const Image& a, const Image& b, double* meanA, double* meanB) {
    int differing = 0, interior = 0;
    *meanA = *meanB = 0.0;
    for (int y = 1; y + 1 < a.height(); ++y)
      for (int x = 1; x + 1 < a.width(); ++x) {
        bool inside = true;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) inside = inside && a.at(x + dx, y + dy).a == 1.0f;
        if (!inside) continue;
        ++interior;
        *meanA += a.at(x, y).g;
        *meanB += b.at(x, y).g;
        differing += std::abs(a.at(x, y).g - b.at(x, y).g) > 1e-4f * (1.0f + a.at(x, y).g) ? 1 : 0;
      }
    *meanA /= std::max(interior, 1);
    *meanB /= std::max(interior, 1);
    EXPECT_GT(interior, 1000);
    return differing;
  };
  double a = 0.0, b = 0.0;
  EXPECT_GT(interiorDifference(plain, shaded, &a, &b), 200);  // MSAA alone shades once per pixel
  EXPECT_NEAR(b / a, 1.0, 0.05);
  EXPECT_GT(interiorDifference(shaded, super, &a, &b), 20);  // smooth map: 16 samples change less
  EXPECT_NEAR(b / a, 1.0, 0.05);
  const ProgramRun refused = run("iblkit-view", quoted(fixture.bake) + " --headless -o " +
                                                    quoted(dir / "x.exr") + " --supersample 3");
  EXPECT_EQ(refused.status, 2);  // a usage error (cli/program.h)
  EXPECT_FALSE(fs::exists(dir / "x.exr"));
}

TEST(IblkitView, WritesTheToneMappedPng) {
  const fs::path dir = test::scratchDir();
  const Fixture fixture = makeFixture(dir);
  const fs::path out = dir / "view.png";
  fs::remove(out);
  const ProgramRun r =
      run("iblkit-view", quoted(fixture.bake) + " --headless -o " + quoted(out) + kSize + " --exposure -1");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(readPng(out).width(), 128);
}

// The normal and depth layers of both programs for the same scene and size, compared where the
// 3 x 3 neighbourhood of a pixel is on one surface (iblkit-trace jitters its samples in the pixel,
// the rasteriser takes the centre; edges differ by construction).
TEST(IblkitView, NormalAndDepthLayersAlignWithIblkitTrace) {
  const fs::path dir = test::scratchDir();
  const Fixture fixture = makeFixture(dir);
  const ProgramRun view =
      run("iblkit-view", quoted(fixture.bake) + " --headless -o " + quoted(dir / "align_view.exr") + kSize +
                             " --normal " + quoted(dir / "align_view_n.exr") + " --depth " +
                             quoted(dir / "align_view_d.exr"));
  ASSERT_EQ(view.status, 0) << view.output;
  const ProgramRun trace =
      run("iblkit-trace", quoted(fixture.scene) + " --env " + quoted(fixture.environment) + " -o " +
                              quoted(dir / "align_trace.exr") + kSize + " --spp 4 --integrator ao --normal " +
                              quoted(dir / "align_trace_n.exr") + " --depth " +
                              quoted(dir / "align_trace_d.exr"));
  ASSERT_EQ(trace.status, 0) << trace.output;
  // Normals have negative components: read them as stored.
  auto read = [](const fs::path& file) { return readExr(file, nullptr, 0, PixelRepair::Keep); };
  const Image vn = read(dir / "align_view_n.exr"), tn = read(dir / "align_trace_n.exr");
  const Image vd = read(dir / "align_view_d.exr"), td = read(dir / "align_trace_d.exr");
  int compared = 0, skyAgrees = 0;
  float maxAngle = 0.0f, maxDepth = 0.0f;
  for (int y = 1; y < 95; ++y)
    for (int x = 1; x < 127; ++x) {
      bool flat = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const float a = td.at(x + dx, y + dy).r, b = td.at(x, y).r;
          if (a == 0.0f || b == 0.0f || std::abs(a - b) > 0.05f * b ||
              glm::dot(glm::vec3(tn.at(x + dx, y + dy)), glm::vec3(tn.at(x, y))) < 0.95f)
            flat = false;
        }
      if (td.at(x, y).r == 0.0f) skyAgrees += vd.at(x, y).r == 0.0f;
      if (!flat) continue;
      ++compared;
      const float cosine = glm::dot(glm::normalize(glm::vec3(vn.at(x, y))), glm::vec3(tn.at(x, y)));
      const float angle = glm::degrees(std::acos(std::min(cosine, 1.0f)));
      maxAngle = std::max(maxAngle, angle);
      maxDepth = std::max(maxDepth, std::abs(vd.at(x, y).r - td.at(x, y).r) / td.at(x, y).r);
    }
  EXPECT_GT(compared, 6000);
  EXPECT_LT(maxAngle, 1.5f);
  EXPECT_LT(maxDepth, 0.01f);
  EXPECT_GT(skyAgrees, 1000);
  std::cout << "alignment: " << compared << " pixels, max normal angle " << maxAngle
            << " degrees, max relative depth " << maxDepth << '\n';
}

// Given a scene instead of a bake folder, iblkit-view bakes it in memory, says so, and renders it.
TEST(IblkitView, BakesASceneFileInMemory) {
  const fs::path dir = test::scratchDir();
  const Fixture fixture = makeFixture(dir);
  const fs::path scene = dir / "scene.json";
  std::ofstream(scene)
      << R"({"models": [{"file": "scene.glb"}], "environment": {"file": "sky.exr"}, "ground": {"enabled": false}})";
  const fs::path fromScene = dir / "from_scene.exr";
  // The irradiance mode: the in-memory stages compute the irradiance cube too.
  const ProgramRun r = run("iblkit-view", quoted(scene) + " --headless -o " + quoted(fromScene) + kSize +
                                              " --mode irradiance --ao-rays 8");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find(scene.string() +
                          ": a scene, not a bake folder: baking it in memory (8 visibility rays per vertex)"),
            std::string::npos)
      << r.output;
  const Image image = readExr(fromScene);
  int covered = 0;
  for (const glm::vec4& p : image.pixels()) {
    ASSERT_TRUE(std::isfinite(p.r + p.g + p.b));
    if (p.a == 1.0f) covered += p.r + p.g + p.b > 1e-3f;
  }
  EXPECT_GT(covered, 1000);
}

// A glTF quad with a 2 x 2 checker base colour texture, baked in memory: --no-textures and
// --texture-slots without base-color show the factor alone; the base colour slot changes the frame.
TEST(IblkitView, TextureSlotsSwitchTheMaterialTextures) {
  const fs::path dir = test::scratchDir();
  test::GltfBuilder builder;
  builder.addQuadNode();
  const std::vector<std::uint8_t> checker = {255, 0, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255, 255, 0, 0, 255};
  builder.addImage(test::encodePng(2, 2, checker), "image/png");
  builder.document()["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9728}}};  // NEAREST
  builder.document()["textures"] = {{{"source", 0}, {"sampler", 0}}};
  builder.document()["materials"] = {
      {{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5, 1.0}}, {"baseColorTexture", {{"index", 0}}}}}}};
  builder.write(dir / "quad.glb", test::GltfBuilder::Storage::Glb);
  Image sky(16, 8);
  for (glm::vec4& p : sky.pixels()) p = glm::vec4(0.2f, 0.3f, 0.4f, 1.0f);
  writeExr(dir / "sky.exr", sky, {.pixelType = PixelType::Float});
  std::ofstream(dir / "scene.json") << R"({"models": [{"file": "quad.glb"}], "environment": {"file": "sky.exr"},
      "ground": {"enabled": false}, "camera": {"position": [0, 0, 3], "target": [0, 0, 0], "yfov": 40}})";
  auto frame = [&](const std::string& name, const std::string& flags) {
    const fs::path out = dir / (name + ".exr");
    const ProgramRun r = run("iblkit-view", quoted(dir / "scene.json") + " --headless -o " + quoted(out) +
                                                " --width 64 --height 64 --mode unlit --ao-rays 1 " + flags);
    EXPECT_EQ(r.status, 0) << r.output;
    return readExr(out);
  };
  const Image all = frame("all", ""), none = frame("none", "--no-textures"),
              others = frame("others", "--texture-slots normal,occlusion,emissive,metallic-roughness");
  // Pixel (20, 20) is on the top-left (red) texel, (44, 20) on the top-right (green) one.
  EXPECT_NEAR(all.at(20, 20).r, 0.5f, 1e-5f);
  EXPECT_NEAR(all.at(20, 20).g, 0.0f, 1e-5f);
  EXPECT_NEAR(all.at(44, 20).g, 0.5f, 1e-5f);
  for (const glm::ivec2 p : {glm::ivec2(20, 20), glm::ivec2(44, 20)}) {
    EXPECT_NEAR(none.at(p.x, p.y).r, 0.5f, 1e-6f);
    EXPECT_NEAR(none.at(p.x, p.y).g, 0.5f, 1e-6f);
    EXPECT_EQ(none.at(p.x, p.y), others.at(p.x, p.y));
  }
}

// IBLKIT_EGL_PLATFORM forces one EGL platform; both give a context on Mesa, and --bench names it.
TEST(IblkitView, EglPlatformCanBeForced) {
  const fs::path dir = test::scratchDir();
  const Fixture fixture = makeFixture(dir);
  for (const std::string platform : {"device", "surfaceless"}) {
    std::string output;
    const int status =
        test::runCommand("IBLKIT_EGL_PLATFORM=" + platform + " " + quoted(test::binDir() / "iblkit-view") +
                             " " + quoted(fixture.bake) + " --headless --bench 1 --mode unlit" + kSize,
                         &output);
    EXPECT_EQ(status, 0) << output;
    EXPECT_NE(output.find("iblkit-view: " + platform + ": "), std::string::npos) << output;
  }
  std::string output;
  EXPECT_EQ(test::runCommand("IBLKIT_EGL_PLATFORM=x11 " + quoted(test::binDir() / "iblkit-view") + " " +
                                 quoted(fixture.bake) + " --headless --bench 1",
                             &output),
            1);
  EXPECT_NE(output.find("iblkit-view: IBLKIT_EGL_PLATFORM: expected device or surfaceless, got 'x11'\n"),
            std::string::npos)
      << output;
}

// Status 1 for bad input files, 2 for the command line (cli/program.h).
void expectFailure(const std::string& arguments, const std::string& message, const fs::path& out,
                   int status = 1) {
  fs::remove(out);
  const ProgramRun r = run("iblkit-view", arguments);
  EXPECT_EQ(r.status, status) << r.output;
  EXPECT_NE(r.output.find(message + "\n"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST(IblkitView, BadInputIsOneLineAndNoOutput) {
  const fs::path dir = test::scratchDir();
  const Fixture fixture = makeFixture(dir);
  const fs::path out = dir / "bad.exr";
  const fs::path missing = dir / "missing_bake";
  expectFailure(quoted(missing) + " --headless -o " + quoted(out),
                "iblkit-view: " + missing.string() + ": no such bake folder", out);

  const fs::path incomplete = dir / "view_incomplete";
  fs::remove_all(incomplete);
  fs::copy(fixture.bake, incomplete, fs::copy_options::recursive);
  fs::remove(incomplete / "env" / "brdf_lut.exr");
  expectFailure(quoted(incomplete) + " --headless -o " + quoted(out),
                "iblkit-view: " + (incomplete / "env" / "brdf_lut.exr").string() +
                    ": missing (incomplete bake folder?)",
                out);

  const fs::path old = dir / "view_old";
  fs::remove_all(old);
  fs::copy(fixture.bake, old, fs::copy_options::recursive);
  std::stringstream text;
  text << std::ifstream(old / "bake.json").rdbuf();
  std::string record = text.str();
  const std::size_t version = record.find("iblkit-bake 1");
  ASSERT_NE(version, std::string::npos);
  record[version + 12] = '9';
  std::ofstream(old / "bake.json") << record;
  expectFailure(quoted(old) + " --headless -o " + quoted(out),
                "iblkit-view: " + (old / "bake.json").string() +
                    ": version 'iblkit-bake 9' is not supported (expected 'iblkit-bake 1')",
                out);

  expectFailure(quoted(fixture.bake) + " --headless -o " + quoted(out) + " --mode shiny",
                "iblkit-view: --mode: unknown shading mode 'shiny' (expected one of unlit, mirror, sh, "
                "irradiance, irradiance-ao-bent, sh-ao, sh-ao-bent, prt, full, lights, lights-shadowed, full-gltf-ao, "
                "full-both-ao, all)",
                out, 2);
  expectFailure(quoted(fixture.bake) + " --headless -o " + quoted(out) + " --mode sh,shiny",
                "iblkit-view: --mode: unknown shading mode 'shiny' (expected one of unlit, mirror, sh, "
                "irradiance, irradiance-ao-bent, sh-ao, sh-ao-bent, prt, full, lights, lights-shadowed, full-gltf-ao, "
                "full-both-ao, all)",
                out, 2);
  // Several modes: each output name needs {mode}; 'all' is alone; no mode twice; the window takes one.
  expectFailure(quoted(fixture.bake) + " --headless -o " + quoted(out) + " --mode sh,full",
                "iblkit-view: -o: with several modes the name needs {mode}, which each mode's name replaces", out, 2);
  const fs::path perMode = dir / "bad_{mode}.exr", sh = dir / "bad_sh.exr";
  expectFailure(quoted(fixture.bake) + " --headless -o " + quoted(perMode) + " --depth " + quoted(out) + " --mode sh,full",
                "iblkit-view: --depth: with several modes the name needs {mode}, which each mode's name replaces", sh, 2);
  expectFailure(quoted(fixture.bake) + " --headless -o " + quoted(perMode) + " --mode sh,sh",
                "iblkit-view: --mode: 'sh' is listed twice", sh, 2);
  expectFailure(quoted(fixture.bake) + " --headless --bench 1 --mode sh,all",
                "iblkit-view: --mode: 'all' is not one of a list of modes", out, 2);
  expectFailure(quoted(fixture.bake) + " --mode sh,full",
                "iblkit-view: --mode: one mode in the window (several are for --headless)", out, 2);
  // All frames or none: sh's is written first, then full's cannot be (its folder is missing), and
  // sh's goes again.
  fs::remove_all(dir / "sh");
  fs::create_directories(dir / "sh");
  const fs::path inFolder = dir / "{mode}" / "frame.exr";
  expectFailure(quoted(fixture.bake) + " --headless -o " + quoted(inFolder) + " --mode sh,full" + kSize,
                "iblkit-view: " + (dir / "full" / "frame.exr").string() +
                    ": cannot create a temporary file beside it: No such file or directory",
                dir / "sh" / "frame.exr");
  EXPECT_TRUE(fs::is_empty(dir / "sh"));
  expectFailure(quoted(fixture.bake) + " --headless -o " + quoted(out) + " --texture-slots normal,albedo",
                "iblkit-view: --texture-slots: unknown texture slot 'albedo' (expected one of base-color, "
                "metallic-roughness, normal, occlusion, emissive, all, none)",
                out, 2);
  expectFailure(quoted(fixture.bake) + " --headless -o " + quoted(out) + " --texture-slots normal --no-textures",
                "iblkit-view: --no-textures: give --no-textures or --texture-slots, not both", out, 2);
  expectFailure(quoted(fixture.bake) + " -o " + quoted(out),
                "iblkit-view: -o: only with --headless (the window saves screenshots: --screenshot)", out, 2);
  expectFailure(quoted(fixture.bake) + " --headless -o " + quoted(out) + " --lights 9",
                "iblkit-view: --lights: Value 9 not in range 0 to 4", out, 2);
  expectFailure(quoted(fixture.bake) + " --headless -o " + quoted(out) + " --shadow-mask-resolution quarter",
                "iblkit-view: --shadow-mask-resolution: quarter not in {half,full}", out, 2);
  expectFailure(quoted(fixture.bake) + " --headless -o " + quoted(out) + " --no-such-option",
                "iblkit-view: The following argument was not expected: --no-such-option", out, 2);
}

// Every program's command-line errors: exactly one stderr line, status 2 (cli/program.h).
TEST(IblkitView, ABadOptionIsOneLineAndStatusTwo) {
  test::expectUsageError(quoted(test::binDir() / "iblkit-view") + " bake --headless -o x.exr --frobnicate",
                         "iblkit-view: The following argument was not expected: --frobnicate");
}

// --env-rotation is absolute (docs/conventions.md): a bake at 30 degrees shown at 90 is the frame
// of a bake at 90 shown as baked, up to the prefiltered cube's texels turned by 60 degrees.
TEST(IblkitView, EnvRotationIsAbsoluteNotAddedToTheBakes) {
  const fs::path dir = test::scratchDir();
  const Fixture fixture = makeFixture(dir);
  const auto bakeAt = [&](const std::string& degrees) {
    const fs::path folder = dir / ("bake" + degrees);
    const ProgramRun r = run("iblkit-bake", quoted(fixture.scene) + " --env " + quoted(fixture.environment) +
                                                " --env-rotation " + degrees + " -o " + quoted(folder) +
                                                " --ao-rays 16 --specular-samples 32 --lut-size 16");
    EXPECT_EQ(r.status, 0) << r.output;
    return folder;
  };
  const auto frame = [&](const fs::path& bake, const std::string& options) {
    const fs::path out = dir / "frame.exr";
    fs::remove(out);
    const ProgramRun r = run("iblkit-view", quoted(bake) + " --headless -o " + quoted(out) + kSize + options);
    EXPECT_EQ(r.status, 0) << r.output;
    return readExr(out);
  };
  const fs::path at30 = bakeAt("30"), at90 = bakeAt("90");
  const Image turned = frame(at30, " --env-rotation 90"), baked = frame(at90, "");
  const Image unturned = frame(at30, "");
  const auto meanDifference = [](const Image& a, const Image& b) {
    double sum = 0.0, total = 0.0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i) {
      const glm::vec4 d = glm::abs(a.pixels()[i] - b.pixels()[i]);
      sum += d.r + d.g + d.b;
      total += b.pixels()[i].r + b.pixels()[i].g + b.pixels()[i].b;
    }
    return sum / total;
  };
  EXPECT_LT(meanDifference(turned, baked), 0.01);
  // The rotation shows: without the flag the bake at 30 is another frame.
  EXPECT_GT(meanDifference(unturned, baked), 10.0 * meanDifference(turned, baked));
}

}  // namespace
}  // namespace iblkit
