// End-to-end: iblkit-report on small images (160x90: below that, FLIP at 67 pixels per degree sees
// the mirror sphere's minified reflection alias) runs the real programs (iblkit-bake, iblkit-view
// through EGL, iblkit-trace), scores every mode, checks the issue's claims on the lone spheres,
// and re-runs from its cache. Bad input gets one line and no report.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/gltf_builder.h"
#include "support/test_paths.h"
#include "support/texture_files.h"
#include "support/usage_error_check.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Built with += : GCC 12 gives a false -Wrestrict on "'" + std::string (its bug 105329).
std::string quoted(const fs::path& p) {
  std::string text = "'";
  text += p.string();
  text += "'";
  return text;
}

int report(const std::string& arguments, std::string* output) {
  return test::runCommand((test::binDir() / "iblkit-report").string() + " --bin " + quoted(test::binDir()) + " " +
                              arguments + " 2>&1",
                          output);
}

// Small images and references held to the rule before the absolute bound, with one light sample
// (--max-reference-relmse 1 --reference-light-samples 1), so that these tests of the modes take the
// time they took before (the absolute bound and splitting have their test below).
std::string smallReport(const fs::path& out, const std::string& scenes, const std::string& envs) {
  return scenes + " --env-dir " + quoted(test::assetsDir() / "hdri") + " --envs " + envs +
         " --width 160 --height 90 --pass-spp 16 --min-passes 2 --max-passes 8 --bench 3"
         " --max-reference-relmse 1 --reference-light-samples 1 -o " +
         quoted(out);
}

json readJson(const fs::path& file) {
  std::ifstream stream(file);
  return json::parse(stream);
}

const json* findClaim(const json& document, const std::string& prefix) {
  for (const json& claim : document["claims"])
    if (claim["statement"].get<std::string>().rfind(prefix, 0) == 0) return &claim;
  return nullptr;
}

