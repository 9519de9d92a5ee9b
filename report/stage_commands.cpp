#include "report/stage_commands.h"

#include <algorithm>
#include <charconv>
#include <sstream>
#include <stdexcept>

#include "core/scene.h"
#include "report/case_modes.h"

namespace iblkit {

namespace fs = std::filesystem;

namespace {

std::string stageFile(const std::string& name) { return std::string(kStageFolder) + "/" + name; }

void appendSize(const ReportSettings& settings, std::vector<std::string>& arguments) {
  arguments.insert(arguments.end(),
                   {"--width", std::to_string(settings.width), "--height", std::to_string(settings.height)});
}

}  // namespace

CaseInputs caseInputs(const fs::path& sceneFile, const fs::path& environmentFile) {
  CaseInputs inputs{sceneFile, environmentFile, {sceneFile}, false, false, {}};
  const Scene scene = loadScene(sceneFile);
  // A missing model file is left to the program that reads it, which fails naming it.
  const auto add = [&](const fs::path& file) {
    std::error_code error;
    if (std::find(inputs.files.begin(), inputs.files.end(), file) == inputs.files.end() &&
        fs::is_regular_file(file, error))
      inputs.files.push_back(file);
  };
  for (const fs::path& model : scene.modelFiles) add(model);
  // An image embedded in a glTF names that glTF, already in the list.
  for (const TextureImage& image : scene.images) add(image.file);
  inputs.files.push_back(environmentFile);
  inputs.environmentRotationDegrees = scene.environment.rotationDegrees;
  inputs.environmentIntensity = scene.environment.intensity;
  inputs.textured = !scene.textures.empty();
  inputs.lobes = sceneLobes(scene);
  inputs.occlusionTexture = inputs.lobes.occlusionTexture;
  return inputs;
}

namespace {

// iblkit-bake's visibility options (what reused_visibility.h compares).
void appendVisibilityOptions(const ReportSettings& settings, std::vector<std::string>& arguments) {
  arguments.insert(arguments.end(), {"--bounces", std::to_string(settings.bakeBounces)});
  if (settings.bakeAreaSampling) arguments.push_back("--ao-area");
}

}  // namespace

StageCommand visibilityCommand(const ReportSettings& settings, const CaseInputs& inputs) {
  StageCommand command{settings.binDir / "iblkit-bake", {inputs.sceneFile.string()}, {}};
  // The scene and what it reads, not the map.
  for (const fs::path& file : inputs.files)
    if (file != inputs.environmentFile) command.inputFiles.push_back(file);
  appendVisibilityOptions(settings, command.arguments);
  command.arguments.insert(command.arguments.end(), {"--visibility-only", "-o", stageFile("bake")});
  return command;
}

namespace {

// A float argument that reads back as the same float (the shortest such text).
std::string floatArgument(float value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

// A stage folder in the cache as the stage's command names it (under kCacheFolder).
std::string cachedStage(const fs::path& folder) { return std::string(kCacheFolder) + "/" + folder.filename().string() + "/bake"; }

}  // namespace

StageCommand environmentCommand(const ReportSettings& settings, const CaseInputs& inputs) {
  // The map alone: no scene, so every scene under it (at its rotation and intensity) shares it.
  return {settings.binDir / "iblkit-bake",
          {"--env", inputs.environmentFile.string(), "--env-rotation", floatArgument(inputs.environmentRotationDegrees),
           "--env-intensity", floatArgument(inputs.environmentIntensity), "--environment-only", "-o",
           stageFile("bake")},
          {inputs.environmentFile}};
}

StageCommand bakeCommand(const ReportSettings& settings, const CaseInputs& inputs, const fs::path& visibility,
                         const fs::path& environment) {
  StageCommand command{settings.binDir / "iblkit-bake",
                       {inputs.sceneFile.string(), "--env", inputs.environmentFile.string()},
                       inputs.files};
  appendVisibilityOptions(settings, command.arguments);
  if (!visibility.empty())
    command.arguments.insert(command.arguments.end(), {"--visibility-from", cachedStage(visibility)});
  if (!environment.empty())
    command.arguments.insert(command.arguments.end(), {"--environment-from", cachedStage(environment)});
  command.arguments.insert(command.arguments.end(), {"-o", stageFile("bake")});
  return command;
}

namespace {

// A view's arguments after --mode MODE: size, samples, supersampling, anisotropy, bench frames.
std::vector<std::string> viewOptions(const ReportSettings& settings, const std::string& mode) {
  std::vector<std::string> arguments;
  appendSize(settings, arguments);
  // Shadow-mapped frames without sample shading: llvmpipe's sample-rate invocations misplace the
  // shadow lookups along silhouettes (a lone diffuse sphere under sky: lights-shadowed against
  // lights FLIP 0.088 with --sample-shading, 0.001 without; docs/engine.md "Shadows"). They shade
  // as many points per pixel by supersampling twice as far per axis instead.
  const bool shadowMapped = mode == "lights-shadowed";
  const bool sampleShading = settings.engineSampleShading && !shadowMapped;
  int supersample = settings.engineSupersample;
  if (shadowMapped && settings.engineSampleShading && settings.engineSamples > 1) supersample = std::min(2 * supersample, 4);  // iblkit-view's largest
  if (settings.engineSamples > 1) {
    arguments.insert(arguments.end(), {"--samples", std::to_string(settings.engineSamples)});
    if (sampleShading) arguments.push_back("--sample-shading");
  }
  if (supersample > 1) arguments.insert(arguments.end(), {"--supersample", std::to_string(supersample)});
  arguments.insert(arguments.end(), {"--anisotropy", std::to_string(settings.engineAnisotropy)});
  if (settings.benchFrames > 0)
    arguments.insert(arguments.end(), {"--bench", std::to_string(settings.benchFrames)});
  return arguments;
}

}  // namespace

std::vector<std::vector<std::string>> viewGroups(const ReportSettings& settings, const std::vector<std::string>& modes) {
  std::vector<std::vector<std::string>> groups;
  std::vector<std::vector<std::string>> options;  // each group's viewOptions
  for (const std::string& mode : modes) {
    std::vector<std::string> own = viewOptions(settings, mode);
    const auto same = std::find(options.begin(), options.end(), own);
    if (same != options.end()) {
      groups[std::size_t(same - options.begin())].push_back(mode);
    } else {
      groups.push_back({mode});
      options.push_back(std::move(own));
    }
  }
  return groups;
}

std::string viewFrameFile(const std::string& mode) { return "frame-" + mode + ".exr"; }

StageCommand viewCommand(const ReportSettings& settings, const fs::path& bake, const std::vector<std::string>& modes) {
  if (modes.empty() || viewGroups(settings, modes).size() != 1)
    throw std::logic_error("viewCommand: modes that need different iblkit-view options");
  std::string list;
  for (const std::string& mode : modes) list += (list.empty() ? "" : ",") + mode;
  StageCommand command{settings.binDir / "iblkit-view",
                       {std::string(kCacheFolder) + "/" + bake.filename().string() + "/bake", "--headless",
                        "-o", stageFile(viewFrameFile("{mode}")), "--mode", list},
                       {}};
  const std::vector<std::string> options = viewOptions(settings, modes.front());
  command.arguments.insert(command.arguments.end(), options.begin(), options.end());
  return command;
}

StageCommand traceCommand(const ReportSettings& settings, const CaseInputs& inputs, int seed, int passes) {
  StageCommand command{settings.binDir / "iblkit-trace",
                       {inputs.sceneFile.string(), "--env", inputs.environmentFile.string(), "-o",
                        stageFile("beauty.exr"), "--depth", stageFile("depth.exr"), "--spp",
                        std::to_string(passes * settings.passSpp), "--seed", std::to_string(seed)},
                       inputs.files};
  std::vector<std::string>& arguments = command.arguments;
  if (seed == 0) arguments.insert(arguments.end(), {"--normal", stageFile("normal.exr")});
  if (settings.referenceIntegrator != "path")
    arguments.insert(arguments.end(), {"--integrator", settings.referenceIntegrator});
  if (settings.referenceLightSamples != 1)
    arguments.insert(arguments.end(),
                     {"--camera-light-samples", std::to_string(settings.referenceLightSamples)});
  if (inputs.textured) {
    std::ostringstream footprint;
    footprint << 1.0 / double(std::max(1, settings.engineSupersample));  // 1, 0.5, 0.25: exact
    arguments.insert(arguments.end(), {"--texture-footprint", footprint.str()});
  }
  appendSize(settings, arguments);
  return command;
}

}  // namespace iblkit
