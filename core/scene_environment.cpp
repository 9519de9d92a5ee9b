#include "core/scene_environment.h"

#include <cmath>

#include "core/error.h"
#include "core/usage_error.h"

namespace iblkit {

void checkEnvironmentOverride(const EnvironmentOverride& override) {
  if (override.rotationDegrees && !std::isfinite(*override.rotationDegrees))
    failUsage("--env-rotation", "must be finite");
  if (override.intensity && (!std::isfinite(*override.intensity) || *override.intensity < 0.0f))
    failUsage("--env-intensity", "must be finite and >= 0");
}

EnvironmentSettings overriddenEnvironment(const EnvironmentSettings& scene,
                                          const EnvironmentOverride& override) {
  return {.file = override.file.empty() ? scene.file : override.file,
          .rotationDegrees = override.rotationDegrees.value_or(scene.rotationDegrees),
          .intensity = override.intensity.value_or(scene.intensity)};
}

EnvironmentMap loadEnvironment(const EnvironmentSettings& settings, ProbeFormat format) {
  EnvironmentMap map = loadEnvironmentMap(settings.file, format);
  map.setRotationDegrees(settings.rotationDegrees);
  map.setIntensity(settings.intensity);
  return map;
}

EnvironmentMap loadSceneEnvironment(const Scene& scene, const EnvironmentOverride& override) {
  const EnvironmentSettings settings = overriddenEnvironment(scene.environment, override);
  if (settings.file.empty()) fail(scene.file, "the scene names no environment map (give --env FILE)");
  return loadEnvironment(settings, override.format);
}

EnvironmentMap loadSceneEnvironment(const Scene& scene, const std::filesystem::path& file) {
  EnvironmentOverride override;
  override.file = file;
  return loadSceneEnvironment(scene, override);
}

}  // namespace iblkit