TEST(IblkitReport, LoneSpheresScoreEveryModeHoldTheirClaimsAndRerunFromTheCache) {
  const fs::path out = test::scratchDir() / "report";
  const fs::path scenes = test::assetsDir() / "scenes";
  const std::string arguments =
      smallReport(out, quoted(scenes / "mirror_sphere.json") + " " + quoted(scenes / "diffuse_sphere.json"),
                  "sky,studio");
  std::string output;
  // --strict exits 3: under the studio map SH9 itself is far more than 3% off (see below).
  ASSERT_EQ(report(arguments + " --strict", &output), 3) << output;
  ASSERT_TRUE(fs::is_regular_file(out / "report.html"));
  const json document = readJson(out / "report.json");
  ASSERT_EQ(document["cases"].size(), 4u);
  for (const json& entry : document["cases"]) {
    EXPECT_GT(entry["reference"]["spp"].get<int>(), 0);
    EXPECT_GT(entry["scoredPixels"].get<int>(), 100) << entry["scene"];
    // The modes that apply (report/case_modes.h; the glTF occlusion modes need an occlusion texture):
    // the metallic mirror sphere has no diffuse lobe, so mirror, full, lights, lights-shadowed; the
    // Lambert diffuse sphere no specular one, so sh, irradiance, sh-ao, sh-ao-bent, prt and those three.
    ASSERT_EQ(entry["modes"].size(), entry["scene"] == "mirror_sphere" ? 4u : 8u) << entry["scene"];
    EXPECT_EQ(entry["modes"].size() + entry["notApplicable"].size(), document["settings"]["modes"].size());
    // The map's kind (report/map_kind.h): sky has a sun, studio softboxes.
    EXPECT_EQ(entry["mapKind"], entry["environment"] == "sky" ? "sunny" : "studio") << entry["environment"];
    for (const json& mode : entry["modes"]) {
      const std::string what = entry["scene"].get<std::string>() + "/" + entry["environment"].get<std::string>() +
                               "/" + mode["mode"].get<std::string>();
      ASSERT_FALSE(mode.contains("failure")) << what << ": " << mode["failure"];
      EXPECT_TRUE(mode["frameMilliseconds"].is_number()) << what;
      if (mode["frameMilliseconds"].is_number()) {
        EXPECT_GT(mode["frameMilliseconds"].get<double>(), 0.0) << what;
      }
      const double flip = mode["meanFlip"].get<double>();
      EXPECT_TRUE(std::isfinite(flip) && flip >= 0.0 && flip <= 1.0) << what;
      EXPECT_TRUE(fs::is_regular_file(out / mode["image"].get<std::string>())) << what;
      EXPECT_TRUE(fs::is_regular_file(out / mode["flipHeatMap"].get<std::string>())) << what;
    }
  }
  // The claims on the lone spheres. The mirror sphere looks the same rasterized and path traced.
  const json* mirror = findClaim(document, "mirror_sphere: mirror mode mean FLIP");
  const json* diffuse = findClaim(document, "diffuse_sphere: sh mode mean relative error");
  const json* own = findClaim(document, "diffuse_sphere: sh mode adds at most 1%");
  ASSERT_NE(mirror, nullptr);
  ASSERT_NE(diffuse, nullptr);
  ASSERT_NE(own, nullptr);
  EXPECT_TRUE((*mirror)["holds"].get<bool>()) << mirror->dump();
  // The diffuse sphere's sh error is SH9's own truncation error on every map (the engine adds
  // nothing)...
  EXPECT_TRUE((*own)["holds"].get<bool>()) << own->dump();
  // ...which under a studio map with small bright lights is far above 3%: the claim fails, and says why.
  EXPECT_FALSE((*diffuse)["holds"].get<bool>()) << diffuse->dump();
  EXPECT_NE((*diffuse)["detail"].get<std::string>().find("SH9's own truncation error"), std::string::npos);
  // The irradiance cube has no truncation: its diffuse sphere is closer to the reference than SH9's.
  const json* cube = findClaim(document, "diffuse_sphere: irradiance mode (the cube) mean relative error < sh");
  ASSERT_NE(cube, nullptr);
  EXPECT_TRUE((*cube)["holds"].get<bool>()) << cube->dump();
  for (const json& entry : document["cases"])
    if (entry["scene"] == "diffuse_sphere") {
      EXPECT_GT(entry["sh9TruncationError"].get<double>(), 0.0);
    }

  // The claims per kind of map on the light mode against full, with the numbers they measured.
  for (const char* prefix : {"diffuse_sphere on sunny maps (sky): lights-shadowed mean FLIP <= 0.05",
                             "diffuse_sphere on studio maps (studio): lights-shadowed mean FLIP <= 0.05",
                             "every scene on sunny maps (sky): lights-shadowed mean FLIP at most full's + 0.005",
                             "every scene on studio maps (studio): lights-shadowed"}) {
    const json* claim = findClaim(document, prefix);
    ASSERT_NE(claim, nullptr) << prefix;
    EXPECT_TRUE((*claim)["measured"].is_number()) << claim->dump();
    EXPECT_NE((*claim)["detail"].get<std::string>().find("diffuse_sphere under "), std::string::npos) << claim->dump();
  }

  // Everything again: every stage comes from the cache, the numbers are the same.
  ASSERT_EQ(report(arguments, &output), 0) << output;
  const json again = readJson(out / "report.json");
  EXPECT_EQ(again["stages"]["run"].get<int>(), 0);
  EXPECT_EQ(again["cases"][0]["modes"][0]["meanFlip"], document["cases"][0]["modes"][0]["meanFlip"]);
}

// The bunny's approximation ladder on small images under an overcast and a soft map: the bent
// normal beats plain AO, and full (multi-bounce AO) beats sh; sh-ao does not beat sh on this white
// scene (docs/report.md says why), and the report says so.
TEST(IblkitReport, BunnyLadderOnSmallImages) {
  const fs::path out = test::scratchDir() / "report";
  std::string output;
  ASSERT_EQ(report(smallReport(out, quoted(test::assetsDir() / "scenes" / "bunny.json"), "city,forest") +
                       " --modes sh,sh-ao,sh-ao-bent,prt,full",
                   &output),
            0)
      << output;
  const json document = readJson(out / "report.json");
  const json* bent = findClaim(document, "bunny: mean FLIP of sh-ao > sh-ao-bent");
  const json* first = findClaim(document, "bunny: mean FLIP of sh > sh-ao");
  ASSERT_NE(bent, nullptr);
  ASSERT_NE(first, nullptr);
  EXPECT_TRUE((*bent)["holds"].get<bool>()) << bent->dump();
  EXPECT_FALSE((*first)["holds"].get<bool>()) << first->dump();
  std::ifstream html(out / "report.html");
  const std::string page((std::istreambuf_iterator<char>(html)), std::istreambuf_iterator<char>());
  EXPECT_NE(page.find("Why AO does not help here"), std::string::npos);
  for (const json& entry : document["cases"]) {
    double sh = 0.0, full = 0.0;
    for (const json& mode : entry["modes"]) {
      if (mode["mode"] == "sh") sh = mode["meanFlip"].get<double>();
      if (mode["mode"] == "full") full = mode["meanFlip"].get<double>();
    }
    EXPECT_LT(full, sh) << entry["environment"];
  }
}

