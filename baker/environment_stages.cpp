#include "baker/environment_stages.h"

#include <bit>
#include <string>
#include <utility>

#include "baker/brdf_lut.h"
#include "baker/irradiance_cube.h"
#include "baker/specular_prefilter.h"
#include "core/environment_sh.h"
#include "core/error.h"
#include "core/stopwatch.h"

namespace iblkit {

void requireEnvironmentForStages(const EnvironmentMap& environment, const std::filesystem::path& file) {
  const int width = environment.width();
  if (width < 8)
    fail(file, "lat-long map is " + std::to_string(width) + "x" + std::to_string(environment.height()) +
                   "; prefiltering needs a width of at least 8");
}

namespace {

// computeEnvironmentStages of `environment`; `owned`, when given, is the same map, which the
// lights' stage turns into the residual in place once nothing reads the map any more.
EnvironmentStages stagesOf(const EnvironmentMap& environment, EnvironmentMap* owned,
                           const EnvironmentStageOptions& options,
                           const std::function<void(std::size_t, std::size_t)>& progress,
                           EnvironmentStageTimes* times) {
  const std::size_t stageCount = options.lights ? 6 : 4;
  auto step = [&](std::size_t done) {
    if (progress) progress(done, stageCount);
  };
  EnvironmentStageTimes measured;
  Stopwatch stopwatch;
  EnvironmentStages stages;
  if (options.copyLatLong) stages.latLong = environment.image();
  stages.rotationDegrees = environment.rotationDegrees();
  stages.intensity = environment.intensity();
  step(0);
  const SphericalHarmonics9 projection = projectEnvironmentSh9(environment);
  stages.shWindowCutoff =
      options.shWindowCutoff ? *options.shWindowCutoff : automaticShWindowCutoff(projection);
  stages.sh9 = windowSh9(projection, stages.shWindowCutoff);
  measured.sh9 = stopwatch.lap();
  step(1);
  if (options.irradianceCubeSize > 0) stages.irradiance = irradianceCube(environment, options.irradianceCubeSize);
  measured.irradiance = stopwatch.lap();
  step(2);
  SpecularPrefilterOptions specular;
  specular.sampleCount = options.specularSamples;
  specular.baseSize = options.specularBaseSize;
  stages.specular = prefilterSpecular(environment, specular);
  measured.specular = stopwatch.lap();
  step(3);
  stages.brdfLut = computeBrdfLut(options.lutSize, options.lutSamples);
  measured.brdfLut = stopwatch.lap();
  step(4);
  if (options.lights) {
    SunExtractionOptions suns = options.suns;
    suns.residualImage = owned == nullptr;
    ExtractedSuns extracted = extractSuns(environment, suns);
    stages.lights.suns = std::move(extracted.suns);
    stages.lights.sunThreshold = extracted.threshold;
    stages.lights.medianCut = medianCutLights(environment, options.medianCutLevels);
    stages.lights.medianCutLevels = options.medianCutLevels;
    // The residual in the map's own frame, as the map: the same rotation and intensity. From here
    // on only the residual is read.
    const float rotationDegrees = environment.rotationDegrees(), intensity = environment.intensity();
    Image residualImage = owned ? std::move(*owned).releaseImage() : std::move(extracted.residual);
    if (owned)
      for (const auto& [texel, value] : extracted.residualTexels) residualImage.pixels()[texel] = value;
    EnvironmentMap residual = EnvironmentMap::fromImage(std::move(residualImage), "residual");
    residual.setRotationDegrees(rotationDegrees);
    residual.setIntensity(intensity);
    measured.lights = stopwatch.lap();
    step(5);
    // The same window as sh9: windowing is linear, so residualSh9 plus the suns' windowed sh9 is sh9.
    stages.residualSh9 = windowSh9(projectEnvironmentSh9(residual), stages.shWindowCutoff);
    measured.residualSh9 = stopwatch.lap();
    stages.residualSpecular = prefilterSpecular(residual, specular);
    if (options.irradianceCubeSize > 0) stages.residualIrradiance = irradianceCube(residual, options.irradianceCubeSize);
    measured.residualSpecular = stopwatch.lap();
    step(6);
  }
  if (times) *times = measured;
  return stages;
}

}  // namespace

EnvironmentStages computeEnvironmentStages(const EnvironmentMap& environment, const EnvironmentStageOptions& options,
                                           const std::function<void(std::size_t, std::size_t)>& progress,
                                           EnvironmentStageTimes* times) {
  return stagesOf(environment, nullptr, options, progress, times);
}

EnvironmentStages computeEnvironmentStages(EnvironmentMap&& environment, const EnvironmentStageOptions& options,
                                           const std::function<void(std::size_t, std::size_t)>& progress,
                                           EnvironmentStageTimes* times) {
  return stagesOf(environment, &environment, options, progress, times);
}

}  // namespace iblkit
