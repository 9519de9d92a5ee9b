// iblkit-trace SCENE -o OUT.exr: the reference path tracer. Renders the image the real-time
// engine approximates (same scene, camera, environment and material model) with Embree, and
// writes OpenEXR (plus optional feature layers and a PNG preview). docs/reference-tracer.md
// describes the integrators, options and conventions.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "cli/pass_arguments.h"
#include "cli/program.h"
#include "cli/scene_arguments.h"
#include "core/error.h"
#include "core/image_io.h"
#include "core/scene.h"
#include "core/scene_environment.h"
#include "core/usage_error.h"
#include "reference/environment_point_lights.h"
#include "reference/environment_sampler.h"
#include "reference/integrator.h"
#include "reference/median_cut_sampler.h"
#include "reference/noise_split.h"
#include "reference/pass_sum.h"
#include "reference/render_scene.h"
#include "reference/renderer.h"
#include "score/halves_flip.h"

namespace iblkit {
namespace {

struct Options {
  SceneArguments scene;  // SCENE and --env, --env-rotation, --env-intensity
  std::filesystem::path output, png;
  std::filesystem::path albedo, normal, depth, variance, mask, bentNormal;
  bool misCompensation = false;
  std::string integrator = "path", envSampling = "mis", filter = "box";
  std::string envOrientation = "normal";
  int maxDepth = 16;
  int environmentLights = 64;
  float aoDistance = std::numeric_limits<float>::infinity();
  int samplesPerPixel = 64;
  double timeSeconds = 0.0;
  int width = 0, height = 0;
  std::uint32_t seed = 0;
  int threads = 0;
  float exposure = 0.0f;
  std::optional<float> phongExponent;
  bool noTextures = false;
  float textureFootprint = kDefaultTextureFootprint;
  PassArguments passes;  // --pass, --passes, --sum, --merge (cli/pass_arguments.h, docs/cluster.md)
  int cameraLightSamples = 1;
  std::string groundOcclusion = "on";
  std::filesystem::path noiseSplit;  // --noise-split: the halves' noise as JSON
};

// Fails early, before a long render, when an output cannot be written.
void checkOutputFolder(const std::filesystem::path& file) {
  if (file.empty()) return;
  const std::filesystem::path folder = file.parent_path();
  if (!folder.empty() && !std::filesystem::is_directory(folder)) fail(file, "folder does not exist");
}

// A progress bar with the estimated time left, redrawn in place (only on a terminal).
void drawProgress(double fraction, double seconds) {
  static double lastDrawn = -1.0;
  if (fraction < 1.0 && seconds - lastDrawn < 0.25) return;
  lastDrawn = seconds;
  constexpr int kWidth = 40;
  const int filled = static_cast<int>(fraction * kWidth);
  const double eta = fraction > 0.0 ? seconds * (1.0 - fraction) / fraction : 0.0;
  std::fprintf(stderr, "\r[%s%s] %3d%%  ETA %.0f s ",
               std::string(static_cast<std::size_t>(filled), '#').c_str(),
               std::string(static_cast<std::size_t>(kWidth - filled), ' ').c_str(),
               static_cast<int>(fraction * 100.0), eta);
  std::fflush(stderr);
}

// iblkit-trace --merge SUM...: the passes' sums added up, written as the image and its layers.
int mergePasses(const Options& options) {
  checkOutputs(options.passes.merge, {options.output, options.variance, options.png, options.passes.sum});
  const PassSum sum = mergePassSumFiles(options.passes.merge);
  if (sum.samples.size() > 1 || sum.samples.front().first != 0)
    warn("--merge", "the samples merged are " + sampleRangesText(sum.samples) +
                        ", not one range from 0: is a pass missing?");
  const Image beauty = meanRadiance(sum);
  const ExrWriteOptions exrOptions{.pixelType = PixelType::Float};
  if (!options.output.empty()) writeExr(options.output, beauty, exrOptions);
  if (!options.variance.empty()) writeExr(options.variance, meanVariance(sum), exrOptions);
  if (!options.png.empty()) writePng(options.png, beauty, ToneMapping{.exposure = options.exposure});
  if (!options.passes.sum.empty()) writePassSum(options.passes.sum, sum);
  std::printf("%dx%d, %llu spp merged from %zu files\n", sum.width, sum.height,
              static_cast<unsigned long long>(sum.sampleCount()), options.passes.merge.size());
  return 0;
}

int run(const Options& options, const CLI::App& app) {
  checkPassArguments(app, options.passes, "scene");
  if (!options.passes.merge.empty()) return mergePasses(options);
  if (options.passes.passes && options.timeSeconds > 0.0)
    failUsage("--passes", "cannot split a --time render");
  // Before any file is read, naming the option (render() would say "render: ...").
  requireInRange("--spp", options.samplesPerPixel, 1, kMaxSamplesPerPixel);
  if (app.count("--width")) requireInRange("--width", options.width, 1, kMaxImageSide);
  if (app.count("--height")) requireInRange("--height", options.height, 1, kMaxImageSide);
  requireInRange("--threads", options.threads, 0, kMaxThreads);
  const ThreadLimit threads(options.threads);
  if (options.maxDepth < 1)
    failUsage("--max-depth", "must be at least 1, got " + std::to_string(options.maxDepth));
  if (!(options.aoDistance > 0.0f)) failUsage("--ao-distance", "must be positive");
  if (!(options.textureFootprint >= 0.0f)) failUsage("--texture-footprint", "must be >= 0 (pixels)");
  if (!(options.timeSeconds >= 0.0) || !std::isfinite(options.timeSeconds))
    failUsage("--time", "must be a finite number of seconds >= 0");
  checkSceneArguments(options.scene);
  IntegratorSettings integratorSettings;
  integratorSettings.kind = parseIntegratorKind(options.integrator);
  integratorSettings.envSampling = parseEnvSampling(options.envSampling);
  const bool medianCut = integratorSettings.envSampling == EnvSampling::MedianCut ||
                         integratorSettings.envSampling == EnvSampling::Lights;
  if (app.count("--env-lights") && !medianCut)
    failUsage("--env-lights", "needs --env-sampling mediancut or lights");
  const std::optional<int> medianCutLevels = medianCutLevelsOf(options.environmentLights);
  if (!medianCutLevels)
    failUsage("--env-lights",
              "must be a power of 2 in 1..4096, not " + std::to_string(options.environmentLights));
  integratorSettings.maxDepth = options.maxDepth;
  integratorSettings.aoDistance = options.aoDistance;
  requireInRange("--camera-light-samples", options.cameraLightSamples, 1, kMaxSplitLightDraws);
  integratorSettings.cameraLightSamples = options.cameraLightSamples;
  integratorSettings.groundOcclusion = options.groundOcclusion == "on";
  if (!options.noiseSplit.empty() && options.samplesPerPixel % 2 != 0)
    failUsage("--noise-split", "needs an even --spp (half of it for each half)");
  const PixelFilterKind filter = parsePixelFilter(options.filter);
  if (options.phongExponent) {
    // Beyond ~1e6 the lobe's normalisation and pdf overflow float (NaN pixels).
    if (!std::isfinite(*options.phongExponent) || *options.phongExponent < 0.0f ||
        *options.phongExponent > kMaxPhongExponent)
      failUsage("--phong", "exponent must be in [0, 1e6]");
    integratorSettings.phong = PhongLobe{*options.phongExponent};
  }
  if (!options.bentNormal.empty() && integratorSettings.kind != IntegratorKind::AmbientOcclusion)
    failUsage("--bent-normal", "needs --integrator ao");
  const SampleRange samples =
      options.passes.passes
          ? passSamples(options.samplesPerPixel, *options.passes.pass, *options.passes.passes)
          : SampleRange{0, static_cast<std::uint32_t>(options.samplesPerPixel)};
  // The halves take seeds 2s and 2s + 1 (reference/noise_split.h): no pass of another render.
  if (!options.noiseSplit.empty() && (options.passes.passes || !options.passes.sum.empty()))
    failUsage("--noise-split", "renders its own two halves; it does not go with --pass or --sum");
  for (const auto* file : {&options.output, &options.png, &options.albedo, &options.normal, &options.depth,
                           &options.variance, &options.mask, &options.bentNormal, &options.passes.sum,
                           &options.noiseSplit})
    checkOutputFolder(*file);

  Scene scene = loadScene(options.scene.input);
  // No output may replace the scene, a model or the map (nor a device node).
  checkOutputs(sceneInputs(scene, options.scene.environment),
               {options.output, options.png, options.albedo, options.normal, options.depth, options.variance,
                options.mask, options.bentNormal, options.passes.sum, options.noiseSplit});
  const std::uint64_t key =
      options.passes.sum.empty()
          ? 0
          : renderKey(sceneInputs(scene, options.scene.environment), samplingArguments(app, "scene"));
  RenderSettings settings;
  settings.width = app.count("--width") ? options.width : scene.width;
  settings.height = app.count("--height") ? options.height : scene.height;
  settings.firstSample = static_cast<int>(samples.first);
  settings.samplesPerPixel = static_cast<int>(samples.count);
  settings.timeSeconds = options.timeSeconds;
  settings.seed = options.seed;
  settings.threads = options.threads;
  settings.filter = filter;
  settings.textureFootprint = options.textureFootprint;

  const EnvironmentMap environment = loadSceneEnvironment(scene, options.scene.environment);
  const EnvironmentSampler environmentSampler(
      environment, options.misCompensation,
      parseEnumName(kLightOrientationNames, options.envOrientation, "--env-orientation", "orientation"));
  if (environmentSampler.isBlack())
    warn(overriddenEnvironment(scene.environment, options.scene.environment).file,
         "environment is black everywhere: only emission will show");

  const float aspect = static_cast<float>(settings.width) / static_cast<float>(std::max(settings.height, 1));
  const Camera camera = sceneCamera(scene, aspect);
  const RenderScene renderScene(std::move(scene), options.noTextures ? 0u : kAllTextureSlots);
  // The median-cut regions, only for the strategies that use them.
  std::optional<MedianCutSampler> medianCutSampler;
  std::optional<EnvironmentPointLights> pointLights;
  if (integratorSettings.envSampling == EnvSampling::MedianCut)
    medianCutSampler.emplace(environment, *medianCutLevels, options.misCompensation);
  if (integratorSettings.envSampling == EnvSampling::Lights)
    pointLights.emplace(environment, *medianCutLevels);
  const Integrator integrator(
      renderScene, environment, environmentSampler, integratorSettings,
      {medianCutSampler ? &*medianCutSampler : nullptr, pointLights ? &*pointLights : nullptr});

  const bool terminal = isatty(STDERR_FILENO) != 0;
  const RenderProgress progress = terminal ? RenderProgress(drawProgress) : RenderProgress();
  std::optional<NoiseSplit> split;
  if (!options.noiseSplit.empty()) split = renderNoiseSplit(integrator, camera, settings, progress);
  RenderResult result = split ? split->mean : render(integrator, camera, settings, progress);
  if (terminal) std::fputs("\n", stderr);

  const ExrWriteOptions exrOptions{.pixelType = PixelType::Float};
  if (!options.output.empty()) writeExr(options.output, result.beauty, exrOptions);
  if (!options.passes.sum.empty()) {
    result.sum.renderKey = key;
    writePassSum(options.passes.sum, result.sum);
  }
  const std::pair<const std::filesystem::path*, const Image*> layers[] = {
      {&options.albedo, &result.albedo}, {&options.normal, &result.normal},
      {&options.depth, &result.depth},   {&options.variance, &result.variance},
      {&options.mask, &result.mask},     {&options.bentNormal, &result.bentNormal}};
  for (const auto& [file, image] : layers)
    if (!file->empty()) writeExr(*file, *image, exrOptions);
  if (!options.png.empty()) writePng(options.png, result.beauty, ToneMapping{.exposure = options.exposure});

  const double megaRaysPerSecond =
      result.seconds > 0.0 ? static_cast<double>(result.rays) / result.seconds * 1e-6 : 0.0;
  std::printf("%dx%d, %d spp, %.2f s, %.2f Mrays/s\n", settings.width, settings.height,
              result.samplesPerPixel, result.seconds, megaRaysPerSecond);
  if (split) {
    const double flip =
        split->geometry.empty() ? 0.0 : halvesMeanFlip(split->a.beauty, split->b.beauty, split->geometry);
    writeNoiseSplitJson(options.noiseSplit, *split, flip);
    std::printf(
        "noise split: relMSE of the mean %.3g (object %.3g over %zu px, %.0f%%; ground %.3g over %zu px, "
        "%.0f%%; direct light %.0f%%, indirect %.0f%%), halves' FLIP %.4f\n",
        split->relMse, split->object.relMse, split->object.pixels, 100.0 * split->object.share,
        split->ground.relMse, split->ground.pixels, 100.0 * split->ground.share, 100.0 * split->direct.share,
        100.0 * split->indirect.share, flip);
  }
  return 0;
}

}  // namespace
}  // namespace iblkit

