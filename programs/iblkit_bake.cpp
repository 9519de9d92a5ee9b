// iblkit-bake: precomputes what the real-time engine needs for a scene (docs/baker.md).
//
//   iblkit-bake SCENE [--env ENV] [--env-format latlong|mirrorball|angular] [--env-rotation D]
//               [--env-intensity I] -o OUTDIR [--ao-rays N]
//               [--ao-distance D] [--ao-falloff P] [--ao-area] [--bounces N] [--seed S] [--threads T]
//               [--sh-window auto|none|BANDS] [--specular-samples N] [--lut-size N]
//               [--sun-threshold auto|L] [--max-suns N] [--median-cut-levels N]
//               [--visibility-only | --visibility-from BAKE] [--environment-from BAKE]
//   iblkit-bake [SCENE] --environment-only [--env ENV ...] -o OUTDIR
//
// OUTDIR/scene.glb  the whole flattened scene (world-space meshes, ground included, materials with
//                   the scene's overrides applied, camera) with per-vertex visibility attributes
//                   (visibility_attributes.h);
// OUTDIR/env/       with an environment: SH9, irradiance cube, specular chain, DFG table, the
//                   dominant lights (env/lights.json) and the residual's SH9 and specular chain;
// OUTDIR/bake.json  inputs, parameters, per-stage timings, ray and light counts.
// OUTDIR appears only when everything is written (output_directory.h).
// --visibility-only bakes the visibility alone (no environment stages, no suns' bounce);
// --visibility-from BAKE takes it from BAKE, a bake of the same scene with the same visibility
// options, instead of tracing it again (baker/reused_visibility.h): a scene under several maps.
// --environment-only bakes the environment stages alone (env/ and bake.json, no scene.glb; the
// scene, when given, only names the map, rotation and intensity); --environment-from BAKE copies
// them from BAKE, a bake of the same map bytes with the same environment options, instead of
// computing them again (baker/reused_environment.h): one map under several scenes.

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>

#include "bakefile/bake_layout.h"
#include "bakefile/bake_record.h"
#include "bakefile/scene_glb.h"
#include "baker/environment_stages.h"
#include "baker/irradiance_cube.h"
#include "baker/reused_environment.h"
#include "baker/reused_visibility.h"
#include "baker/vertex_visibility.h"
#include "baker/visibility_attributes.h"
#include "cli/program.h"
#include "core/environment_lights.h"
#include "core/environment_map_file.h"
#include "core/error.h"
#include "core/output_directory.h"
#include "core/scene.h"
#include "core/scene_environment.h"
#include "core/stopwatch.h"
#include "core/usage_error.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kProgram = "iblkit-bake";

struct Options {
  fs::path scene, output;
  EnvironmentOverride environment;  // its format is parsed from envFormat
  int aoRays = 256;
  float aoDistance = 0.0f;
  float aoFalloff = 0.0f;
  bool aoArea = false;
  int bounces = 0;
  std::uint32_t seed = 0;
  int threads = 0;  // 0: every core
  std::string envFormat = "latlong";
  std::string shWindow = "auto";  // "auto", "none" or a cutoff in bands
  std::uint32_t specularSamples = 1024;
  std::string specularSize = "auto";  // "auto" or a power of two
  int lutSize = 128;
  std::string sunThreshold = "auto";  // "auto" or a luminance
  int maxSuns = SunExtractionOptions{}.maxLights;
  int medianCutLevels = kDefaultMedianCutLevels;
  bool force = false;
  bool visibilityOnly = false;
  fs::path visibilityFrom;
  bool environmentOnly = false;
  fs::path environmentFrom;
};

// bake.json's parameters (bake_record.h), the visibility's under kVisibilityParameters' names.
json bakeParameters(const Options& options) {
  return {{"ao_rays", options.aoRays},
          {"ao_distance", options.aoDistance},
          {"ao_falloff", options.aoFalloff},
          {"ao_area", options.aoArea},
          {"bounces", options.bounces},
          {"seed", options.seed},
          {"sh_window", options.shWindow},
          {"specular_samples", options.specularSamples},
          {"specular_size", options.specularSize},
          {"lut_size", options.lutSize},
          {"sun_threshold", options.sunThreshold},
          {"max_suns", options.maxSuns},
          {"median_cut_levels", options.medianCutLevels}};
}

