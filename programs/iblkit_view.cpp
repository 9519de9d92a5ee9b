// iblkit-view: the real-time engine's program (docs/engine.md).
//
//   iblkit-view OUTDIR|SCENE|MODEL --headless -o IMAGE [--env MAP] [--env-intensity X] [--width W] [--height H] [--mode M[,M...]]
//               [--exposure E] [--env-rotation D] [--samples MSAA] [--normal FILE] [--depth FILE]
//               [--bench N] [--no-sky] [--ao-rays N] [--texture-slots LIST | --no-textures]
//               [--anisotropy A] [--lights K] [--no-shadows] [--no-shadow-mask]
//               [--shadow-mask-resolution half|full] [--no-ground-visibility]
//
// OUTDIR is an iblkit-bake folder; a .json scene or a .gltf/.glb model is baked in memory first,
// under --env MAP when given (cli/scene_arguments.h: the same MODEL --env MAP as iblkit-trace). -o .exr
// writes linear float RGBA (alpha = coverage of non-ground objects), .png tone-mapped sRGB. Several
// modes (--mode sh,full) render in one process, each to the output names with {mode} replaced by its
// name (-o frame-{mode}.exr), and --bench times them in turn, round by round: what the report runs
// for each case, without a process (EGL, the bake's loading, the shared shaders' compiles) per mode.
// Without --headless the window viewer runs (engine/view/viewer.h, docs/viewer.md):
//
//   iblkit-view OUTDIR|SCENE [--env ENV] [--env-dir DIR] [--reference REF.exr | --reference REPORT [--case CASE]]
//               [--show IMAGE] [--compare VIEW] [--frames N] [--screenshot FILE] [--no-panel] [--width W] [--height H]
//               [--mode M] [--exposure E] ...
//   iblkit-view --reference REPORT [--case CASE]   (the case's own scene under its map)

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "baker/bake_in_memory.h"
#include "baker/environment_stages.h"
#include "cli/program.h"
#include "cli/scene_arguments.h"
#include "core/error.h"
#include "core/image_io.h"
#include "core/scene_environment.h"
#include "core/temporary_files.h"
#include "core/usage_error.h"
#include "bakefile/bake_folder.h"
#include "engine/gl/drawn_lights.h"
#include "engine/gl/gl_debug.h"
#include "engine/gl/headless_context.h"
#include "engine/gl/light_constants.h"
#include "engine/gl/render_target.h"
#include "engine/gl/renderer.h"
#include "engine/gl/texture_slot_names.h"
#include "engine/view/reference_comparison.h"
#include "engine/view/screenshot.h"
#include "engine/view/viewer.h"
#include "report/report_case_images.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

constexpr const char* kProgram = "iblkit-view";

struct Options {
  SceneArguments scene;  // OUTDIR|SCENE|MODEL, --env, --env-rotation, --env-intensity
  fs::path output, normalOutput, depthOutput;
  bool headless = false;
  int width = 0, height = 0;  // 0: the scene's size
  std::vector<std::string> modes = {"full"};  // several (headless), or "all" with --bench
  float exposure = 0.0f;
  bool exposureGiven = false;  // --exposure given: the window's exposure starts locked there
  int samples = 1;
  bool sampleShading = false;
  int supersample = 1;
  int bench = 0;
  int aoRays = 64;
  bool noSky = false;
  std::string textureSlots = "all";  // --texture-slots; --no-textures is "none"
  bool noTextures = false;
  float anisotropy = kDefaultTextureAnisotropy;
  int lights = -1;  // --lights K; < 0: all the suns
  bool noShadows = false;
  bool noShadowMask = false;
  bool noGroundVisibility = false;
  std::string shadowMaskResolution = "half";
  // The window viewer's.
  std::filesystem::path envDir, reference, screenshot;
  std::string caseName, show;  // --case: of a report --reference; --show: the image shown first
  std::string compare = "split";
  std::vector<fs::path> open;  // --open: as if dropped onto the window
  int frames = 0;
  bool noPanel = false;
};

// --shadow-mask-resolution: FrameSettings::shadowMaskDivisor.
int shadowMaskDivisor(const std::string& resolution) { return resolution == "full" ? 1 : 2; }

