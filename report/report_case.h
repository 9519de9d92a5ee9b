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
  int benchFrames = 5;  // iblkit-view --bench frames for the frame time; 0: not measured
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
  std::string referenceImage;     // PNG path relative to outDir
  std::vector<ModeResult> modes;
  std::vector<std::string> commands;  // the command lines of the stages, for the report
};

CaseResult runCase(const ReportSettings& settings, const StageCache& cache,
                   const std::filesystem::path& sceneFile, const std::filesystem::path& environmentFile);

}  // namespace iblkit
