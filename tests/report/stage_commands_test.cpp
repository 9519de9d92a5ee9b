#include "report/stage_commands.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/image_io.h"
#include "report/pending_stages.h"
#include "support/gltf_builder.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

// Stand-ins for the programs and a scene under a map: the commands are built, not run.
struct Fixture {
  ReportSettings settings;
  CaseInputs inputs;
  Fixture() {
    const fs::path dir = test::scratchDir();
    settings.binDir = dir / "bin";
    fs::create_directories(settings.binDir);
    for (const char* program : {"iblkit-bake", "iblkit-view", "iblkit-trace"})
      std::ofstream(settings.binDir / program) << program;
    std::ofstream(dir / "map.exr") << "pixels";
    std::ofstream(dir / "scene.json")
        << R"({"models": [{"shape": "sphere"}], "environment": {"file": "map.exr"}})";
    inputs = caseInputs(dir / "scene.json", dir / "map.exr");
  }
};

TEST(StageCommands, OutputsAreUnderThePlaceholder) {
  Fixture fixture;
  const StageCommand bake = bakeCommand(fixture.settings, fixture.inputs);
  const std::vector<std::string> bakeArgv = stageArgv(bake, "/c", "/c/b");
  EXPECT_EQ(bakeArgv.back(), "/c/b/bake");
  // The report's interreflection bounces (ReportSettings::bakeBounces) reach the baker.
  const auto bounces = std::find(bakeArgv.begin(), bakeArgv.end(), "--bounces");
  ASSERT_NE(bounces, bakeArgv.end());
  EXPECT_EQ(*(bounces + 1), std::to_string(fixture.settings.bakeBounces));
  const StageCommand trace = traceCommand(fixture.settings, fixture.inputs, 0);
  const std::vector<std::string> argv = stageArgv(trace, "/c", "/c/t");
  for (const char* file : {"/c/t/beauty.exr", "/c/t/depth.exr", "/c/t/normal.exr"})
    EXPECT_NE(std::find(argv.begin(), argv.end(), file), argv.end()) << file;
  EXPECT_EQ(fixture.inputs.files.size(), 2u);  // the scene and the map: a shape names no file
}

// A scene's visibility is one stage for every map: its command and key name the scene's files and
// the visibility options, not the map; the bakes read it from the cache.
TEST(StageCommands, TheVisibilityStageIsTheScenesUnderEveryMap) {
  Fixture fixture;
  const fs::path dir = fixture.inputs.sceneFile.parent_path();
  std::ofstream(dir / "other.exr") << "other pixels";
  const CaseInputs other = caseInputs(dir / "scene.json", dir / "other.exr");
  const StageCommand visibility = visibilityCommand(fixture.settings, fixture.inputs);
  EXPECT_EQ(stageKey(visibility), stageKey(visibilityCommand(fixture.settings, other)));
  EXPECT_EQ(std::find(visibility.inputFiles.begin(), visibility.inputFiles.end(), fixture.inputs.environmentFile),
            visibility.inputFiles.end());
  const std::vector<std::string> argv = stageArgv(visibility, "/c", "/c/v");
  EXPECT_NE(std::find(argv.begin(), argv.end(), "--visibility-only"), argv.end());
  EXPECT_EQ(std::find(argv.begin(), argv.end(), "--env"), argv.end());
  EXPECT_EQ(argv.back(), "/c/v/bake");
  // The visibility options change it, as they change the bakes that read it.
  ReportSettings bounced = fixture.settings;
  bounced.bakeBounces = 0;
  EXPECT_NE(stageKey(visibilityCommand(bounced, fixture.inputs)), stageKey(visibility));
  ReportSettings pointSampled = fixture.settings;
  pointSampled.bakeAreaSampling = !pointSampled.bakeAreaSampling;
  EXPECT_NE(stageKey(visibilityCommand(pointSampled, fixture.inputs)), stageKey(visibility));
  // A bake names the stage's folder under the cache placeholder, so the stage's key is in its key.
  const StageCommand bake = bakeCommand(fixture.settings, fixture.inputs, "/cache/visibility-scene-0123");
  const std::vector<std::string> bakeArgv = stageArgv(bake, "/c", "/c/b");
  const auto from = std::find(bakeArgv.begin(), bakeArgv.end(), "--visibility-from");
  ASSERT_NE(from, bakeArgv.end());
  EXPECT_EQ(*(from + 1), "/c/visibility-scene-0123/bake");
  EXPECT_EQ(stageFoldersRead(bake), std::vector<std::string>{"visibility-scene-0123"});
  EXPECT_NE(stageKey(bake), stageKey(bakeCommand(fixture.settings, fixture.inputs, "/cache/visibility-scene-4567")));
}