// A one-line progress bar on stderr, redrawn when the whole percentage changes; only when stderr
// is a terminal, so logs and tests see no carriage returns. Called from the worker threads.
std::function<void(std::size_t, std::size_t)> progressBar(const char* stage) {
  if (!isatty(STDERR_FILENO)) return {};
  struct State {
    std::mutex mutex;
    int shown = -1;
  };
  auto state = std::make_shared<State>();
  return [state, stage](std::size_t done, std::size_t total) {
    const int percent = total ? int(100 * done / total) : 100;
    const std::lock_guard lock(state->mutex);
    if (percent <= state->shown) return;
    state->shown = percent;
    constexpr int kWidth = 40;
    const int filled = percent * kWidth / 100;
    std::fprintf(stderr, "\r%s: %s [%s%s] %3d%%%s", kProgram, stage, std::string(filled, '#').c_str(),
                 std::string(kWidth - filled, ' ').c_str(), percent, percent == 100 ? "\n" : "");
  };
}

// The sinc^4 window cutoff for SH9: automatic (unset: the largest cutoff keeping irradiance >= 0),
// none (0), or a number of bands.
std::optional<float> shWindowCutoff(const std::string& choice) {
  if (choice == "auto") return std::nullopt;
  if (choice == "none") return 0.0f;
  try {
    std::size_t used = 0;
    const float cutoff = std::stof(choice, &used);
    if (used == choice.size() && cutoff > 0.0f) return cutoff;
  } catch (const std::exception&) {
  }
  failUsage("--sh-window", "expected auto, none or a positive number of bands, got '" + choice + "'");
}

// The sun extraction threshold: automatic (0, automaticSunThreshold) or a positive luminance.
float sunThreshold(const std::string& choice) {
  if (choice == "auto") return 0.0f;
  try {
    std::size_t used = 0;
    const float threshold = std::stof(choice, &used);
    if (used == choice.size() && std::isfinite(threshold) && threshold > 0.0f) return threshold;
  } catch (const std::exception&) {
  }
  failUsage("--sun-threshold", "expected auto or a positive luminance, got '" + choice + "'");
}

// The specular chains' face size of level 0: automatic (0: defaultSpecularBaseSize of the map's
// width, at most kMaxDefaultSpecularBaseSize) or a power of two up to kMaxSpecularSize. 4096 bakes
// the bundled diffuse sphere in 126 s at an 8.9 GB peak, two 1.3 GB chains; an 8192 base (6.4 GB
// for one RGBA float level 0 before its copies) was killed for memory on a 24 GB machine.
constexpr int kMaxSpecularSize = 4096;
int specularBaseSize(const std::string& choice) {
  if (choice == "auto") return 0;
  try {
    std::size_t used = 0;
    const int size = std::stoi(choice, &used);
    if (used == choice.size() && size >= 1 && size <= kMaxSpecularSize && std::has_single_bit(unsigned(size)))
      return size;
  } catch (const std::exception&) {
  }
  failUsage("--specular-size", "expected auto or a power of two from 1 to " + std::to_string(kMaxSpecularSize) +
                                   ", got '" + choice + "'");
}

// The environment stages (baker/environment_stages.h), their seconds added to `timings`. Computed
// before the output's temporary folder exists, so that an interrupt during the long stages finds
// nothing to clean up, and the folder lives only while files are written into it.
EnvironmentStages bakeEnvironment(EnvironmentMap&& environment, const Options& options,
                                  std::optional<float> windowCutoff, json& timings) {
  EnvironmentStageOptions stageOptions;
  stageOptions.shWindowCutoff = windowCutoff;
  stageOptions.specularSamples = options.specularSamples;
  stageOptions.specularBaseSize = specularBaseSize(options.specularSize);
  stageOptions.copyLatLong = false;  // the viewer reads the map itself
  stageOptions.lutSize = options.lutSize;
  stageOptions.lights = true;
  stageOptions.suns.threshold = sunThreshold(options.sunThreshold);
  stageOptions.suns.maxLights = options.maxSuns;
  stageOptions.medianCutLevels = options.medianCutLevels;
  EnvironmentStageTimes times;
  EnvironmentStages stages =
      computeEnvironmentStages(std::move(environment), stageOptions, progressBar("environment"), &times);
  timings["sh9_s"] = times.sh9;
  timings["irradiance_s"] = times.irradiance;
  timings["specular_s"] = times.specular;
  timings["brdf_lut_s"] = times.brdfLut;
  timings["lights_s"] = times.lights;
  timings["residual_sh9_s"] = times.residualSh9;
  timings["residual_specular_s"] = times.residualSpecular;
  return stages;
}

