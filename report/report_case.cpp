#include "report/report_case.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "bakefile/bake_layout.h"
#include "bakefile/sh9_json.h"
#include "core/error.h"
#include "core/image_io.h"
#include "core/scene.h"
#include "core/scene_environment.h"
#include "report/content_hash.h"
#include "report/program_runner.h"
#include "report/sh9_truncation.h"
#include "score/heat_map.h"
#include "score/image_metrics.h"

namespace iblkit {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A finished stage: its folder, how long it took when it ran and its command line.
struct StageRun {
  fs::path folder;
  double seconds = 0.0;
  std::string command;
};

// Runs `argv` (which writes into the folder given to `arguments`) as a cached stage and records
// its wall time and command in the stage's stage.json, so cached runs report the original time.
template <typename Arguments>
StageRun cachedRun(const StageCache& cache, const std::string& name, const std::string& key, Arguments arguments) {
  StageRun run;
  run.folder = cache.stage(name, key, [&](const fs::path& folder) {
    const std::vector<std::string> argv = arguments(folder);
    const auto start = std::chrono::steady_clock::now();
    runProgram(argv, folder / "log.txt");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::ofstream(folder / "stage.json") << json{{"seconds", seconds}, {"command", commandLine(argv)}}.dump(2);
  });
  std::ifstream stream(run.folder / "stage.json");
  const json record = json::parse(stream, nullptr, false);
  if (record.is_discarded() || !record.contains("seconds")) fail(run.folder / "stage.json", "unreadable stage record");
  run.seconds = record["seconds"].get<double>();
  run.command = record["command"].get<std::string>();
  return run;
}

// What a scene's images depend on: the scene file, every model file it names and the environment.
ContentHash sceneInputsHash(const fs::path& sceneFile, const fs::path& environmentFile) {
  ContentHash hash;
  hash.addFile(sceneFile);
  for (const fs::path& model : loadScene(sceneFile).modelFiles) {
    std::error_code error;
    if (fs::is_regular_file(model, error)) hash.addFile(model);
  }
  hash.addFile(environmentFile);
  return hash;
}

Image meanOf(const std::vector<Image>& images) {
  Image mean(images.front().width(), images.front().height());
  for (const Image& image : images)
    for (std::size_t i = 0; i < mean.pixelCount(); ++i) mean.pixels()[i] += image.pixels()[i];
  for (glm::vec4& pixel : mean.pixels()) pixel /= float(images.size());
  return mean;
}

// Exposure (stops) that brings the median luminance of the scored reference pixels to 0.18.
float thumbnailExposure(const Image& reference, std::span<const std::uint8_t> mask) {
  std::vector<float> values;
  for (std::size_t i = 0; i < reference.pixelCount(); ++i)
    if (mask[i]) values.push_back(luminance(glm::vec3(reference.pixels()[i])));
  if (values.empty()) return 0.0f;
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
  const float median = values[values.size() / 2];
  return median > 0.0f ? std::clamp(std::log2(0.18f / median), -16.0f, 16.0f) : 0.0f;
}

// The median frame time iblkit-view --bench prints for the one mode ("  sh   cpu 12.34 ms  gpu 0.00 ms"):
// the CPU time, synchronised with glFinish, since GPU timer queries are not everywhere.
double parseMedianMilliseconds(const std::string& output) {
  static const std::regex pattern(R"(\bcpu\s+([0-9]+(\.[0-9]+)?)\s*ms)");
  std::smatch match;
  if (!std::regex_search(output, match, pattern)) return std::numeric_limits<double>::quiet_NaN();
  return std::stod(match[1].str());
}

}  // namespace