// A map's environment stages are one stage for every scene under it at the same rotation and
// intensity: its command and key name the map, not the scene; the bakes read it from the cache.
TEST(StageCommands, TheEnvironmentStageIsTheMapsUnderEveryScene) {
  Fixture fixture;
  const fs::path dir = fixture.inputs.sceneFile.parent_path();
  std::ofstream(dir / "other.json") << R"({"models": [{"shape": "sphere", "translation": [1, 0, 0]}], "environment": {"file": "map.exr"}})";
  const CaseInputs other = caseInputs(dir / "other.json", dir / "map.exr");
  const StageCommand environment = environmentCommand(fixture.settings, fixture.inputs);
  EXPECT_EQ(stageKey(environment), stageKey(environmentCommand(fixture.settings, other)));
  EXPECT_EQ(environment.inputFiles, std::vector<fs::path>{fixture.inputs.environmentFile});
  const std::vector<std::string> argv = stageArgv(environment, "/c", "/c/e");
  EXPECT_NE(std::find(argv.begin(), argv.end(), "--environment-only"), argv.end());
  EXPECT_EQ(std::find(argv.begin(), argv.end(), fixture.inputs.sceneFile.string()), argv.end());
  EXPECT_EQ(argv.back(), "/c/e/bake");
  // The scene's rotation and intensity go into it as arguments that read back as the same floats,
  // so a scene that turns the map has a stage of its own.
  std::ofstream(dir / "turned.json")
      << R"({"models": [{"shape": "sphere"}], "environment": {"file": "map.exr", "rotation": 33.3, "intensity": 0.1}})";
  const CaseInputs turned = caseInputs(dir / "turned.json", dir / "map.exr");
  const StageCommand turnedEnvironment = environmentCommand(fixture.settings, turned);
  EXPECT_NE(stageKey(turnedEnvironment), stageKey(environment));
  const std::vector<std::string> turnedArgv = stageArgv(turnedEnvironment, "/c", "/c/e");
  const auto rotation = std::find(turnedArgv.begin(), turnedArgv.end(), "--env-rotation");
  ASSERT_NE(rotation, turnedArgv.end());
  EXPECT_EQ(std::stof(*(rotation + 1)), 33.3f);
  const auto intensity = std::find(turnedArgv.begin(), turnedArgv.end(), "--env-intensity");
  ASSERT_NE(intensity, turnedArgv.end());
  EXPECT_EQ(std::stof(*(intensity + 1)), 0.1f);
  // The map's bytes change it.
  const std::string key = stageKey(environment);
  std::ofstream(dir / "map.exr") << "other pixels";
  EXPECT_NE(stageKey(environmentCommand(fixture.settings, fixture.inputs)), key);
  // A bake names the stage's folder under the cache placeholder, so the stage's key is in its key.
  const StageCommand bake = bakeCommand(fixture.settings, fixture.inputs, "/cache/visibility-scene-0123",
                                        "/cache/environment-map-89ab");
  const std::vector<std::string> bakeArgv = stageArgv(bake, "/c", "/c/b");
  const auto from = std::find(bakeArgv.begin(), bakeArgv.end(), "--environment-from");
  ASSERT_NE(from, bakeArgv.end());
  EXPECT_EQ(*(from + 1), "/c/environment-map-89ab/bake");
  EXPECT_EQ(stageFoldersRead(bake), (std::vector<std::string>{"visibility-scene-0123", "environment-map-89ab"}));
  EXPECT_NE(stageKey(bake), stageKey(bakeCommand(fixture.settings, fixture.inputs, "/cache/visibility-scene-0123",
                                                 "/cache/environment-map-cdef")));
}