// bake.json's "environment" section.
json environmentRecord(const EnvironmentStages& stages, const Options& options) {
  const IrradianceError shError = shIrradianceError(stages.irradiance, stages.sh9);
  return {{"sh_window_cutoff", stages.shWindowCutoff},
          {"irradiance_cube_size", stages.irradiance.size},
          {"sh9_irradiance_error",
           {{"mean_relative", shError.meanRelative}, {"max_relative", shError.maxRelative}}},
          {"specular_face_size", stages.specular.levels.front().size},
          {"specular_roughness_per_level", stages.specular.roughness},
          {"brdf_lut_size", options.lutSize},
          {"lights",
           {{"sun_threshold", stages.lights.sunThreshold},
            {"suns", stages.lights.suns.size()},
            {"median_cut_levels", stages.lights.medianCutLevels},
            {"median_cut", stages.lights.medianCut.size()}}}};
}

int bake(const Options& options) {
  // Checked before any work.
  const std::optional<float> windowCutoff = shWindowCutoff(options.shWindow);
  sunThreshold(options.sunThreshold);
  specularBaseSize(options.specularSize);
  checkEnvironmentOverride(options.environment);
  const bool sceneGiven = !options.scene.empty();
  if (!sceneGiven && !options.environmentOnly)
    failUsage("scene", "required (only --environment-only bakes without a scene, the map from --env)");
  if (!sceneGiven && options.environment.file.empty())
    failUsage("--env", "required by --environment-only without a scene");
  Stopwatch stopwatch;
  json timings;
  Scene scene;
  if (sceneGiven) {
    scene = loadScene(options.scene);
    timings["load_s"] = stopwatch.lap();
  } else {
    scene.file = options.environment.file;  // what a message about the map's settings names
  }

  const EnvironmentSettings environment = overriddenEnvironment(scene.environment, options.environment);
  // -o replaces the folder: it must not be or hold an input, and an existing folder must be a
  // bake (or empty) unless --force.
  checkOutputs(sceneGiven ? sceneInputs(scene, options.environment) : std::vector<fs::path>{environment.file}, {},
               {OutputFolder(options.output, {"iblkit bake folder", {kBakeRecordFile}})}, options.force);
  if ((options.environmentOnly || !options.environmentFrom.empty()) && environment.file.empty())
    fail(scene.file, std::string("the scene names no environment map (") +
                         (options.environmentOnly ? "--environment-only" : "--environment-from") +
                         " needs one; give --env FILE)");
  const bool withEnvironment = !environment.file.empty() && !options.visibilityOnly;
  const BakeInputs inputs{.scene = sceneGiven ? fs::absolute(options.scene).lexically_normal() : fs::path(),
                          .environment = withEnvironment ? fs::absolute(environment.file).lexically_normal() : fs::path(),
                          .environmentFormat = options.envFormat,
                          .environmentRotationDegrees = environment.rotationDegrees,
                          .environmentIntensity = environment.intensity};
  // bake.json, its parameters (the environment's env_format, rotation and intensity included) what
  // --visibility-from and --environment-from compare; the rest is added as the stages finish.
  json record = makeBakeRecord(inputs, bakeParameters(options));
  const json& parameters = record["parameters"];
  // Loaded before the long visibility stage, so a bad map fails fast; or, with --environment-from,
  // the stages of another bake of the same map bytes (checked before any work too).
  std::optional<EnvironmentMap> environmentMap;
  std::optional<ReusedEnvironment> reusedEnvironment;
  std::string environmentHash;
  if (withEnvironment) {
    if (options.environmentFrom.empty()) {
      environmentMap = loadEnvironment(environment, parseProbeFormat(options.envFormat));
      checkEnvironmentIntensity(*environmentMap, environment, scene, options.environment);
      requireEnvironmentForStages(*environmentMap, environment.file);
    }
    environmentHash = environmentContentHash(environment.file);
    if (!options.environmentFrom.empty())
      reusedEnvironment = reuseEnvironment(options.environmentFrom, parameters, environmentHash);
    timings["load_environment_s"] = stopwatch.lap();
  }

  VisibilitySettings settings;
  settings.rayCount = options.aoRays;
  settings.maxDistance = options.aoDistance;
  settings.seed = options.seed;
  settings.falloff = options.aoFalloff;
  settings.areaSampling = options.aoArea;
  settings.bounces = options.bounces;
  // Each mesh's grey albedo, for --bounces, the suns' bounce and bake.json (it averages textures).
  const std::vector<float> albedos = meshDiffuseAlbedos(scene);
  if (options.bounces > 0) settings.albedo = albedos;
  useSceneMaterials(settings, scene);  // AO rays pass through masked texels
  settings.progress = progressBar("visibility");
  VisibilityStatistics statistics;
  std::string sceneHash;
  double visibilitySeconds = 0.0;
  if (!options.environmentOnly) {
    sceneHash = sceneContentHash(scene);
    if (!options.visibilityFrom.empty()) {
      reuseVisibility(options.visibilityFrom, parameters, sceneHash, scene);
      for (const Mesh& mesh : scene.meshes) statistics.vertices += mesh.vertexCount();
    } else {
      attachVisibilityAttributes(scene.meshes, bakeVertexVisibility(scene.meshes, settings, &statistics));
    }
    visibilitySeconds = stopwatch.lap();
    timings["visibility_s"] = visibilitySeconds;
    timings["visibility_build_s"] = statistics.buildSeconds;
    timings["visibility_rays_s"] = statistics.raySeconds;
    timings["bounces_s"] = statistics.bounceSeconds;
  }

  std::size_t triangles = 0;
  for (const Mesh& mesh : scene.meshes) triangles += mesh.triangleCount();
  std::optional<EnvironmentStages> stages;
  if (environmentMap) {
    // The stages make the residual out of the map itself: nothing reads it after them.
    stages = bakeEnvironment(std::move(*environmentMap), options, windowCutoff, timings);
    stopwatch.lap();  // the stages timed themselves
  }
  // The suns' bounce for the engine's lights modes, with the visibility's rays, from the lights
  // computed here or read back from --environment-from's bake.
  const EnvironmentLights* lights =
      stages ? &stages->lights : (reusedEnvironment ? &reusedEnvironment->lights : nullptr);
  VisibilityStatistics sunBounceStatistics;
  if (!options.environmentOnly && lights && !lights->suns.empty()) {
    VisibilitySettings sunBounce = settings;
    sunBounce.albedo = albedos;
    attachSunBounce(scene.meshes, *lights, std::move(sunBounce), &sunBounceStatistics);
    timings["sun_bounce_s"] = stopwatch.lap();
  }
  writeDirectoryAtomically(options.output, [&](const fs::path& folder) {
    json outputs = json::array();
    if (!options.environmentOnly) {
      writeSceneGlb(scene, folder / kBakeSceneFile);
      timings["write_scene_s"] = stopwatch.lap();
      outputs.push_back(kBakeSceneFile);
    }
    outputs.push_back(kBakeRecordFile);
    json environmentReport = nullptr;
    if (stages) {
      writeEnvironmentStages(folder, *stages);
      timings["write_environment_s"] = stopwatch.lap();
      environmentReport = environmentRecord(*stages, options);
      for (const char* file : kBakeEnvironmentFiles) outputs.push_back(file);
    } else if (reusedEnvironment) {
      copyReusedEnvironment(*reusedEnvironment, folder);
      timings["write_environment_s"] = stopwatch.lap();
      environmentReport = reusedEnvironment->record;
      for (const char* file : reusedEnvironment->files) outputs.push_back(file);
    }
    // Where the visibility and the environment stages came from (the visibility's rays, counted
    // below, are that bake's).
    if (!options.visibilityFrom.empty())
      record["visibility_from"] = fs::absolute(options.visibilityFrom).lexically_normal().string();
    if (!options.environmentFrom.empty())
      record["environment_from"] = fs::absolute(options.environmentFrom).lexically_normal().string();
    record["environment"] = environmentReport;
    // What --visibility-from and --environment-from check (baker/reused_visibility.h,
    // baker/reused_environment.h).
    if (!sceneHash.empty()) record["scene_hash"] = sceneHash;
    if (!environmentHash.empty()) record["environment_hash"] = environmentHash;
    record["outputs"] = outputs;
    record["timings"] = timings;
    record["counts"] = {{"meshes", scene.meshes.size()},
                        {"vertices", statistics.vertices},
                        {"triangles", triangles},
                        {"rays", statistics.rays},
                        {"bounce_rays", statistics.bounceRays},
                        {"sun_bounce_rays", sunBounceStatistics.bounceRays},
                        {"rejected_directions", statistics.rejected}};
    // The grey albedo per mesh (meshDiffuseAlbedo) that the suns' bounce (and --bounces) reflect with.
    record["mesh_albedos"] = albedos;
    record["rays_per_second"] = visibilitySeconds > 0.0 ? double(statistics.rays) / visibilitySeconds : 0.0;
    record["trace_rays_per_second"] =
        statistics.raySeconds > 0.0 ? double(statistics.rays) / statistics.raySeconds : 0.0;
    writeBakeRecord(folder / kBakeRecordFile, record);
  });
  if (options.environmentOnly)
    std::cout << kProgram << ": wrote " << options.output.string() << " (the environment stages of "
              << environment.file.string() << ")\n";
  else
    std::cout << kProgram << ": wrote " << options.output.string() << " (" << statistics.vertices << " vertices, "
              << statistics.rays << " rays in " << visibilitySeconds << " s)\n";
  return 0;
}

}  // namespace
}  // namespace iblkit

