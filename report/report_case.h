#pragma once
// One case of the demo report: a scene under one environment map. Bakes it (iblkit-bake), renders
// every engine mode headless (iblkit-view), path-traces the reference (iblkit-trace) in passes
// until its own error is negligible next to the modes' errors, and scores each mode against it.
// Every stage is cached under a key hashed from its command (stage_command.h); docs/report.md.
// The stages are functions of their own: stage_commands.h, engine_frames.h, reference_passes.h,
// mode_scores.h, case_pictures.h and sh9_truncation.h.

#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "report/frame_scores.h"
#include "report/map_kind.h"
#include "report/report_settings.h"
#include "report/stage_cache.h"

namespace iblkit {

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
  // The environment's kind and the shares it was told from (map_kind.h); set by the program,
  // once per map. The claims per kind of map skip a case without one.
  std::optional<MapKind> mapKind;
  MapConcentration concentration;
  double bakeSeconds = 0.0, traceSeconds = 0.0;
  // The scene's visibility stage (shared by its cases under every map: not in bakeSeconds).
  double visibilitySeconds = 0.0;
  // The map's environment stage (shared by the cases of every scene under it: not in bakeSeconds).
  double environmentSeconds = 0.0;
  int referenceSpp = 0;
  double referenceRelMse = 0.0;  // estimated from the two halves
  // Mean HDR-FLIP between the two halves over the scored pixels (score/halves_flip.h); NaN until traced.
  double referenceHalvesFlip = std::numeric_limits<double>::quiet_NaN();
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
  std::string linearImages;       // the page's linear images script relative to outDir (page_images.h)
  std::vector<ModeResult> modes;
  std::vector<std::string> commands;  // the command lines of the stages, for the report
  // The requested modes the case does not score, and why (case_modes.h: modeNotApplicable).
  std::vector<std::pair<std::string, std::string>> notApplicable;
  // Some stage this case needs is not in the cache yet, and the cache collects missing stages
  // rather than running them (StageCache::collectInto): the case is not scored, and only its
  // names, modes and commands are set. A scheduler runs the stages and the case is run again.
  bool pending = false;
};

// Runs the case's stages (or collects the missing ones, then `pending` says so) and scores it.
CaseResult runCase(const ReportSettings& settings, const StageCache& cache,
                   const std::filesystem::path& sceneFile, const std::filesystem::path& environmentFile);

}  // namespace iblkit