std::string lowerExtension(const fs::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension;
}

void requireExtension(const fs::path& file, std::initializer_list<const char*> allowed) {
  const std::string extension = lowerExtension(file);
  std::string list;
  for (const char* a : allowed) {
    if (extension == a) return;
    list += (list.empty() ? "" : " or ") + std::string(a);
  }
  fail(file, "unsupported output format (expected " + list + ")");
}

// A bake folder, or a scene or model baked in memory with `aoRays` visibility rays per vertex and
// the viewer's environment stages, under `environment` (the scene's map when it names none). A
// bake folder given another map (--env) has that map's stages prefiltered here, at the override's
// rotation and intensity, else the bake's.
// The in-memory bake's steps, reported to the viewer's panel (null: not shown).
std::function<void(const char*, std::size_t, std::size_t)> progressTo(LoadProgress* progress) {
  if (!progress) return {};
  return [progress](const char* step, std::size_t done, std::size_t total) { progress->report(step, done, total); };
}

BakedScene loadViewScene(const fs::path& input, const EnvironmentOverride& environment, int aoRays,
                         LoadProgress* progress = nullptr) {
  if (isSceneFile(input)) {
    InMemoryBakeOptions options;
    options.aoRays = aoRays;
    options.environment = environment;
    options.progress = progressTo(progress);
    return bakeInMemory(input, options);
  }
  if (environment.intensity && environment.file.empty())
    failUsage("--env-intensity", "with a bake folder, only together with --env (its stages hold the bake's intensity)");
  BakedScene bake = readBakeFolder(input);
  if (environment.file.empty()) return bake;
  const EnvironmentSettings settings{environment.file, environment.rotationDegrees.value_or(bake.env.rotationDegrees),
                                     environment.intensity.value_or(bake.env.intensity)};
  bake.env = computeEnvironmentStages(loadEnvironment(settings, environment.format), kViewerEnvironmentStages);
  return bake;
}

// 0 for no values.
double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

struct FrameTimes {
  double gpuMs = 0.0;             // the median over the rounds
  std::vector<double> cpuRounds;  // each round's CPU time, in round order
  double cpuMs() const { return median(cpuRounds); }
};

// The median over the rounds of a's time over b's in the same round: two variants' ratio with the
// load that changes from round to round divided out (a ratio of medians mixes the rounds).
double medianRoundRatio(const FrameTimes& a, const FrameTimes& b) {
  std::vector<double> ratios;
  for (std::size_t k = 0; k < a.cpuRounds.size() && k < b.cpuRounds.size(); ++k)
    if (b.cpuRounds[k] > 0.0) ratios.push_back(a.cpuRounds[k] / b.cpuRounds[k]);
  return ratios.empty() ? 0.0 : median(ratios);
}

// Median frame times of each variant (settings, most often one per mode) over `frames` rounds; each
// round renders every variant once, in turn, so that load from other processes weighs on all alike. CPU time runs from the first
// GL call to glFinish; GPU time is a GL_TIME_ELAPSED query around the frame (llvmpipe's is not
// meaningful: it renders when glFinish asks).
// `newShadowMaps`: every frame renders the shadow maps again (their cost; otherwise they are
// rendered once, the camera does not move them).
std::vector<FrameTimes> benchmark(Renderer& renderer, RenderTarget& target, const Camera& camera,
                                  const std::vector<FrameSettings>& variants, int frames, bool newShadowMaps = false) {
  std::vector<std::vector<double>> cpu(variants.size()), gpu(variants.size());
  GLuint query = 0;
  glCreateQueries(GL_TIME_ELAPSED, 1, &query);
  for (int frame = 0; frame < frames; ++frame)
    for (std::size_t m = 0; m < variants.size(); ++m) {
      const FrameSettings& modeSettings = variants[m];
      if (newShadowMaps) renderer.invalidateShadowMaps();
      const auto start = std::chrono::steady_clock::now();
      glBeginQuery(GL_TIME_ELAPSED, query);
      renderer.render(camera, modeSettings, target.framebuffer(), target.width(), target.height());
      target.resolve();
      glEndQuery(GL_TIME_ELAPSED);
      glFinish();
      cpu[m].push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      GLuint64 nanoseconds = 0;
      glGetQueryObjectui64v(query, GL_QUERY_RESULT, &nanoseconds);
      gpu[m].push_back(double(nanoseconds) * 1e-6);
    }
  glDeleteQueries(1, &query);
  checkGlErrors("benchmark");
  std::vector<FrameTimes> times;
  for (std::size_t m = 0; m < variants.size(); ++m) times.push_back({median(gpu[m]), cpu[m]});
  return times;
}