int main(int argc, char** argv) {
  iblkit::Options options;
  CLI::App app{"Bakes per-vertex ambient occlusion, bent normals and SH transfer for a scene.",
               iblkit::kProgram};
  app.add_option("scene", options.scene,
                 "scene: .json description, .gltf or .glb (required unless --environment-only)");
  iblkit::addEnvironmentOptions(app, options.environment);
  app.add_option("-o,--output", options.output,
                 "output folder, replaced only after success (an existing one must be a bake, or --force)")
      ->required();
  iblkit::addForceOption(app, options.force);
  app.add_option("--ao-rays", options.aoRays, "visibility rays per vertex")
      ->check(CLI::Range(1, 1 << 24))
      ->capture_default_str();
  app.add_option("--ao-distance", options.aoDistance,
                 "occluders beyond this distance are ignored; 0 = infinite")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--ao-falloff", options.aoFalloff,
                 "occlusion falloff exponent p: a hit at distance t occludes by (1 - t / D)^p; 0 = off "
                 "(needs --ao-distance D)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_flag("--ao-area", options.aoArea,
               "sample ray origins over each vertex's one-ring (large triangles)");
  app.add_option("--bounces", options.bounces, "interreflection bounces added to the SH transfer")
      ->check(CLI::Range(0, iblkit::kMaxTransferBounces))
      ->capture_default_str();
  app.add_option("--seed", options.seed, "sample scrambling seed")->capture_default_str();
  app.add_option("--env-format", options.envFormat, "environment layout")
      ->check(iblkit::nameChoice(iblkit::kProbeFormatNames, "environment format"))
      ->capture_default_str();
  app.add_option("--sh-window", options.shWindow, "SH9 ringing window: auto, none or a cutoff in bands")
      ->capture_default_str();
  app.add_option("--specular-samples", options.specularSamples,
                 "GGX samples per texel for the roughest level")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  app.add_option("--specular-size", options.specularSize,
                 "face size of the specular chains' sharpest level: auto (map width / 4 as a power of two, "
                 "at most 1024) or a power of two up to 4096")
      ->capture_default_str();
  app.add_option("--lut-size", options.lutSize, "DFG table size")
      ->check(CLI::Range(8, 1024))
      ->capture_default_str();
  app.add_option("--sun-threshold", options.sunThreshold,
                 "luminance above which the map's texels become sun lights (docs/dominant-lights.md): "
                 "auto or a positive number")
      ->capture_default_str();
  app.add_option("--max-suns", options.maxSuns, "the most sun lights extracted from the map")
      ->check(CLI::Range(0, 64))
      ->capture_default_str();
  app.add_option("--median-cut-levels", options.medianCutLevels,
                 "median-cut lights: 2^N regions of equal energy")
      ->check(CLI::Range(0, 12))
      ->capture_default_str();
  app.add_flag("--visibility-only", options.visibilityOnly,
               "bake the per-vertex visibility alone: no environment stages, no suns' bounce (a bake for "
               "--visibility-from)");
  app.add_option("--visibility-from", options.visibilityFrom,
                 "take the per-vertex visibility from this bake folder, a bake of the same scene with the same "
                 "--ao-*, --bounces and --seed, instead of tracing it again")
      ->excludes("--visibility-only");
  auto* environmentOnly = app.add_flag(
      "--environment-only", options.environmentOnly,
      "bake the environment stages alone: env/ and bake.json, no scene.glb (a bake for --environment-from); "
      "the scene is optional, --env names the map without one");
  environmentOnly->excludes("--visibility-only")->excludes("--visibility-from");
  app.add_option("--environment-from", options.environmentFrom,
                 "copy the environment stages from this bake folder, a bake of the same map file with the same "
                 "--env-*, --sh-window, --specular-*, --lut-size and light options, instead of computing them again")
      ->excludes(environmentOnly)
      ->excludes("--visibility-only");
  app.add_option("--threads", options.threads, "worker threads; 0 = every core")
      ->check(CLI::Range(0, iblkit::kMaxThreads))
      ->capture_default_str();
  return iblkit::runProgram(app, argc, argv, [&] {
    const iblkit::ThreadLimit threads(options.threads);
    return iblkit::bake(options);
  });
}