// The glTF occlusion modes are scored where a material has an occlusion texture, beside `full`,
// and not on a scene without one (where they would repeat `full`). The textured scene: a quad
// facing the camera whose occlusion texture darkens its left half, in a scene file with a camera.
TEST(IblkitReport, GltfOcclusionModesOnlyOnScenesWithAnOcclusionTexture) {
  const fs::path dir = test::scratchDir();
  std::vector<std::uint8_t> rgba(8 * 8 * 4, 255);
  for (int i = 0; i < 8 * 8; ++i)
    if (i % 8 < 4) rgba[4 * i] = 40;  // R, the occlusion channel
  test::writeFileBytes(dir / "ao.png", test::encodePng(8, 8, rgba));
  test::GltfBuilder builder;
  const int card = builder.addQuadNode();  // [-1, 1]^2, lifted to stand on the ground at y = 0
  builder.document()["nodes"][card]["translation"] = {0.0, 1.0, 0.0};
  builder.document()["images"] = {{{"uri", "ao.png"}}};
  builder.document()["textures"] = {{{"source", 0}}};
  builder.document()["materials"] = {
      {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}, {"occlusionTexture", {{"index", 0}}}}};
  builder.write(dir / "card.glb", test::GltfBuilder::Storage::Glb);
  std::ofstream(dir / "card.json") << R"({"models": [{"file": "card.glb"}], "ground": {"enabled": true},
      "camera": {"position": [0, 1, 4], "target": [0, 0.8, 0], "yfov": 45}})";

  const fs::path out = dir / "report";
  std::string output;
  ASSERT_EQ(report(smallReport(out, quoted(dir / "card.json") + " " +
                                        quoted(test::assetsDir() / "scenes" / "mirror_sphere.json"),
                               "city") +
                       " --modes full,full-gltf-ao,full-both-ao",
                   &output),
            0)
      << output;
  const json document = readJson(out / "report.json");
  ASSERT_EQ(document["cases"].size(), 2u);
  for (const json& entry : document["cases"]) {
    std::vector<std::string> modes;
    for (const json& mode : entry["modes"]) {
      modes.push_back(mode["mode"]);
      EXPECT_FALSE(mode.contains("failure")) << entry["scene"] << " " << mode["mode"] << ": " << mode["failure"];
    }
    // A textured scene's frames are rendered without --sample-shading (ReportSettings::
    // engineSampleShading), an untextured scene's with it.
    int views = 0, sampleShaded = 0;
    for (const json& command : entry["commands"]) {
      const std::string text = command.get<std::string>();
      if (text.find("iblkit-view") == std::string::npos) continue;
      ++views;
      if (text.find("--sample-shading") != std::string::npos) ++sampleShaded;
    }
    EXPECT_GT(views, 0) << entry["scene"];
    EXPECT_EQ(sampleShaded, entry["scene"] == "card" ? 0 : views) << entry["scene"];
    if (entry["scene"] == "card") {
      EXPECT_EQ(modes, (std::vector<std::string>{"full", "full-gltf-ao", "full-both-ao"}));
      // The texture darkens half the card: glTF occlusion changes the frame, so its score differs.
      EXPECT_NE(entry["modes"][0]["meanFlip"], entry["modes"][2]["meanFlip"]);
    } else {
      EXPECT_EQ(modes, std::vector<std::string>{"full"}) << entry["scene"];
    }
  }
}

