#include "bench/env_sampling_study.h"

#include <cmath>
#include <cstdio>
#include <optional>

#include "core/error.h"
#include "core/image_io.h"
#include "core/usage_error.h"
#include "reference/environment_point_lights.h"
#include "reference/environment_sampler.h"
#include "reference/median_cut_sampler.h"
#include "reference/render_scene.h"
#include "reference/renderer.h"
#include "score/image_metrics.h"

namespace iblkit {

namespace {

constexpr std::uint32_t kReferenceSeed = 0x5eed5eedU;

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

IntegratorSettings integratorSettings(const SamplingStudySettings& settings, EnvSampling sampling) {
  IntegratorSettings out;
  out.envSampling = sampling;
  if (settings.phong) out.phong = PhongLobe{*settings.phong};
  return out;
}

// The cached reference of `name` with these settings, or the one rendered now (and cached).
void readOrRenderReference(const SamplingStudySettings& settings, const Integrator& mis, const Camera& camera,
                           const std::string& name, const StudyLog& log, Image* reference, Image* variance,
                           MapStudy* out) {
  const std::string key = name + "_" + std::to_string(settings.width) + "x" +
                          std::to_string(settings.height) + "_" + std::to_string(settings.referenceSpp) +
                          "spp" + (settings.phong ? "_phong" + format("%g", *settings.phong) : std::string());
  const std::filesystem::path referenceFile = settings.cache / ("reference_" + key + ".exr");
  const std::filesystem::path varianceFile = settings.cache / ("reference_" + key + "_variance.exr");
  if (std::filesystem::exists(referenceFile) && std::filesystem::exists(varianceFile)) {
    *reference = readExr(referenceFile);
    *variance = readExr(varianceFile);
    out->referenceCached = true;
  } else {
    if (log) log(name + ": rendering the reference, " + std::to_string(settings.referenceSpp) + " spp mis");
    RenderSettings referenceSettings;
    referenceSettings.width = settings.width;
    referenceSettings.height = settings.height;
    referenceSettings.threads = settings.threads;
    referenceSettings.samplesPerPixel = settings.referenceSpp;
    referenceSettings.seed = kReferenceSeed;
    RenderResult result = render(mis, camera, referenceSettings);
    out->referenceSeconds = result.seconds;
    *reference = std::move(result.beauty);
    *variance = std::move(result.variance);
    std::filesystem::create_directories(settings.cache);
    writeExr(referenceFile, *reference, {.pixelType = PixelType::Float});
    writeExr(varianceFile, *variance, {.pixelType = PixelType::Float});
  }
  for (const Image* image : {reference, variance})
    if (image->width() != settings.width || image->height() != settings.height)
      fail(referenceFile, "cached reference has the wrong size (delete the cache folder)");
}

}  // namespace

std::size_t studyStrategyIndex(EnvSampling sampling) {
  for (std::size_t s = 0; s < kStudyStrategyCount; ++s)
    if (kStudyStrategies[s].sampling == sampling) return s;
  fail("sampling_study", "strategy not in the study");
}

std::size_t studyStrategyIndex(const std::string& name) {
  for (std::size_t s = 0; s < kStudyStrategyCount; ++s)
    if (kStudyStrategies[s].name == name) return s;
  fail("sampling_study", "no strategy '" + name + "' in the study");
}

void validateSamplingStudySettings(const SamplingStudySettings& settings) {
  requireInRange("--width", settings.width, 1, kMaxImageSide);
  requireInRange("--height", settings.height, 1, kMaxImageSide);
  requireInRange("--max-spp", settings.maxSpp, 1, kMaxSamplesPerPixel);
  requireInRange("--reference-spp", settings.referenceSpp, 1, kMaxSamplesPerPixel);
  if (settings.threads < 0) failUsage("--threads", "must be >= 0, not " + std::to_string(settings.threads));
  if (settings.phong && !(std::isfinite(*settings.phong) && *settings.phong >= 0.0f))
    failUsage("--phong", "exponent must be finite and >= 0");
}

std::vector<int> studySppLevels(int maxSpp) {
  std::vector<int> levels;
  for (int spp = 1; spp <= maxSpp; spp *= 2) {
    levels.push_back(spp);
    if (spp > maxSpp / 2) break;  // the next level would pass maxSpp (or overflow near INT_MAX)
  }
  return levels;
}

double referenceNoiseFloor(const Image& reference, const Image& variance) {
  double sum = 0.0;
  for (std::size_t i = 0; i < reference.pixelCount(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double r = reference.pixels()[i][c];
      sum += variance.pixels()[i][c] / (r * r + kRelMseEpsilon);
    }
  return sum / (3.0 * static_cast<double>(reference.pixelCount()));
}

double relMseRatio(const MapStudy& study, EnvSampling numerator, EnvSampling denominator, std::size_t level) {
  return study.relMse[studyStrategyIndex(numerator)][level] /
         study.relMse[studyStrategyIndex(denominator)][level];
}

MapStudy studyEnvironmentMap(const SamplingStudySettings& settings, const Scene& scene,
                             const EnvironmentMap& environment, const std::string& name,
                             const std::string& label, const StudyLog& log) {
  validateSamplingStudySettings(settings);
  MapStudy out;
  out.name = name;
  out.label = label;
  const EnvironmentSampler sampler(environment);
  const Camera camera = sceneCamera(scene, static_cast<float>(settings.width) / settings.height);
  const RenderScene renderScene(scene);

  Image reference, variance;
  const Integrator mis(renderScene, environment, sampler, integratorSettings(settings, EnvSampling::Mis));
  readOrRenderReference(settings, mis, camera, name, log, &reference, &variance, &out);
  out.referenceFloor = referenceNoiseFloor(reference, variance);

  RenderSettings renderSettings;
  renderSettings.width = settings.width;
  renderSettings.height = settings.height;
  renderSettings.threads = settings.threads;
  const std::vector<int> levels = studySppLevels(settings.maxSpp);
  for (const StudyStrategy& strategy : kStudyStrategies) {
    // The median-cut regions of the strategies that use them.
    std::optional<MedianCutSampler> medianCut;
    std::optional<EnvironmentPointLights> pointLights;
    if (strategy.sampling == EnvSampling::MedianCut)
      medianCut.emplace(environment, medianCutLevelsOf(strategy.lights).value());
    if (strategy.sampling == EnvSampling::Lights)
      pointLights.emplace(environment, medianCutLevelsOf(strategy.lights).value());
    const Integrator integrator(renderScene, environment, sampler,
                                integratorSettings(settings, strategy.sampling),
                                {medianCut ? &*medianCut : nullptr, pointLights ? &*pointLights : nullptr});
    std::vector<double> scores;
    double seconds = 0.0, samples = 0.0;
    for (std::size_t level = 0; level < levels.size(); ++level) {
      renderSettings.samplesPerPixel = levels[level];
      renderSettings.seed = static_cast<std::uint32_t>(level + 1);
      const RenderResult result = render(integrator, camera, renderSettings);
      scores.push_back(relativeMeanSquaredError(reference, result.beauty));
      seconds += result.seconds;
      samples += static_cast<double>(settings.width) * settings.height * levels[level];
    }
    out.relMse.push_back(scores);
    out.microsecondsPerSample.push_back(1e6 * seconds / samples);
    if (log) {
      char line[200];
      std::snprintf(line, sizeof line, "%s %-7s relMSE %.3g at 1 spp, %.3g at %d spp; %.2f us/sample",
                    name.c_str(), strategy.name, scores.front(), scores.back(), levels.back(),
                    out.microsecondsPerSample.back());
      log(line);
    }
  }
  return out;
}

}  // namespace iblkit
