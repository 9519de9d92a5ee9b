#include "engine/baked/environment_stages.h"

#include "baker/brdf_lut.h"
#include "baker/environment_sh.h"

namespace iblkit {

EnvironmentStages prepareEnvironment(const EnvironmentMap& environment,
                                     const PrepareEnvironmentOptions& options) {
  EnvironmentStages stages;
  stages.latLong = environment.image();
  stages.rotationDegrees = environment.rotationDegrees();
  stages.intensity = environment.intensity();
  const SphericalHarmonics9 sh = projectEnvironmentSh9(environment);
  stages.shWindowCutoff = automaticShWindowCutoff(sh);
  stages.sh9 = windowSh9(sh, stages.shWindowCutoff);
  SpecularPrefilterOptions specular;
  specular.sampleCount = options.specularSamples;
  stages.specular = prefilterSpecular(environment, specular);
  stages.brdfLut = computeBrdfLut(options.lutSize, options.lutSamples);
  return stages;
}

}  // namespace iblkit