// The references' defaults: 2 light samples at the first hit (in every trace command, so in the
// stage keys) and converged at the absolute bound, relMSE <= 1e-3 (--negligible-relmse 1e-3 makes
// that bound the target whatever the sh frame's error), which the tiny diffuse sphere under city
// reaches well before the 64-pass maximum (the count aimed from the measured noise); report.json
// and the case table give the halves' FLIP.
TEST(IblkitReport, ReferencesConvergeAtTheAbsoluteBoundWithSplitLightSamples) {
  const fs::path out = test::scratchDir() / "report";
  std::string output;
  ASSERT_EQ(report(quoted(test::assetsDir() / "scenes" / "diffuse_sphere.json") + " --env-dir " +
                       quoted(test::assetsDir() / "hdri") +
                       " --envs city --width 64 --height 36 --pass-spp 8 --min-passes 2 --bench 0 --modes sh"
                       " --negligible-relmse 1e-3 -o " +
                       quoted(out),
                   &output),
            0)
      << output;
  const json document = readJson(out / "report.json");
  EXPECT_EQ(document["settings"]["maxReferenceRelMse"].get<double>(), 1e-3);
  EXPECT_EQ(document["settings"]["referenceLightSamples"].get<int>(), 2);
  ASSERT_EQ(document["cases"].size(), 1u);
  const json& reference = document["cases"][0]["reference"];
  EXPECT_TRUE(reference["converged"].get<bool>()) << reference.dump();
  EXPECT_LE(reference["relMseEstimate"].get<double>(), 1e-3) << reference.dump();
  EXPECT_LT(reference["spp"].get<int>(), 64 * 8) << reference.dump();
  const double flip = reference["halvesMeanFlip"].get<double>();
  EXPECT_TRUE(flip > 0.0 && flip < 0.1) << reference.dump();
  int traces = 0;
  for (const json& command : document["cases"][0]["commands"]) {
    const std::string text = command.get<std::string>();
    if (text.find("iblkit-trace") == std::string::npos) continue;
    ++traces;
    EXPECT_NE(text.find("--camera-light-samples 2"), std::string::npos) << text;
  }
  EXPECT_EQ(traces, 1);
  std::ifstream html(out / "report.html");
  const std::string page((std::istreambuf_iterator<char>(html)), std::istreambuf_iterator<char>());
  EXPECT_NE(page.find("halves' FLIP</th>"), std::string::npos);
}

// The samples per pixel of each reference stage in a report's cache (trace-*/stage.json).
std::vector<int> traceStageSpp(const fs::path& cache) {
  std::vector<int> spp;
  for (const fs::directory_entry& entry : fs::directory_iterator(cache)) {
    if (entry.path().filename().string().rfind("trace-", 0) != 0) continue;
    const std::string command = readJson(entry.path() / "stage.json")["command"].get<std::string>();
    const std::size_t at = command.find("--spp ");
    EXPECT_NE(at, std::string::npos) << command;
    if (at != std::string::npos) spp.push_back(std::stoi(command.substr(at + 6)));
  }
  return spp;
}

// A wave's passes run as pairs of stages of up to --max-stage-passes passes: every sample the
// reference counts was traced once, by fewer runs than passes; with 1, a run per pass as before.
TEST(IblkitReport, ReferencePassesRunInStagesOfSeveralPasses) {
  for (const int stagePasses : {1, 16}) {
    const fs::path out = test::scratchDir() / ("report-stages-" + std::to_string(stagePasses));
    std::string output;
    ASSERT_EQ(report(quoted(test::assetsDir() / "scenes" / "diffuse_sphere.json") + " --env-dir " +
                         quoted(test::assetsDir() / "hdri") +
                         " --envs esplanade --width 64 --height 36 --pass-spp 4 --min-passes 2 --bench 0"
                         " --modes sh --max-stage-passes " + std::to_string(stagePasses) + " -o " + quoted(out),
                     &output),
              0)
        << output;
    const json reference = readJson(out / "report.json")["cases"][0]["reference"];
    const int spp = reference["spp"].get<int>();
    const std::vector<int> stages = traceStageSpp(out / "cache");
    int sum = 0;
    for (int s : stages) {
      EXPECT_EQ(s % 4, 0) << "whole passes";
      EXPECT_LE(s, 4 * stagePasses);
      sum += s;
    }
    EXPECT_EQ(sum, spp) << reference.dump();
    EXPECT_EQ(stages.size() % 2, 0u) << "the halves' stages come in pairs";
    // The first wave alone is 2 passes; the esplanade sun needs more, in fewer stages than passes.
    ASSERT_GT(spp, 2 * 4) << reference.dump();
    if (stagePasses == 1)
      EXPECT_EQ(int(stages.size()), spp / 4);
    else
      EXPECT_LT(int(stages.size()), spp / 4);
  }
}