// The modes that one iblkit-view renders together: all but lights-shadowed, which supersamples
// without sample shading, when the report sample-shades; every one when it does not.
TEST(StageCommands, ModesShareAViewWhereTheirOptionsAgree) {
  Fixture fixture;
  const std::vector<std::string> modes = {"mirror", "sh", "lights-shadowed", "full", "lights"};
  const std::vector<std::vector<std::string>> groups = viewGroups(fixture.settings, modes);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0], (std::vector<std::string>{"mirror", "sh", "full", "lights"}));
  EXPECT_EQ(groups[1], (std::vector<std::string>{"lights-shadowed"}));
  ReportSettings plain = fixture.settings;
  plain.engineSampleShading = false;
  EXPECT_EQ(viewGroups(plain, modes), (std::vector<std::vector<std::string>>{modes}));
  // One run of a group: its modes as one --mode list, each frame to its own file in the stage.
  const std::vector<std::string> argv = stageArgv(viewCommand(fixture.settings, "/c/bake-1", groups[0]), "/c", "/c/v");
  const auto mode = std::find(argv.begin(), argv.end(), "--mode");
  ASSERT_NE(mode, argv.end());
  EXPECT_EQ(*(mode + 1), "mirror,sh,full,lights");
  EXPECT_NE(std::find(argv.begin(), argv.end(), "/c/v/frame-{mode}.exr"), argv.end());
  EXPECT_EQ(viewFrameFile("sh"), "frame-sh.exr");
  // Modes that need different options cannot share a command.
  EXPECT_THROW(viewCommand(fixture.settings, "/c/bake-1", {"sh", "lights-shadowed"}), std::logic_error);
  // A group's key is not any one mode's.
  EXPECT_NE(stageKey(viewCommand(fixture.settings, "/c/bake-1", {"sh", "full"})),
            stageKey(viewCommand(fixture.settings, "/c/bake-1", {"sh"})));
}

