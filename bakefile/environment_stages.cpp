#include "bakefile/environment_stages.h"

#include "bakefile/bake_layout.h"
#include "bakefile/brdf_lut_exr.h"
#include "bakefile/environment_lights_json.h"
#include "bakefile/irradiance_exr.h"
#include "bakefile/sh9_json.h"
#include "core/environment_map_file.h"
#include "core/error.h"

namespace iblkit {

namespace fs = std::filesystem;

void writeEnvironmentStages(const fs::path& folder, const EnvironmentStages& stages) {
  fs::create_directories((folder / kBakeSh9File).parent_path());
  writeSh9Json(folder / kBakeSh9File, stages.sh9, stages.shWindowCutoff);
  if (stages.irradiance.size > 0) writeIrradianceCubeExr(folder / kBakeIrradianceFile, stages.irradiance);
  writeSpecularCubeExr(folder / kBakeSpecularFile, stages.specular);
  writeBrdfLutExr(folder / kBakeBrdfLutFile, stages.brdfLut);
  if (!stages.residualSpecular.levels.empty()) {
    writeEnvironmentLightsJson(folder / kBakeLightsFile, stages.lights);
    writeSh9Json(folder / kBakeResidualSh9File, stages.residualSh9, stages.shWindowCutoff);
    writeSpecularCubeExr(folder / kBakeResidualSpecularFile, stages.residualSpecular);
    if (stages.residualIrradiance.size > 0)
      writeIrradianceCubeExr(folder / kBakeResidualIrradianceFile, stages.residualIrradiance);
  }
}

EnvironmentStages readEnvironmentStages(const fs::path& folder, const BakeInputs& inputs) {
  if (inputs.environment.empty())
    fail(folder / kBakeRecordFile, "the bake has no environment stages (bake with --env)");
  EnvironmentStages env;
  env.rotationDegrees = inputs.environmentRotationDegrees;
  env.intensity = inputs.environmentIntensity;
  env.latLong =
      loadEnvironmentMap(requireBakeFile(inputs.environment),
                         parseProbeFormat(inputs.environmentFormat, (folder / kBakeRecordFile).string()))
          .image();
  env.sh9 = readSh9Json(requireBakeFile(folder / kBakeSh9File), &env.shWindowCutoff);
  env.specular = readSpecularCubeExr(requireBakeFile(folder / kBakeSpecularFile));
  env.brdfLut = readBrdfLutExr(requireBakeFile(folder / kBakeBrdfLutFile));
  // The baker writes the irradiance cube unless its size is 0: without the file the cube is absent
  // (size 0), and only the irradiance modes need it.
  if (fs::exists(folder / kBakeIrradianceFile)) env.irradiance = readIrradianceCubeExr(folder / kBakeIrradianceFile);
  // The lights and the residual come together; a bake without env/lights.json has neither.
  if (std::filesystem::exists(folder / kBakeLightsFile)) {
    env.lights = readEnvironmentLightsJson(requireBakeFile(folder / kBakeLightsFile));
    env.residualSh9 = readSh9Json(requireBakeFile(folder / kBakeResidualSh9File));
    env.residualSpecular = readSpecularCubeExr(requireBakeFile(folder / kBakeResidualSpecularFile));
    if (fs::exists(folder / kBakeResidualIrradianceFile))
      env.residualIrradiance = readIrradianceCubeExr(folder / kBakeResidualIrradianceFile);
  }
  return env;
}

}  // namespace iblkit