CaseResult runCase(const ReportSettings& settings, const StageCache& cache, const fs::path& sceneFile,
                   const fs::path& environmentFile) {
  CaseResult result;
  result.scene = sceneFile.stem().string();
  result.environment = environmentFile.stem().string();
  result.sceneFile = sceneFile;
  result.environmentFile = environmentFile;
  const std::string caseName = result.scene + "-" + result.environment;
  const std::string size[] = {"--width", std::to_string(settings.width), "--height", std::to_string(settings.height)};
  const ContentHash inputs = sceneInputsHash(sceneFile, environmentFile);
  const fs::path bake = settings.binDir / "iblkit-bake", trace = settings.binDir / "iblkit-trace",
                 view = settings.binDir / "iblkit-view";

  // Bake: per-vertex visibility and the environment's prefiltered stages.
  const StageRun baked = cachedRun(cache, "bake-" + caseName, ContentHash(inputs).addFile(bake).hex(),
                                   [&](const fs::path& folder) -> std::vector<std::string> {
                                     return {bake.string(), sceneFile.string(), "--env", environmentFile.string(),
                                             "-o", (folder / "bake").string()};
                                   });
  result.bakeSeconds = baked.seconds;
  result.commands.push_back(baked.command);

  // Engine frames, one per mode, and their frame times.
  std::vector<Image> frames;
  for (const std::string& mode : settings.modes) {
    ModeResult modeResult;
    modeResult.mode = mode;
    try {
      ContentHash key = ContentHash().add(baked.folder.string()).addFile(view).add(mode);
      for (const std::string& argument : size) key.add(argument);
      key.add(std::to_string(settings.benchFrames)).add(std::to_string(settings.engineSamples));
      key.add(std::to_string(settings.engineSupersample));
      const StageRun rendered = cachedRun(cache, "view-" + caseName + "-" + mode, key.hex(),
                                          [&](const fs::path& folder) {
                                            std::vector<std::string> argv = {
                                                view.string(), (baked.folder / "bake").string(), "--headless",
                                                "-o", (folder / "frame.exr").string(), "--mode", mode};
                                            argv.insert(argv.end(), std::begin(size), std::end(size));
                                            if (settings.engineSamples > 1) {
                                              argv.insert(argv.end(), {"--samples",
                                                                       std::to_string(settings.engineSamples),
                                                                       "--sample-shading"});
                                            }
                                            if (settings.engineSupersample > 1) {
                                              argv.insert(argv.end(), {"--supersample",
                                                                       std::to_string(settings.engineSupersample)});
                                            }
                                            if (settings.benchFrames > 0) {
                                              argv.push_back("--bench");
                                              argv.push_back(std::to_string(settings.benchFrames));
                                            }
                                            return argv;
                                          });
      result.commands.push_back(rendered.command);
      std::ifstream log(rendered.folder / "log.txt");
      modeResult.frameMilliseconds =
          parseMedianMilliseconds(std::string(std::istreambuf_iterator<char>(log), std::istreambuf_iterator<char>()));
      frames.push_back(readExr(rendered.folder / "frame.exr", nullptr, 0, PixelRepair::Keep));
    } catch (const Error& e) {
      modeResult.failure = e.what();
      frames.emplace_back();
    }
    result.modes.push_back(modeResult);
  }

  // Reference passes with seeds 0, 1, 2, ...: even seeds make half A, odd seeds half B.
  std::vector<Image> passes;
  std::vector<std::uint8_t> mask;
  Image reference, normals;
  for (int count = settings.minPasses;; count = std::min(2 * count, settings.maxPasses)) {
    while (int(passes.size()) < count) {
      const int seed = int(passes.size());
      ContentHash key = ContentHash(inputs).addFile(trace).add(std::to_string(settings.passSpp)).add(std::to_string(seed));
      if (seed == 0) key.add("normal");
      if (settings.referenceIntegrator != "path") key.add(settings.referenceIntegrator);
      for (const std::string& argument : size) key.add(argument);
      const StageRun pass = cachedRun(cache, "trace-" + caseName + "-" + std::to_string(seed), key.hex(),
                                      [&](const fs::path& folder) {
                                        std::vector<std::string> argv = {
                                            trace.string(), sceneFile.string(), "--env", environmentFile.string(),
                                            "-o", (folder / "beauty.exr").string(), "--depth",
                                            (folder / "depth.exr").string(), "--spp", std::to_string(settings.passSpp),
                                            "--seed", std::to_string(seed)};
                                        if (seed == 0) argv.insert(argv.end(), {"--normal", (folder / "normal.exr").string()});
                                        if (settings.referenceIntegrator != "path")
                                          argv.insert(argv.end(), {"--integrator", settings.referenceIntegrator});
                                        argv.insert(argv.end(), std::begin(size), std::end(size));
                                        return argv;
                                      });
      if (seed == 0) {
        result.commands.push_back(pass.command + "   (one pass of " + std::to_string(settings.maxPasses) + " at most)");
        const Image depth = readExr(pass.folder / "depth.exr");
        mask = erodeMask(geometryMask(depth), depth.width(), depth.height());
        normals = readExr(pass.folder / "normal.exr", nullptr, 0, PixelRepair::Keep);  // signed
      }
      result.traceSeconds += pass.seconds;
      passes.push_back(readExr(pass.folder / "beauty.exr", nullptr, 0, PixelRepair::Keep));
    }
    std::vector<Image> halfA, halfB;
    for (std::size_t i = 0; i < passes.size(); ++i) (i % 2 == 0 ? halfA : halfB).push_back(passes[i]);
    const Image a = meanOf(halfA), b = meanOf(halfB);
    reference = averageImages(a, b);
    result.referenceSpp = count * settings.passSpp;
    result.scoredPixels = std::size_t(std::count(mask.begin(), mask.end(), std::uint8_t(1)));
    if (result.scoredPixels == 0) fail(sceneFile, "no pixel of the reference sees geometry");
    result.referenceRelMse = halvesRelMseEstimate(a, b, mask);
    result.flipExposures = automaticExposureRange(reference);
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t m = 0; m < result.modes.size(); ++m) {
      ModeResult& modeResult = result.modes[m];
      if (!modeResult.failure.empty() && frames[m].empty()) continue;
      if (frames[m].width() != reference.width() || frames[m].height() != reference.height()) {
        modeResult.failure = "frame is " + std::to_string(frames[m].width()) + "x" + std::to_string(frames[m].height()) +
                             ", reference is " + std::to_string(reference.width()) + "x" +
                             std::to_string(reference.height());
        continue;
      }
      // Only relMSE decides convergence; the full scores (FLIP is the costly one) come once, below.
      const double relMse = relativeMeanSquaredError(reference, frames[m], mask);
      if (std::isfinite(relMse)) best = std::min(best, relMse);
    }
    result.referenceConverged =
        result.referenceRelMse <= std::max(settings.negligibleRatio * best, settings.negligibleRelMse);
    if (result.referenceConverged || count >= settings.maxPasses) break;
  }

  // Pictures: reference and frames at one exposure, FLIP heat maps.
  const fs::path images = settings.outDir / "images";
  fs::create_directories(images);
  result.exposure = thumbnailExposure(reference, mask);
  const ToneMapping toneMapping{result.exposure, ToneCurve::AcesFitted};
  result.referenceImage = "images/" + caseName + "-reference.png";
  writePng(settings.outDir / result.referenceImage, reference, toneMapping);
  for (std::size_t m = 0; m < result.modes.size(); ++m) {
    ModeResult& modeResult = result.modes[m];
    if (!modeResult.failure.empty()) continue;
    FlipErrorMap flip;
    modeResult.scores = scoreFrame(reference, frames[m], mask, result.flipExposures, &flip);
    if (modeResult.scores.invalidPixels > 0) {
      modeResult.failure = std::to_string(modeResult.scores.invalidPixels) + " NaN or infinite pixel values";
      continue;
    }
    modeResult.image = "images/" + caseName + "-" + modeResult.mode + ".png";
    writePng(settings.outDir / modeResult.image, frames[m], toneMapping);
    modeResult.heatMap = "images/" + caseName + "-" + modeResult.mode + "-flip.png";
    writeHeatMap(settings.outDir / modeResult.heatMap, flip.error, flip.width, flip.height);
  }

  // SH9's own error on these normals, with the SH9 the bake wrote and the scene's map as lit.
  const Scene scene = loadScene(sceneFile);
  EnvironmentMap environment = loadSceneEnvironment(scene, environmentFile);
  const Sh9Truncation truncation =
      sh9Truncation(environment, readSh9Json(baked.folder / "bake" / kBakeSh9File), normals, mask);
  result.sh9Truncation = truncation.meanRelativeError;
  for (std::size_t m = 0; m < result.modes.size(); ++m)
    if (result.modes[m].mode == "sh" && result.modes[m].failure.empty())
      result.shBeyondSh9 = errorBeyondSh9(reference, frames[m], truncation, mask);
  return result;
}

}  // namespace iblkit
