#pragma once
// Everything the engine needs from an environment map, in one place: the lat-long radiance (the
// sky and the `mirror` mode), its SH9 radiance coefficients (diffuse), the GGX-prefiltered
// specular cube chain and the split-sum DFG table (docs/prefilter.md), and the brute-force
// irradiance cube the SH9 irradiance is checked against. baker/environment_stages.h computes
// them; this file writes them into a bake folder's env/ (bake_layout.h) and reads them back.
#include <filesystem>

#include "bakefile/bake_record.h"
#include "bakefile/specular_exr.h"
#include "core/cube_map.h"
#include "core/environment_lights.h"
#include "core/image.h"
#include "core/spherical_harmonics.h"

namespace iblkit {

struct EnvironmentStages {
  // The lat-long map as stored (rotation and intensity not applied), with the scene's rotation
  // (degrees about +Y, environment_map.h) and radiance multiplier. The shaders apply both to every
  // lookup of the map.
  Image latLong;
  float rotationDegrees = 0.0f;
  float intensity = 1.0f;
  // SH9 radiance coefficients L_k (spherical_harmonics.h) with the sinc^4 ringing window of
  // shWindowCutoff applied (0: none), in world space: rotationDegrees and intensity are already in
  // them. What env/sh9.json stores and the engine evaluates.
  SphericalHarmonics9 sh9;
  float shWindowCutoff = 0.0f;
  // The prefiltered chain (level i has perceptual roughness specular.roughness[i]), world space
  // like sh9.
  SpecularCube specular;
  // The DFG table (brdf_lut.h): R = A, G = B, B = E; NoV along x, roughness along y.
  Image brdfLut;
  // Brute-force irradiance per texel, world space like sh9 (size 0: not computed): the engine's
  // `irradiance` modes look it up along the normal.
  CubeMap irradiance;
  // Dominant lights (core/environment_lights.h), world space like sh9; empty when not computed.
  EnvironmentLights lights;
  // The residual: the map with lights.suns taken out (ExtractedSuns::residual), its windowed SH9
  // (the same cutoff) and its specular chain; residualSpecular.levels empty when not computed.
  // lights.suns plus the residual integrate to the map exactly.
  SphericalHarmonics9 residualSh9;
  SpecularCube residualSpecular;
  // The residual's brute-force irradiance cube (size 0: not computed, or a bake from before it):
  // the lights modes correct the residual SH9's truncation with it (docs/dominant-lights.md).
  CubeMap residualIrradiance;
};

// Writes env/sh9.json (sh9 and shWindowCutoff), env/irradiance.exr (when computed),
// env/specular.exr and env/brdf_lut.exr into `folder`, creating env/; and when the residual was
// computed (residualSpecular.levels not empty), env/lights.json, env/residual_sh9.json (with
// shWindowCutoff), env/residual_specular.exr and env/residual_irradiance.exr (when computed).
// Throws Error naming the file.
void writeEnvironmentStages(const std::filesystem::path& folder, const EnvironmentStages& stages);

// Reads them back from `folder`, with the lat-long map, its rotation and intensity from the bake's
// `inputs`; env/irradiance.exr only where it exists (else irradiance.size is 0); the lights and the
// residual only when env/lights.json exists (a bake without it has none: lights and residual stay
// empty), and then the two residual files must exist too (env/residual_irradiance.exr only where
// it exists: bakes made before it have none). Throws Error("<file>: ...") naming the
// file that is missing or invalid, and
// Error("<folder>/bake.json: the bake has no environment stages ...") when `inputs` has none.
EnvironmentStages readEnvironmentStages(const std::filesystem::path& folder, const BakeInputs& inputs);

}  // namespace iblkit
