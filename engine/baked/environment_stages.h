#pragma once
// Everything the engine needs from an environment map, in one place: the lat-long radiance (the
// sky and the `mirror` mode), its SH9 radiance coefficients (diffuse), the GGX-prefiltered
// specular cube chain and the split-sum DFG table (docs/prefilter.md). Either read from a bake
// (baked_scene.h) or computed here with the baker library, for the viewer's environment switching.
#include <cstdint>
#include <vector>

#include "baker/specular_prefilter.h"
#include "core/environment_map.h"
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
  // SH9 radiance coefficients L_k (spherical_harmonics.h), ringing window applied, in world space:
  // rotationDegrees and intensity are already in them.
  SphericalHarmonics9 sh9;
  float shWindowCutoff = 0.0f;  // the sinc^4 cutoff applied (0: none)
  // The prefiltered chain (level i has perceptual roughness specular.roughness[i]), world space
  // like sh9.
  SpecularCube specular;
  // The DFG table (brdf_lut.h): R = A, G = B, B = E; NoV along x, roughness along y.
  Image brdfLut;
};

struct PrepareEnvironmentOptions {
  std::uint32_t specularSamples = 256;  // GGX samples per texel of the roughest level
  int lutSize = 64;
  std::uint32_t lutSamples = 256;
};

// Computes the stages of `environment` (its rotation and intensity applied) as iblkit-bake does:
// SH9 projection with the automatic sinc^4 window (automaticShWindowCutoff), the full specular
// chain with a face size of environment.width() / 4, and the DFG table. Parallel (TBB); a
// 512 x 256 map takes about 1 s of CPU with the default options (iblkit-view measured 1.2 s of user
// time for the whole in-memory bake of bunny.json, visibility included).
EnvironmentStages prepareEnvironment(const EnvironmentMap& environment,
                                     const PrepareEnvironmentOptions& options = {});

}  // namespace iblkit
