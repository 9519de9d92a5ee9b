#pragma once
// The report's reference stage: iblkit-trace passes, added until the reference's own error is
// negligible next to the engine frames' errors (docs/report.md, "Reference").

#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"
#include "report/report_case.h"
#include "report/stage_cache.h"
#include "report/stage_commands.h"

namespace iblkit {

struct Reference {
  Image image;                     // the mean of every pass
  Image normals;                   // pass 0's normal layer, signed
  std::vector<std::uint8_t> mask;  // the scored pixels: geometry less its rim (frame_scores.h)
};

// Traces passes with seeds 0, 1, 2, ... (stage "trace-CASE-SEED"; even seeds make half A, odd
// seeds half B), from settings.minPasses doubling up to settings.maxPasses, until the halves'
// relMSE estimate is negligible next to the best of `frames` (referenceConverged). Sets result's
// reference fields (spp, relMSE, convergence, trace seconds, scored pixels, FLIP bracket), adds
// pass 0's command, and marks the modes whose frame has the wrong size as failed.
Reference traceReference(const ReportSettings& settings, const StageCache& cache, const std::string& caseName,
                         const CaseInputs& inputs, const std::vector<Image>& frames, CaseResult& result);

}  // namespace iblkit
