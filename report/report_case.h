#pragma once
// One case of the demo report: a scene under one environment map. Bakes it (iblkit-bake), renders
// every engine mode headless (iblkit-view), path-traces the reference (iblkit-trace) in passes
// until its own error is negligible next to the modes' errors, and scores each mode against it.
// Every stage is cached by the hash of its inputs (stage_cache.h); docs/report.md.

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "report/frame_scores.h"
#include "report/stage_cache.h"

namespace iblkit {

struct ReportSettings {
  std::filesystem::path binDir;  // where iblkit-bake, iblkit-trace and iblkit-view are
  std::filesystem::path outDir;  // report.html, report.json and images/
  int width = 320, height = 180;
  std::vector<std::string> modes;  // engine modes to score (iblkit-view --mode)
  int passSpp = 16;                // samples per pixel of one reference pass
  int minPasses = 4, maxPasses = 64;  // reference passes; even, doubled until negligible
  // The reference is converged when its estimated relMSE is at most this fraction of the best
  // mode's relMSE, so its noise adds at most that fraction to every mode's measured error.
  double negligibleRatio = 0.1;
  // ...or at most this relMSE (1% RMS relative noise), whichever is larger: where a mode is
  // nearly exact (the mirror sphere's `mirror`), 10% of its error would ask for thousands of
  // samples to resolve differences no score can see.
  double negligibleRelMse = 1e-4;
  int benchFrames = 5;  // iblkit-view --bench frames for the frame time; 0: not measured
  // Engine frames shade this many samples per pixel (iblkit-view --samples N --sample-shading), so
  // their pixels average the shading over the pixel as the reference's pixel filter does; 1: one.
  int engineSamples = 4;
  // ...and render K x K pixels per output pixel (iblkit-view --supersample K): 4 x 2 x 2 = 16
  // shaded samples by default, since 4 still alias the mirror sphere's minified reflection.
  int engineSupersample = 2;
  // iblkit-trace --integrator of the reference: path (full global illumination) or direct (one
  // bounce: what the engine's modes model without interreflection), for experiments.
  std::string referenceIntegrator = "path";
};

struct ModeResult {
  std::string mode;
  FrameScores scores;
  double frameMilliseconds = std::numeric_limits<double>::quiet_NaN();
  std::string image, heatMap;  // PNG paths relative to outDir
  std::string failure;         // non-empty when the frame could not be scored
};

struct CaseResult {
  std::string scene, environment;  // names (file stems)
  std::filesystem::path sceneFile, environmentFile;
  double bakeSeconds = 0.0, traceSeconds = 0.0;
  int referenceSpp = 0;
  double referenceRelMse = 0.0;  // estimated from the two halves
  bool referenceConverged = false;
  float exposure = 0.0f;          // of the PNG thumbnails, stops
  ExposureRange flipExposures;    // HDR-FLIP bracket shared by every mode of this case
  std::size_t scoredPixels = 0;
  // SH9's own error on the scored pixels' normals (sh9_truncation.h): what an exact `sh` frame of a
  // convex Lambert object would still measure as meanRelativeError.
  double sh9Truncation = std::numeric_limits<double>::quiet_NaN();
  // What the `sh` frame gets wrong beyond that (errorBeyondSh9); NaN without an `sh` frame.
  double shBeyondSh9 = std::numeric_limits<double>::quiet_NaN();
  std::string referenceImage;     // PNG path relative to outDir
  std::vector<ModeResult> modes;
  std::vector<std::string> commands;  // the command lines of the stages, for the report
};

CaseResult runCase(const ReportSettings& settings, const StageCache& cache,
                   const std::filesystem::path& sceneFile, const std::filesystem::path& environmentFile);

}  // namespace iblkit
