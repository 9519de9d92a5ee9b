#include "core/scene_environment.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.h"
#include "core/usage_error.h"

namespace iblkit {

namespace {
// The largest intensity x brightest texel x texel count: float's maximum with room for the
// solid-angle weights and the sums' rounding.
constexpr double kMaxEnvironmentTotal = 1e36;
}  // namespace

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

void checkEnvironmentIntensity(const EnvironmentMap& map, const EnvironmentSettings& settings, const Scene& scene,
                               const EnvironmentOverride& override) {
  const double total = double(settings.intensity) * double(map.brightestTexel()) * double(map.width()) *
                       double(map.height());
  if (total <= kMaxEnvironmentTotal) return;
  char text[160];
  std::snprintf(text, sizeof(text), "%g times the brightest texel of %s (%g) overflows float radiance",
                double(settings.intensity), settings.file.filename().string().c_str(),
                double(map.brightestTexel()));
  if (override.intensity) failUsage("--env-intensity", text);
  fail(scene.file, std::string("environment.intensity: ") + text);
}

EnvironmentMap loadSceneEnvironment(const Scene& scene, const EnvironmentOverride& override) {
  const EnvironmentSettings settings = overriddenEnvironment(scene.environment, override);
  if (settings.file.empty()) fail(scene.file, "the scene names no environment map (give --env FILE)");
  EnvironmentMap map = loadEnvironment(settings, override.format);
  checkEnvironmentIntensity(map, settings, scene, override);
  return map;
}

EnvironmentMap loadSceneEnvironment(const Scene& scene, const std::filesystem::path& file) {
  EnvironmentOverride override;
  override.file = file;
  return loadSceneEnvironment(scene, override);
}

}  // namespace iblkit