// `settings` in each of `modes`.
std::vector<FrameSettings> inModes(const FrameSettings& settings, const std::vector<ShadingMode>& modes) {
  std::vector<FrameSettings> variants;
  for (ShadingMode mode : modes) {
    variants.push_back(settings);
    variants.back().mode = mode;
  }
  return variants;
}

// The target's colour, box-filtered down by the supersampling factor (a power of two).
Image readFrame(RenderTarget& target, int supersample) {
  Image image = target.readColor();
  for (int factor = supersample; factor > 1; factor /= 2) image = downsample2x(image);
  return image;
}

Image renderLayer(Renderer& renderer, RenderTarget& target, const Camera& camera, FrameSettings settings,
                  FrameLayer layer, int supersample) {
  settings.layer = layer;
  renderer.render(camera, settings, target.framebuffer(), target.width(), target.height());
  Image image = readFrame(target, supersample);
  checkGlErrors("render");
  return image;
}

constexpr std::string_view kModePlaceholder = "{mode}";

// `file` with each {mode} replaced by `mode`'s name.
fs::path forMode(const fs::path& file, ShadingMode mode) {
  std::string name = file.string();
  const std::string_view modeName = shadingModeName(mode);
  for (std::size_t at = 0; (at = name.find(kModePlaceholder, at)) != std::string::npos; at += modeName.size())
    name.replace(at, kModePlaceholder.size(), modeName);
  return name;
}

// Output images written beside their targets under temporary names as they are rendered, then
// renamed into place together (commit) or removed (the destructor, when commit was not reached):
// several modes' frames are all written or none, holding one frame at a time in memory, and an
// interrupt removes the temporaries (core/temporary_files.h).
class StagedOutputs {
 public:
  StagedOutputs() = default;
  StagedOutputs(const StagedOutputs&) = delete;
  StagedOutputs& operator=(const StagedOutputs&) = delete;
  ~StagedOutputs() {
    for (const auto& [temporary, target] : staged_) discardTemporary(temporary);
  }

  // `image` for `target`: tone-mapped PNG (the frame's exposure and curve) or float EXR with alpha.
  void add(const fs::path& target, const Image& image, bool png, const FrameSettings& settings) {
    const fs::path temporary = createTemporaryFile(target);
    staged_.emplace_back(temporary, target);
    if (png)
      writePng(temporary, image, {.exposure = settings.exposure, .curve = settings.curve});
    else
      writeExr(temporary, image, {.pixelType = PixelType::Float, .writeAlpha = true});
  }

  void commit() {
    withTemporariesLocked([&] {
      for (const auto& [temporary, target] : staged_) {
        fs::rename(temporary, target);
        unregisterTemporary(temporary);
      }
    });
    staged_.clear();
  }

 private:
  std::vector<std::pair<fs::path, fs::path>> staged_;  // (temporary, target)
};

// --mode: one mode, "all" (every mode, --bench only), or several (a list).
std::vector<ShadingMode> parseModes(const std::vector<std::string>& names, bool* all) {
  *all = names.size() == 1 && names[0] == "all";
  if (*all) return std::vector<ShadingMode>(std::begin(kShadingModes), std::end(kShadingModes));
  std::vector<ShadingMode> modes;
  for (const std::string& name : names) {
    if (name == "all") failUsage("--mode", "'all' is not one of a list of modes");
    const ShadingMode mode = parseShadingMode(name);
    if (std::find(modes.begin(), modes.end(), mode) != modes.end())
      failUsage("--mode", "'" + name + "' is listed twice");
    modes.push_back(mode);
  }
  return modes;
}

