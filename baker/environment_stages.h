#pragma once
// The environment stages of a bake, computed from the map (bakefile/environment_stages.h holds
// and stores them): SH9 projection and its automatic or chosen ringing window, the brute-force
// irradiance cube, the GGX-prefiltered specular chain and the DFG table (docs/prefilter.md), and
// on request the dominant lights with the residual's SH9 and specular chain
// (docs/dominant-lights.md). One function for iblkit-bake and for the viewer, which switches maps
// at run time with lighter settings.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>

#include "bakefile/environment_stages.h"
#include "core/environment_lights.h"
#include "core/environment_map.h"

namespace iblkit {

struct EnvironmentStageOptions {
  // The sinc^4 window's cutoff in bands (0: none); unset: automaticShWindowCutoff.
  std::optional<float> shWindowCutoff;
  std::uint32_t specularSamples = 1024;  // GGX samples per texel of the roughest level
  // Face size of the specular chains' level 0, a power of two; 0: defaultSpecularBaseSize of the
  // map's width.
  int specularBaseSize = 0;
  // Whether stages.latLong gets a copy of the map (the viewer draws it); iblkit-bake writes no
  // lat-long, and a 16384 x 8192 map's copy is 2 GiB.
  bool copyLatLong = true;
  int lutSize = 128;
  std::uint32_t lutSamples = 512;
  int irradianceCubeSize = 16;  // face size of the brute-force irradiance cube; 0: not computed
  // The dominant lights (extractSuns with `suns`, medianCutLights with medianCutLevels) and the
  // residual's SH9 (the same window cutoff as sh9) and specular chain (the same samples and sizes
  // as specular). Off: stages.lights and the residual stay empty.
  bool lights = false;
  SunExtractionOptions suns{};
  int medianCutLevels = kDefaultMedianCutLevels;
};

// iblkit-view's stages of a map switched to at run time or baked in memory: about 1 s of CPU for
// a 512 x 256 map (the specular chain's samples and the table are a quarter of the baker's), the
// irradiance cube (the `irradiance` modes) at the baker's size, about 0.2 s of it, the lights and
// the residual's chain included (docs/benchmarks.md).
inline constexpr EnvironmentStageOptions kViewerEnvironmentStages{.shWindowCutoff = std::nullopt,
                                                                  .specularSamples = 256,
                                                                  .lutSize = 64,
                                                                  .lutSamples = 256,
                                                                  .irradianceCubeSize = 16,
                                                                  .lights = true};

// Seconds each stage took (the last three 0 without options.lights).
struct EnvironmentStageTimes {
  double sh9 = 0.0, irradiance = 0.0, specular = 0.0, brdfLut = 0.0;
  double lights = 0.0, residualSh9 = 0.0, residualSpecular = 0.0;
};

// Computes the stages of `environment` (its rotation and intensity applied): the SH9 projection,
// its window (sh9 = the windowed projection), the irradiance cube, the full specular chain with a
// face size of options.specularBaseSize (or defaultSpecularBaseSize(environment.width())), and the
// DFG table; with
// options.lights, then the suns and the median-cut regions (stages.lights), and the residual's
// windowed SH9 and specular chain. Parallel (TBB). `progress` (optional) is called with (stages
// done, 4, or 6 with lights) before and after each stage; `times` (optional) receives the seconds
// of each. Throws std::invalid_argument for bad light options (extractSuns, medianCutLights).
// Throws Error("<file>: ...") unless `environment` can be prefiltered: a lat-long map at least 8
// texels wide. For the programs, before any work, so the message names the map rather than a stage.
void requireEnvironmentForStages(const EnvironmentMap& environment, const std::filesystem::path& file);

EnvironmentStages computeEnvironmentStages(const EnvironmentMap& environment,
                                           const EnvironmentStageOptions& options,
                                           const std::function<void(std::size_t, std::size_t)>& progress = {},
                                           EnvironmentStageTimes* times = nullptr);
// The same stages from a map the caller is done with: with options.lights its image becomes the
// residual in place (the suns' texels replaced) instead of a copy, which on a 16384 x 8192 map is
// 2 GiB of the bake's peak. With options.lights the map is left empty.
EnvironmentStages computeEnvironmentStages(EnvironmentMap&& environment, const EnvironmentStageOptions& options,
                                           const std::function<void(std::size_t, std::size_t)>& progress = {},
                                           EnvironmentStageTimes* times = nullptr);

}  // namespace iblkit