TEST(StageCommands, EachSettingChangesItsStagesKey) {
  Fixture fixture;
  const fs::path bake = "/cache/bake-0123";
  const auto viewKey = [&](const ReportSettings& settings) {
    return stageKey(viewCommand(settings, bake, {"sh"}));
  };
  const auto traceKey = [&](const ReportSettings& settings) {
    return stageKey(traceCommand(settings, fixture.inputs, 3));
  };
  const std::vector<std::function<void(ReportSettings&)>> viewChanges = {
      [](ReportSettings& s) { s.width = 64; }, [](ReportSettings& s) { s.height = 36; },
      [](ReportSettings& s) { s.engineSamples = 1; }, [](ReportSettings& s) { s.engineSupersample = 4; },
      [](ReportSettings& s) { s.benchFrames = 0; }, [](ReportSettings& s) { s.engineAnisotropy = 16; },
      [](ReportSettings& s) { s.engineSampleShading = false; }};
  for (std::size_t i = 0; i < viewChanges.size(); ++i) {
    ReportSettings changed = fixture.settings;
    viewChanges[i](changed);
    EXPECT_NE(viewKey(changed), viewKey(fixture.settings)) << "view change " << i;
  }
  EXPECT_NE(stageKey(viewCommand(fixture.settings, bake, {"prt"})), viewKey(fixture.settings));
  EXPECT_NE(stageKey(viewCommand(fixture.settings, "/cache/bake-4567", {"sh"})), viewKey(fixture.settings));
  // The same bake in a cache elsewhere (--cache, another output folder) keeps the frame's key.
  EXPECT_EQ(stageKey(viewCommand(fixture.settings, "/elsewhere/bake-0123", {"sh"})), viewKey(fixture.settings));
  EXPECT_EQ(stageArgv(viewCommand(fixture.settings, bake, {"sh"}), "/cache", "/cache/view")[1],
            "/cache/bake-0123/bake");
  // Isotropic texture filtering, as the reference's ray cones model it.
  const std::vector<std::string> view = viewCommand(fixture.settings, bake, {"sh"}).arguments;
  const auto anisotropy = std::find(view.begin(), view.end(), "--anisotropy");
  ASSERT_NE(anisotropy, view.end());
  ASSERT_NE(anisotropy + 1, view.end());
  EXPECT_EQ(*(anisotropy + 1), "1");
  EXPECT_NE(std::find(view.begin(), view.end(), "--sample-shading"), view.end());
  ReportSettings textured = fixture.settings;
  textured.engineSampleShading = false;
  const std::vector<std::string> texturedView = viewCommand(textured, bake, {"sh"}).arguments;
  EXPECT_EQ(std::find(texturedView.begin(), texturedView.end(), "--sample-shading"), texturedView.end());
  EXPECT_NE(std::find(texturedView.begin(), texturedView.end(), "--samples"), texturedView.end());
  const std::vector<std::function<void(ReportSettings&)>> traceChanges = {
      [](ReportSettings& s) { s.width = 64; }, [](ReportSettings& s) { s.passSpp = 32; },
      [](ReportSettings& s) { s.referenceIntegrator = "direct"; },
      [](ReportSettings& s) { s.referenceLightSamples = 1; },
      [](ReportSettings& s) { s.referenceLightSamples = 8; }};
  for (std::size_t i = 0; i < traceChanges.size(); ++i) {
    ReportSettings changed = fixture.settings;
    traceChanges[i](changed);
    EXPECT_NE(traceKey(changed), traceKey(fixture.settings)) << "trace change " << i;
  }
  EXPECT_NE(stageKey(traceCommand(fixture.settings, fixture.inputs, 4)), traceKey(fixture.settings));
  // The references' light samples reach iblkit-trace as --camera-light-samples, 1 as no option.
  const std::vector<std::string> trace = traceCommand(fixture.settings, fixture.inputs, 0).arguments;
  const auto split = std::find(trace.begin(), trace.end(), "--camera-light-samples");
  ASSERT_NE(split, trace.end());
  ASSERT_NE(split + 1, trace.end());
  EXPECT_EQ(*(split + 1), "2");
  ReportSettings single = fixture.settings;
  single.referenceLightSamples = 1;
  const std::vector<std::string> plain = traceCommand(single, fixture.inputs, 0).arguments;
  EXPECT_EQ(std::find(plain.begin(), plain.end(), "--camera-light-samples"), plain.end());
  // What iblkit-view alone reads does not touch the reference's key, nor the bake's.
  ReportSettings engineOnly = fixture.settings;
  engineOnly.engineSamples = 8;
  EXPECT_EQ(traceKey(engineOnly), traceKey(fixture.settings));
  EXPECT_EQ(stageKey(bakeCommand(engineOnly, fixture.inputs)),
            stageKey(bakeCommand(fixture.settings, fixture.inputs)));
  // The bake's interreflection bounces are the bake's, not the reference's.
  ReportSettings bounced = fixture.settings;
  bounced.bakeBounces = 0;
  EXPECT_NE(stageKey(bakeCommand(bounced, fixture.inputs)), stageKey(bakeCommand(fixture.settings, fixture.inputs)));
  EXPECT_EQ(traceKey(bounced), traceKey(fixture.settings));
  // So is its area sampling (ReportSettings::bakeAreaSampling, on by default: --ao-area).
  const std::vector<std::string> bakeArguments = bakeCommand(fixture.settings, fixture.inputs).arguments;
  EXPECT_NE(std::find(bakeArguments.begin(), bakeArguments.end(), "--ao-area"), bakeArguments.end());
  ReportSettings pointSampled = fixture.settings;
  pointSampled.bakeAreaSampling = false;
  const std::vector<std::string> pointArguments = bakeCommand(pointSampled, fixture.inputs).arguments;
  EXPECT_EQ(std::find(pointArguments.begin(), pointArguments.end(), "--ao-area"), pointArguments.end());
  EXPECT_NE(stageKey(bakeCommand(pointSampled, fixture.inputs)), stageKey(bakeCommand(fixture.settings, fixture.inputs)));
  EXPECT_EQ(traceKey(pointSampled), traceKey(fixture.settings));
}