int runHeadless(const Options& options) {
  if (options.output.empty() && options.bench == 0)
    failUsage("-o", "an output image is required with --headless");
  if (!options.output.empty()) requireExtension(options.output, {".exr", ".png"});
  for (const fs::path& layer : {options.normalOutput, options.depthOutput})
    if (!layer.empty()) requireExtension(layer, {".exr"});
  bool allModes = false;
  const std::vector<ShadingMode> modes = parseModes(options.modes, &allModes);
  if (allModes && options.bench == 0) failUsage("--mode", "'all' is only for --bench");
  if (allModes && !options.output.empty()) failUsage("-o", "not with --mode all (list the modes to write)");
  const std::pair<const char*, const fs::path*> outputOptions[] = {
      {"-o", &options.output}, {"--normal", &options.normalOutput}, {"--depth", &options.depthOutput}};
  for (const auto& [flag, file] : outputOptions)
    if (modes.size() > 1 && !file->empty() && file->string().find(kModePlaceholder) == std::string::npos)
      failUsage(flag, "with several modes the name needs {mode}, which each mode's name replaces");
  FrameSettings settings;
  settings.mode = modes.front();
  settings.exposure = options.exposure;
  settings.drawSky = !options.noSky;
  settings.sampleShading = options.sampleShading;
  settings.textureSlots = options.noTextures ? 0u : parseTextureSlots(options.textureSlots);
  settings.lightCount = options.lights;
  settings.shadows = !options.noShadows;
  settings.shadowMask = !options.noShadowMask;
  settings.groundVisibility = !options.noGroundVisibility;
  settings.shadowMaskDivisor = shadowMaskDivisor(options.shadowMaskResolution);

  const BakedScene bake = loadViewScene(options.scene.input, options.scene.environment, options.aoRays);
  // No image may replace the bake folder's files, the scene, a model or the map.
  std::vector<fs::path> inputs = sceneInputs(bake.scene, options.scene.environment);
  inputs.push_back(options.scene.input);
  std::vector<fs::path> outputs;
  if (!allModes)
    for (ShadingMode mode : modes)
      for (const auto& [flag, file] : outputOptions)
        if (!file->empty()) outputs.push_back(forMode(*file, mode));
  checkOutputs(inputs, outputs);
  settings.envRotationDegrees = envRotationFromBake(bake.env, options.scene.environment.rotationDegrees);
  const int width = options.width > 0 ? options.width : bake.scene.width;
  const int height = options.height > 0 ? options.height : bake.scene.height;

  HeadlessContext context = HeadlessContext::create();
  enableGlDebugOutput(GlDebugMode::Strict);
  Renderer renderer(bake, options.anisotropy);
  RenderTarget target(width * options.supersample, height * options.supersample, options.samples);
  const Camera camera = sceneCamera(bake.scene, float(width) / float(height));
  checkGlErrors("setup");

  // The output frames first: they also warm up their shader variants and render the shadow maps
  // for the frames timed after them (one warm-up frame less). Written all or none.
  if (!options.output.empty()) {
    StagedOutputs staged;
    for (ShadingMode mode : modes) {
      FrameSettings modeSettings = settings;
      modeSettings.mode = mode;
      renderer.render(camera, modeSettings, target.framebuffer(), target.width(), target.height());
      const Image image = readFrame(target, options.supersample);
      checkGlErrors("render");
      if (!options.normalOutput.empty())
        staged.add(forMode(options.normalOutput, mode),
                   renderLayer(renderer, target, camera, modeSettings, FrameLayer::Normal, options.supersample), false,
                   settings);
      if (!options.depthOutput.empty())
        staged.add(forMode(options.depthOutput, mode),
                   renderLayer(renderer, target, camera, modeSettings, FrameLayer::Depth, options.supersample), false,
                   settings);
      staged.add(forMode(options.output, mode), image, lowerExtension(options.output) == ".png", settings);
    }
    staged.commit();
  }
  if (options.bench > 0) {
    std::cout << kProgram << ": " << context.description() << ", " << width << "x" << height << ", "
              << target.samples() << " sample(s), texture slots " << textureSlotsName(settings.textureSlots)
              << " (" << bake.scene.textures.size() << " textures, anisotropy " << renderer.textureAnisotropy()
              << "), median of " << options.bench << " frames\n";
    // Warm-up: shader variants, caches (the output frame, when there is one, was the first).
    benchmark(renderer, target, camera, inModes(settings, modes), options.output.empty() || allModes ? 2 : 1);
    const std::vector<FrameTimes> times = benchmark(renderer, target, camera, inModes(settings, modes), options.bench);
    double unlit = 0.0, full = 0.0;
    const FrameTimes* fullTimes = nullptr;
    for (std::size_t m = 0; m < modes.size(); ++m) {
      std::cout << std::fixed << std::setprecision(2) << "  " << std::left << std::setw(15)
                << shadingModeName(modes[m]) << " cpu " << times[m].cpuMs() << " ms  gpu " << times[m].gpuMs
                << " ms\n";
      if (modes[m] == ShadingMode::Unlit) unlit = times[m].cpuMs();
      if (modes[m] == ShadingMode::Full) full = times[m].cpuMs(), fullTimes = &times[m];
    }
    if (unlit > 0.0 && full > 0.0)
      std::cout << "  full / unlit = " << std::setprecision(2) << full / unlit << '\n';
    const auto shadowed = std::find(modes.begin(), modes.end(), ShadingMode::LightsShadowed);
    const int lights = drawnLightCount(bake.env, settings.lightCount);
    // The shadow maps' own cost with every mode (the speed command), not for one mode's time.
    if (allModes && shadowed != modes.end() && settings.shadows && lights > 0) {
      const double cached = times[std::size_t(shadowed - modes.begin())].cpuMs();
      const FrameTimes fresh =
          benchmark(renderer, target, camera, inModes(settings, {ShadingMode::LightsShadowed}), options.bench, true)
              .front();
      std::cout << "  lights-shadowed with its " << lights << " shadow map(s) of " << kShadowMapSize << "^2 rendered "
                << "again each frame: cpu " << fresh.cpuMs() << " ms (the maps: " << fresh.cpuMs() - cached << " ms)\n";
      if (full > 0.0) {
        // The two frames alone, in turn (A/B pairs, as an A/B timer runs two commands): every other
        // mode's frame in between evicts the shadowed frame's maps and targets from the caches,
        // which a viewer drawing one mode does not pay.
        const std::vector<FrameTimes> pair =
            benchmark(renderer, target, camera, inModes(settings, {ShadingMode::Full, ShadingMode::LightsShadowed}),
                      options.bench);
        std::cout << "  lights-shadowed / full = " << medianRoundRatio(pair[1], pair[0])
                  << " (the two in turn, the median of the pairs' ratios; " << pair[1].cpuMs() << " / " << pair[0].cpuMs()
                  << " ms); among every mode " << medianRoundRatio(times[std::size_t(shadowed - modes.begin())], *fullTimes)
                  << " (the median of the rounds' ratios; the ratio of the medians " << cached / full << ")\n";
      }
      // The screen-space mask against the shadows in the lit pass, frames interleaved (single-sample
      // targets only: a multisampled one shadows in the lit pass either way).
      if (target.samples() == 1 && settings.shadowMask) {
        std::vector<FrameSettings> pair = inModes(settings, {ShadingMode::LightsShadowed, ShadingMode::LightsShadowed});
        pair[1].shadowMask = false;
        const std::vector<FrameTimes> both = benchmark(renderer, target, camera, pair, options.bench);
        std::cout << "  lights-shadowed, shadows in the lit pass (--no-shadow-mask): cpu " << both[1].cpuMs()
                  << " ms; with the screen-space mask: " << both[0].cpuMs() << " ms (ratio "
                  << both[1].cpuMs() / both[0].cpuMs() << ")\n";
        // The mask at the frame's resolution against the half-resolution one, interleaved too.
        std::vector<FrameSettings> sizes =
            inModes(settings, {ShadingMode::LightsShadowed, ShadingMode::LightsShadowed});
        sizes[0].shadowMaskDivisor = 2;
        sizes[1].shadowMaskDivisor = 1;
        const std::vector<FrameTimes> bySize = benchmark(renderer, target, camera, sizes, options.bench);
        std::cout << "  lights-shadowed, mask at full resolution: cpu " << bySize[1].cpuMs()
                  << " ms; at half resolution: " << bySize[0].cpuMs() << " ms (ratio "
                  << bySize[1].cpuMs() / bySize[0].cpuMs() << ")\n";
      }
    }
  }

  return 0;
}

