#pragma once
// The environment-sampling study of the reference path tracer (issues 3 and 15; docs/benchmarks.md,
// "Sampling study"): a scene rendered under one environment map with each --env-sampling strategy
// (and the point lights at several light counts) at equal sample counts 1, 2, 4, ..., maxSpp, every render
// scored by its relMSE (score/image_metrics.h) against a high-spp MIS render of the same map with another
// seed. The program bench/sampling_study.cpp runs it over several maps and writes the results
// (sampling_study_report.h); tests/bench checks the claim it measures.
//
// The reference has noise of its own: the expected relMSE of a test render against it is the
// test's own plus the reference's, which the reference's per-pixel variance estimates (the
// "floor"). The floor is reported, not subtracted.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/environment_map.h"
#include "core/image.h"
#include "core/scene.h"
#include "reference/integrator.h"

namespace iblkit {

// The strategies compared, in the order of every table, plot and MapStudy row.
struct StudyStrategy {
  const char* name;  // as --env-sampling spells it, with the light count for lights
  EnvSampling sampling;
  int lights;          // median-cut regions (mediancut) or point lights (lights); 0 for the others
  const char* colour;  // the plot's line colour
};
// The five unbiased strategies of issue 3, the median-cut sampler with 64 regions (unbiased too),
// and the biased point-light approximation with 4 to 256 lights (issue 15: its aliasing against
// the exact environment sampler). Colours: matplotlib's tab10, uniform in grey; the point lights
// in purples, darker with more lights.
inline constexpr StudyStrategy kStudyStrategies[] = {
    {"uniform", EnvSampling::Uniform, 0, "#7f7f7f"},  {"cosine", EnvSampling::Cosine, 0, "#1f77b4"},
    {"brdf", EnvSampling::Brdf, 0, "#2ca02c"},        {"env", EnvSampling::Env, 0, "#ff7f0e"},
    {"mis", EnvSampling::Mis, 0, "#d62728"},          {"mediancut", EnvSampling::MedianCut, 64, "#8c564b"},
    {"lights4", EnvSampling::Lights, 4, "#c994c7"},   {"lights16", EnvSampling::Lights, 16, "#9e9ac8"},
    {"lights64", EnvSampling::Lights, 64, "#6a51a3"}, {"lights256", EnvSampling::Lights, 256, "#3f007d"}};
inline constexpr std::size_t kStudyStrategyCount = std::size(kStudyStrategies);

// The row of the first strategy of `sampling` in kStudyStrategies (and in MapStudy::relMse).
std::size_t studyStrategyIndex(EnvSampling sampling);
// The row of the strategy named `name` ("lights16").
std::size_t studyStrategyIndex(const std::string& name);

struct SamplingStudySettings {
  int width = 160, height = 90;
  int maxSpp = 64;          // the spp levels are 1, 2, 4, ... up to it
  int referenceSpp = 4096;  // samples per pixel of the MIS reference
  int threads = 2;          // render threads (0: all hardware threads)
  // Set: every surface reflects with the modified Phong lobe of this exponent (brdf.h) instead of
  // its glTF material, the second material model.
  std::optional<float> phong;
  // Where references are cached as OpenEXR, keyed by map, size, sample count and material.
  std::filesystem::path cache = "build/sampling_study";
};

// Throws Error("<option>: <problem>", e.g. "--width: must be in 1..16384, not 0") for sizes outside
// 1..kMaxImageSide, sample counts outside 1..kMaxSamplesPerPixel (renderer.h), a negative thread
// count or a negative or non-finite Phong exponent, so that bad settings fail before anything is
// rendered.
void validateSamplingStudySettings(const SamplingStudySettings& settings);

// The spp levels 1, 2, 4, ..., up to maxSpp (maxSpp >= 1).
std::vector<int> studySppLevels(int maxSpp);

// Mean over pixels and RGB of variance / (reference^2 + kRelMseEpsilon): the relMSE that the
// reference's own noise adds to every score against it. `variance` is the per-pixel variance of
// the reference's mean (RenderResult::variance).
double referenceNoiseFloor(const Image& reference, const Image& variance);

// One map's results.
struct MapStudy {
  std::string name, label;      // e.g. "sky", "sunny"
  double referenceFloor = 0.0;  // referenceNoiseFloor of the reference
  double referenceSeconds = 0.0;
  bool referenceCached = false;  // read from the cache instead of rendered
  // relMse[strategy][level]: strategy as in kStudyStrategies, level as in studySppLevels.
  std::vector<std::vector<double>> relMse;
  std::vector<double> microsecondsPerSample;  // per strategy, over all its renders
};

// relMSE of strategy `numerator` over that of `denominator` at spp level `level`: how many times
// lower `denominator`'s error is.
double relMseRatio(const MapStudy& study, EnvSampling numerator, EnvSampling denominator, std::size_t level);

// Progress lines ("sky: rendering the reference, 4096 spp mis"), without a newline.
using StudyLog = std::function<void(const std::string& line)>;

// Runs the study of `scene` lit by `environment` as it is given (the scene's own map is ignored:
// loadSceneEnvironment with a file override gives a map with the scene's rotation and intensity). The
// reference is read from settings.cache when a file of the same key is there, else rendered and written
// there. Throws Error for a cached reference of the wrong size and for settings that
// validateSamplingStudySettings refuses.
MapStudy studyEnvironmentMap(const SamplingStudySettings& settings, const Scene& scene,
                             const EnvironmentMap& environment, const std::string& name,
                             const std::string& label, const StudyLog& log = {});

}  // namespace iblkit