TEST(StageCommands, TheScenesBytesAreInTheBakeAndTraceKeys) {
  Fixture fixture;
  const std::string bake = stageKey(bakeCommand(fixture.settings, fixture.inputs)),
                    trace = stageKey(traceCommand(fixture.settings, fixture.inputs, 0));
  std::ofstream(fixture.inputs.environmentFile) << "other pixels";
  EXPECT_NE(stageKey(bakeCommand(fixture.settings, fixture.inputs)), bake);
  EXPECT_NE(stageKey(traceCommand(fixture.settings, fixture.inputs, 0)), trace);
}

// A texture image in a file beside the glTF goes into the bake's and the trace's keys (editing the
// image re-runs them), and an occlusion texture makes the case score the glTF occlusion modes.
TEST(StageCommands, ImageFilesAreInputsAndAnOcclusionTextureIsNoticed) {
  const Fixture plain;  // its stand-in programs, and a scene without textures (first: it makes the scratch folder)
  const fs::path dir = plain.settings.binDir.parent_path() / "textured";
  fs::create_directories(dir);
  writePng(dir / "ao.png", Image(4, 4, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f)));
  test::GltfBuilder builder;
  const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<glm::vec2> uvs = {{0, 0}, {1, 0}, {0, 1}};
  builder.addPrimitiveNode({{"attributes", {{"POSITION", builder.addFloats(positions)},
                                            {"TEXCOORD_0", builder.addFloats(uvs)}}},
                            {"material", 0}});
  builder.document()["images"] = {{{"uri", "ao.png"}}};
  builder.document()["textures"] = {{{"source", 0}}};
  builder.document()["materials"] = {{{"occlusionTexture", {{"index", 0}}}}};
  builder.write(dir / "model.glb", test::GltfBuilder::Storage::Glb);
  std::ofstream(dir / "map.exr") << "pixels";

  const CaseInputs inputs = caseInputs(dir / "model.glb", dir / "map.exr");
  EXPECT_TRUE(inputs.occlusionTexture);
  EXPECT_NE(std::find(inputs.files.begin(), inputs.files.end(), dir / "ao.png"), inputs.files.end());
  const ReportSettings& settings = plain.settings;
  const std::string before = stageKey(bakeCommand(settings, inputs));
  writePng(dir / "ao.png", Image(4, 4, glm::vec4(0.25f, 0.25f, 0.25f, 1.0f)));
  EXPECT_NE(stageKey(bakeCommand(settings, inputs)), before);
  EXPECT_FALSE(plain.inputs.occlusionTexture);

  // The textured scene's reference traces with the engine frame's footprint, 1 / supersample.
  EXPECT_TRUE(inputs.textured);
  EXPECT_FALSE(plain.inputs.textured);
  const auto footprint = [](const StageCommand& command) {
    const auto at = std::find(command.arguments.begin(), command.arguments.end(), "--texture-footprint");
    return at == command.arguments.end() ? std::string("none") : *(at + 1);
  };
  ReportSettings four = settings;
  four.engineSupersample = 4;
  EXPECT_EQ(footprint(traceCommand(settings, inputs, 0)), "0.5");  // the default 2 x 2
  EXPECT_EQ(footprint(traceCommand(four, inputs, 0)), "0.25");
  EXPECT_EQ(footprint(traceCommand(four, plain.inputs, 0)), "none");
  EXPECT_EQ(stageKey(traceCommand(four, plain.inputs, 0)), stageKey(traceCommand(settings, plain.inputs, 0)));
}

}  // namespace
}  // namespace iblkit
