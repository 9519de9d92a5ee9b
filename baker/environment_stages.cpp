#include "baker/environment_stages.h"

#include <bit>
#include <string>

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

EnvironmentStages computeEnvironmentStages(const EnvironmentMap& environment, const EnvironmentStageOptions& options,
                                           const std::function<void(std::size_t, std::size_t)>& progress,
                                           EnvironmentStageTimes* times) {
  constexpr std::size_t kStages = 4;
  auto step = [&](std::size_t done) {
    if (progress) progress(done, kStages);
  };
  EnvironmentStageTimes measured;
  Stopwatch stopwatch;
  EnvironmentStages stages;
  stages.latLong = environment.image();
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
  stages.specular = prefilterSpecular(environment, specular);
  measured.specular = stopwatch.lap();
  step(3);
  stages.brdfLut = computeBrdfLut(options.lutSize, options.lutSamples);
  measured.brdfLut = stopwatch.lap();
  step(4);
  if (times) *times = measured;
  return stages;
}

}  // namespace iblkit