// --env-dir defaults to assets/hdri, under IBLKIT_ASSETS when that is set.
fs::path defaultEnvironmentFolder() {
  const char* assets = std::getenv("IBLKIT_ASSETS");
  return (assets && *assets ? fs::path(assets) : fs::path("assets")) / "hdri";
}

// A report case's images for the comparison, and their source's name.
std::vector<ComparisonImage> caseImages(ReportCase& report, std::string* source) {
  *source = report.reportJson.string() + ", case " + report.caseName;
  std::vector<ComparisonImage> images;
  for (ReportCaseImage& image : report.images)
    images.push_back({std::move(image.name), std::move(image.detail), std::move(image.image)});
  return images;
}

// --reference: one image (OpenEXR), or a report (its output folder or report.json) whose case
// --case names: the case's reference and each mode's frame (report/report_case_images.h).
std::vector<ComparisonImage> readReferences(const Options& options, std::string* source) {
  if (options.reference.empty()) {
    if (!options.caseName.empty()) failUsage("--case", "only with --reference REPORT");
    return {};
  }
  if (!isReportPath(options.reference)) {
    if (!options.caseName.empty())
      failUsage("--case", "only with a report --reference (a folder or its report.json), not an image");
    *source = options.reference.string();
    return {{"reference", "", readExr(options.reference)}};
  }
  ReportCase report = readReportCase(options.reference, options.caseName);
  return caseImages(report, source);
}