int main(int argc, char** argv) {
  using namespace iblkit;
  Options options;
  CLI::App app{"Reference path tracer (Embree): renders a scene under its environment map", "iblkit-trace"};
  addSceneArguments(app, options.scene, "scene", "scene (.json), or a .gltf/.glb model lit by --env");
  app.add_option("-o,--output", options.output, "beauty image, OpenEXR float RGB (required unless --sum)");
  app.add_option("--png", options.png, "PNG preview (tone-mapped, sRGB)");
  app.add_option("--exposure", options.exposure, "PNG exposure in stops");
  app.add_option("--albedo", options.albedo, "first-hit base colour, OpenEXR");
  app.add_option("--normal", options.normal, "first-hit world shading normal, OpenEXR");
  app.add_option("--depth", options.depth, "distance to the first hit (metres), OpenEXR");
  app.add_option("--variance", options.variance, "variance of each beauty pixel's mean, OpenEXR");
  app.add_option("--mask", options.mask, "coverage of non-ground objects, OpenEXR");
  app.add_option("--bent-normal", options.bentNormal, "ao only: mean unoccluded direction, OpenEXR");
  app.add_flag("--mis-compensation", options.misCompensation,
               "MIS compensation in the environment sampler (env, mis, mediancut)");
  addNameOption(app, "--env-orientation", options.envOrientation, kLightOrientationNames, "orientation",
                "env and mis: normal samples the map by its texels times a bound of the cosine with the "
                "vertex's normal, none by the texels alone");
  app.add_option("--env-lights", options.environmentLights,
                 "median-cut regions of --env-sampling mediancut and point lights of lights (a power of 2 "
                 "in 1..4096, default 64)");
  app.add_option("--phong", options.phongExponent,
                 "every surface uses the modified Phong lobe of this exponent (sampling study)");
  app.add_option("--max-depth", options.maxDepth, "most scattering events of a path");
  app.add_option("--ao-distance", options.aoDistance, "ao: occluders farther away do not count");
  app.add_option("--spp", options.samplesPerPixel, "samples per pixel (per pass with --time)");
  app.add_option("--time", options.timeSeconds, "render passes of --spp until this many seconds have passed");
  app.add_option("--width", options.width, "image width (default: the scene's)");
  app.add_option("--height", options.height, "image height (default: the scene's)");
  app.add_option("--seed", options.seed, "random seed");
  app.add_option("--camera-light-samples", options.cameraLightSamples,
                 "environment light samples at the camera ray's first hit (splitting, 1..64)");
  app.add_option("--ground-occlusion", options.groundOcclusion,
                 "mis on a horizontal ground (Lambert, or rough under a specular layer): its exact "
                 "unoccluded light minus the light the objects hide, a control variate where the BRDF "
                 "depends on the directions (on, default), or the plain estimate (off)")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_option("--noise-split", options.noiseSplit,
                 "render two independent halves (seeds 2s, 2s+1) and write their noise estimate (JSON)");
  app.add_option("--threads", options.threads, "worker threads (0: all)");
  app.add_flag("--no-textures", options.noTextures,
               "trace the materials' constant factors (every texture slot off; alpha from the factor)");
  app.add_option("--texture-footprint", options.textureFootprint,
                 "camera ray cone spread in pixels (texture level of detail; 0.5 = the report's 2x2 "
                 "supersampled engine frame, 0 = finest level)")
      ->check(finiteNumber());
  addNameOption(app, "--integrator", options.integrator, kIntegratorNames, "integrator");
  addNameOption(app, "--env-sampling", options.envSampling, kEnvSamplingNames, "strategy");
  // gaussian: sigma 0.5 px, radius 1.5 px (reference/pixel_filter.h).
  addNameOption(app, "--filter", options.filter, kPixelFilterNames, "filter");
  addPassArguments(app, options.passes, "scene");
  return runProgram(app, argc, argv, [&] { return run(options, app); });
}