// The modes that share iblkit-view's options render in one run (report/stage_commands.h, viewGroups);
// when that run fails, each mode runs alone, so a mode iblkit-view refuses fails by itself, with
// iblkit-view's own error, and the others are scored with their frame times.
TEST(IblkitReport, AModeTheEngineRefusesFailsAlone) {
  const fs::path out = test::scratchDir() / "report";
  const fs::path scene = test::assetsDir() / "scenes" / "diffuse_sphere.json";
  std::string output;
  report(quoted(scene) + " --env-dir " + quoted(test::assetsDir() / "hdri") +
             " --envs sky --width 64 --height 36 --pass-spp 8 --min-passes 2 --max-passes 2 --bench 1"
             " --max-reference-relmse 1 --reference-light-samples 1 --modes sh,shiny,full -o " + quoted(out),
         &output);
  ASSERT_TRUE(fs::is_regular_file(out / "report.json")) << output;
  const json document = readJson(out / "report.json");
  ASSERT_EQ(document["cases"].size(), 1u);
  const json& modes = document["cases"][0]["modes"];
  ASSERT_EQ(modes.size(), 3u);
  for (const json& mode : modes) {
    if (mode["mode"] == "shiny") {
      ASSERT_TRUE(mode.contains("failure")) << mode.dump();
      EXPECT_NE(mode["failure"].get<std::string>().find("unknown shading mode 'shiny'"), std::string::npos)
          << mode.dump();
    } else {
      EXPECT_FALSE(mode.contains("failure")) << mode.dump();
      EXPECT_TRUE(mode["frameMilliseconds"].is_number()) << mode.dump();
      EXPECT_TRUE(mode["meanFlip"].is_number()) << mode.dump();
    }
  }
}

TEST(IblkitReport, AMissingEnvironmentIsOneLineAndNoReport) {
  const fs::path out = test::scratchDir() / "report";
  const fs::path scene = test::assetsDir() / "scenes" / "mirror_sphere.json";
  std::string output;
  EXPECT_EQ(report(smallReport(out, quoted(scene), "no_such_map"), &output), 1);
  EXPECT_NE(output.find("iblkit-report: "), std::string::npos) << output;
  EXPECT_NE(output.find("no_such_map.exr: environment map does not exist"), std::string::npos) << output;
  EXPECT_EQ(output.find('\n'), output.size() - 1) << output;
  EXPECT_FALSE(fs::exists(out / "report.json"));
}

TEST(IblkitReport, AMissingSceneIsOneLineAndNoReport) {
  const fs::path out = test::scratchDir() / "report";
  std::string output;
  EXPECT_EQ(report(smallReport(out, quoted(test::scratchDir() / "absent.json"), "sky"), &output), 1);
  EXPECT_NE(output.find("absent.json: scene file does not exist"), std::string::npos) << output;
  EXPECT_EQ(output.find('\n'), output.size() - 1) << output;
  EXPECT_FALSE(fs::exists(out / "report.json"));
}

// Every program's command-line errors: one line naming the program, status 2 (cli/program.h).
TEST(IblkitReport, ABadOptionIsOneLineAndStatusTwo) {
  const fs::path out = test::scratchDir() / "report";
  const std::string program = (test::binDir() / "iblkit-report").string() + " -o " + quoted(out);
  test::expectUsageError(program + " --no-such-option",
                         "iblkit-report: The following argument was not expected: --no-such-option");
  test::expectUsageError(
      program + " --integrator ao",
      "iblkit-report: --integrator: unknown integrator 'ao' (expected one of path, direct)");
  test::expectUsageError(program + " --min-passes 3 --max-passes 8",
                         "iblkit-report: --min-passes and --max-passes must be even, min <= max");
  test::expectUsageError(program + " --modes sh,full,sh", "iblkit-report: --modes: 'sh' is listed twice");
  EXPECT_FALSE(fs::exists(out / "report.json"));
}

}  // namespace
}  // namespace iblkit