int runWindow(Options options) {
  // Without a MODEL, a report case opens its own scene under its own map (unless --env names one).
  std::vector<ComparisonImage> references;
  std::string referenceSource;
  if (options.scene.input.empty()) {
    ReportCase report = readReportCase(options.reference, options.caseName);
    if (report.sceneFile.empty()) fail(report.reportJson, "case '" + report.caseName + "' names no scene file");
    if (!fs::is_regular_file(report.sceneFile))
      fail(report.sceneFile, "the scene of case '" + report.caseName + "' in " + report.reportJson.string() +
                                 " does not exist (relative paths are from the folder the report ran in)");
    options.scene.input = report.sceneFile;
    if (options.scene.environment.file.empty()) options.scene.environment.file = report.environmentFile;
    checkSceneArguments(options.scene);
    references = caseImages(report, &referenceSource);
  } else {
    references = readReferences(options, &referenceSource);
  }
  if (!options.output.empty())
    failUsage("-o", "only with --headless (the window saves screenshots: --screenshot)");
  if (options.bench > 0)
    failUsage("--bench", "only with --headless (the window prints its frame time with --frames)");
  if (!options.normalOutput.empty() || !options.depthOutput.empty())
    failUsage("--normal/--depth", "only with --headless");
  if (!options.screenshot.empty()) {
    const ScreenshotFiles files = screenshotFiles(options.screenshot);
    checkOutputs({options.scene.input, options.scene.environment.file, options.reference}, {files.exr, files.png});
  }
  ViewerOptions viewer;
  viewer.input = options.scene.input;
  viewer.width = options.width;
  viewer.height = options.height;
  if (options.modes.size() != 1) failUsage("--mode", "one mode in the window (several are for --headless)");
  viewer.mode = options.modes.front();
  viewer.exposure = options.exposure;
  viewer.autoExposure = !options.exposureGiven;
  viewer.open = options.open;
  viewer.envRotation = options.scene.environment.rotationDegrees;
  viewer.samples = options.samples;
  viewer.noSky = options.noSky;
  viewer.textureSlots = options.noTextures ? 0u : parseTextureSlots(options.textureSlots);
  viewer.anisotropy = options.anisotropy;
  viewer.lightCount = options.lights;
  viewer.shadows = !options.noShadows;
  viewer.shadowMask = !options.noShadowMask;
  viewer.groundVisibility = !options.noGroundVisibility;
  viewer.shadowMaskDivisor = shadowMaskDivisor(options.shadowMaskResolution);
  // A bake folder with --env alone starts with the bake's map and switches on the worker (the
  // window opens at once); a scene or model is baked under the map before the window opens.
  EnvironmentOverride environment = options.scene.environment;
  if (!isSceneFile(options.scene.input) && !environment.intensity) {
    viewer.environment = environment.file;
    environment.file.clear();
  }
  viewer.loadScene = [aoRays = options.aoRays, environment](const fs::path& input, const EnvironmentStages* current,
                                                            LoadProgress* progress) {
    if (!current) return loadViewScene(input, environment, aoRays);
    // Opened from the window: a bare model under the environment shown, a scene under its own map.
    const std::string extension = lowerExtension(input);
    if (isSceneFile(input) && (extension == ".gltf" || extension == ".glb")) {
      InMemoryBakeOptions options;
      options.aoRays = aoRays;
      options.environmentStages = current;
      options.progress = progressTo(progress);
      return bakeInMemory(input, options);
    }
    return loadViewScene(input, {}, aoRays, progress);
  };
  viewer.prepareEnvironment = [](const EnvironmentMap& map) {
    return computeEnvironmentStages(map, kViewerEnvironmentStages);
  };
  viewer.envDir = options.envDir.empty() ? defaultEnvironmentFolder() : options.envDir;
  viewer.references = std::move(references);
  viewer.referenceSource = referenceSource;
  viewer.show = options.show;
  viewer.compare = options.compare;
  viewer.frames = options.frames;
  viewer.screenshot = options.screenshot;
  viewer.panel = !options.noPanel;
  return runViewer(viewer);
}

