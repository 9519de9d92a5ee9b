#pragma once
// The environment a program lights a scene with: the scene's map, rotation and intensity
// (core/scene.h), each replaceable from the command line (--env, --env-rotation,
// --env-intensity). One function for every program, so that an override means the same in each:
// the rotation is absolute, about +Y in degrees, replacing the scene's (docs/conventions.md).

#include <filesystem>
#include <optional>

#include "core/environment_map.h"
#include "core/environment_map_file.h"
#include "core/scene.h"

namespace iblkit {

struct EnvironmentOverride {
  std::filesystem::path file;            // empty: the scene's map
  std::optional<float> rotationDegrees;  // unset: the scene's
  std::optional<float> intensity;        // unset: the scene's
  ProbeFormat format = ProbeFormat::LatLong;
};

// Throws UsageError("--env-rotation: must be finite") or ("--env-intensity: must be finite and
// >= 0") for an override no map can take; for programs, before any file is read.
void checkEnvironmentOverride(const EnvironmentOverride& override);

// The scene's settings with the override's in their place; the file stays empty when neither
// names a map (a bare glTF scene without --env).
EnvironmentSettings overriddenEnvironment(const EnvironmentSettings& scene,
                                          const EnvironmentOverride& override);

// Loads `settings.file` as `format` and sets its rotation and intensity.
EnvironmentMap loadEnvironment(const EnvironmentSettings& settings,
                               ProbeFormat format = ProbeFormat::LatLong);

// Throws unless settings.intensity x the brightest texel of `map` x its texel count stays within
// float (1e36), so that no sum over the map overflows: a UsageError naming --env-intensity when
// `override` sets the intensity, else Error("<scene file>: environment.intensity: ...").
void checkEnvironmentIntensity(const EnvironmentMap& map, const EnvironmentSettings& settings, const Scene& scene,
                               const EnvironmentOverride& override);

// The map lighting `scene`: loadEnvironment(overriddenEnvironment(...)), checked with
// checkEnvironmentIntensity. When neither the scene
// nor the override names a map, throws Error("<scene file>: the scene names no environment map
// (give --env FILE)").
EnvironmentMap loadSceneEnvironment(const Scene& scene, const EnvironmentOverride& override = {});

// The lat-long map `file` in place of the scene's, with the scene's rotation and intensity.
EnvironmentMap loadSceneEnvironment(const Scene& scene, const std::filesystem::path& file);

}  // namespace iblkit
