#pragma once
// The report's engine stages: the frames of a case's modes with their frame times, from one
// iblkit-view per group of modes that share its options (stage_commands.h, viewGroups).

#include <filesystem>
#include <string>
#include <vector>

#include "core/image.h"
#include "report/report_case.h"
#include "report/stage_cache.h"

namespace iblkit {

// Renders every mode of `settings` from the bake in `bake` (a stage "view-CASE-MODE+MODE..." per
// group of modes). Appends each mode's ModeResult (frame time, or its failure) to result.modes, in
// the order of settings.modes, and each stage's command line to result.commands; returns the frames
// in mode order, an empty image where a mode failed.
std::vector<Image> renderEngineFrames(const ReportSettings& settings, const StageCache& cache,
                                      const std::string& caseName, const std::filesystem::path& bake,
                                      CaseResult& result);

// The median frame time iblkit-view --bench prints for `mode` ("  sh   cpu 12.34 ms  gpu 0.00 ms"):
// the CPU time, synchronised with glFinish, since GPU timer queries are not everywhere. NaN when absent.
double parseMedianMilliseconds(const std::string& output, const std::string& mode);

}  // namespace iblkit