void rejectWindowFlagsWhenHeadless(const Options& options) {
  if (!options.headless) return;
  if (options.frames > 0 || !options.screenshot.empty() || !options.reference.empty() || !options.envDir.empty() ||
      options.noPanel || !options.open.empty() || !options.caseName.empty() || !options.show.empty())
    throw UsageError(
        "--frames, --screenshot, --env-dir, --reference, --case, --show, --open and --no-panel are for the window, "
        "not --headless");
}

}  // namespace
}  // namespace iblkit

int main(int argc, char** argv) {
  using namespace iblkit;
  Options options;
  CLI::App app{"Renders a baked scene in real time (OpenGL 4.5), in a window or headless.", kProgram};
  addSceneArguments(app, options.scene, "input",
                    "iblkit-bake output folder, a .json scene, or a .gltf/.glb model lit by --env (window: "
                    "optional with --reference REPORT, which opens the case's own scene)",
                    /*required=*/false);
  app.add_flag("--headless", options.headless, "render offscreen through EGL and write -o");
  app.add_option("-o,--output", options.output,
                 "output image: .exr (linear float RGBA) or .png (tone-mapped)");
  app.add_option("--width", options.width, "image width (default: the scene's)")->check(CLI::Range(1, 16384));
  app.add_option("--height", options.height, "image height (default: the scene's)")
      ->check(CLI::Range(1, 16384));
  std::vector<std::string> modeChoices = enumNames(kShadingModeNames);
  modeChoices.push_back("all");
  app.add_option("--mode", options.modes,
                 "shading mode; headless, several (comma-separated: each to its own -o with {mode} in the "
                 "name, timed in turn by --bench) or all (every mode, --bench)")
      ->delimiter(',')
      ->check(nameChoice(modeChoices, "shading mode"))
      ->capture_default_str();
  app.add_option("--exposure", options.exposure,
                 "exposure in stops (PNG and display); the window's is automatic unless this is given (it then "
                 "starts locked)")
      ->capture_default_str();
  app.add_flag("--sample-shading", options.sampleShading,
               "shade every MSAA sample (supersampling: the pixel's shading is averaged, as the reference does)");
  app.add_option("--supersample", options.supersample,
                 "render K x K pixels per output pixel and box-filter them down (K = 1, 2 or 4)")
      ->check(CLI::IsMember({1, 2, 4}));
  app.add_option("--samples", options.samples, "MSAA samples per pixel")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  app.add_option("--normal", options.normalOutput, "also write the world shading normal layer (.exr)");
  app.add_option("--depth", options.depthOutput, "also write the camera distance layer (.exr)");
  app.add_option("--bench", options.bench, "render N frames and print the median frame time")
      ->check(CLI::Range(1, 100000));
  app.add_flag("--no-sky", options.noSky, "black background (alpha 0) instead of the environment");
  app.add_option("--texture-slots", options.textureSlots,
                 "material texture slots used: comma-separated base-color, metallic-roughness, normal, "
                 "occlusion, emissive; or all, none")
      ->capture_default_str();
  app.add_flag("--no-textures", options.noTextures, "every material with its factors only (--texture-slots none)");
  app.add_option("--anisotropy", options.anisotropy,
                 "maximum anisotropy of the trilinear texture samplers (1: isotropic; clamped to the driver's)")
      ->check(CLI::Range(1.0f, 16.0f))
      ->capture_default_str();
  app.add_option("--lights", options.lights,
                 "lights and lights-shadowed modes: draw the K brightest suns as lights, the others stay in the "
                 "residual's SH9 (default: all, at most " + std::to_string(kMaxEngineLights) + ")")
      ->check(CLI::Range(0, kMaxEngineLights));
  app.add_flag("--no-shadows", options.noShadows, "lights-shadowed draws its lights unshadowed (as lights)");
  app.add_flag("--no-shadow-mask", options.noShadowMask,
               "lights-shadowed reads the shadow maps in the lit pass, not from a screen-space mask "
               "(single-sample targets; multisampled ones always do)");
  app.add_flag("--no-ground-visibility", options.noGroundVisibility,
               "lights-shadowed shadows a planar ground per pixel (the mask or the lit pass) instead of reading "
               "the ground's visibility texture, computed with the shadow maps");
  app.add_option("--shadow-mask-resolution", options.shadowMaskResolution,
                 "the screen-space shadow mask's resolution: half (a mask pixel per 2 x 2 frame pixels, upsampled "
                 "with its depths) or full (each pixel's own visibilities)")
      ->check(CLI::IsMember({"half", "full"}))
      ->capture_default_str();
  app.add_option("--ao-rays", options.aoRays, "visibility rays per vertex when baking a scene in memory")
      ->check(CLI::Range(1, 1 << 16))
      ->capture_default_str();
  app.add_option("--env-dir", options.envDir,
                 "window: folder of environment maps to switch between (default: assets/hdri)");
  app.add_option("--reference", options.reference,
                 "window: path-traced reference (.exr) shown beside the live frame, or as a difference; or an "
                 "iblkit-report output (its folder or report.json) whose case --case names: its reference and "
                 "each mode's frame, flipped through with { and }");
  app.add_option("--case", options.caseName,
                 "window: the case of a report --reference, SCENE-ENVIRONMENT (e.g. bunny-sky; default: the only one)");
  app.add_option("--show", options.show,
                 "window: the image of --reference shown first: reference, or a mode of the report case");
  addNameOption(app, "--compare", options.compare, kComparisonViewNames, "view",
                "window: the reference view to start with");
  app.add_option("--frames", options.frames, "window: quit after N frames and print the median frame time")
      ->check(CLI::Range(1, 1000000));
  app.add_option("--screenshot", options.screenshot,
                 "window: at exit, write the last frame as FILE.exr (radiance) and FILE.png (the view)");
  app.add_flag("--no-panel", options.noPanel, "window: start with the panel hidden (Tab shows it)");
  app.add_option("--open", options.open,
                 "window: after the first frame, open these files as if dropped onto the window (a scene, model, "
                 "map or bake folder)");
  return runProgram(app, argc, argv, [&] {
    rejectWindowFlagsWhenHeadless(options);
    if (options.noTextures && options.textureSlots != "all")
      failUsage("--no-textures", "give --no-textures or --texture-slots, not both");
    try {
      parseTextureSlots(options.textureSlots);
    } catch (const Error& e) {
      throw UsageError(e.what());  // a bad command line: status 2, like --mode's names
    }
    if (options.scene.input.empty() && (options.headless || !isReportPath(options.reference)))
      throw UsageError("input is required");  // the window takes a report case's scene instead
    checkSceneArguments(options.scene);
    options.exposureGiven = app.count("--exposure") > 0;
    return options.headless ? runHeadless(options) : runWindow(options);
  });
}
