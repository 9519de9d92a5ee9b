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

// The relMSE at which a reference counts as converged, given the best mode's relMSE against it:
// min(settings.maxReferenceRelMse, max(settings.negligibleRatio x best, settings.negligibleRelMse)).
double referenceTargetRelMse(const ReportSettings& settings, double bestModeRelMse);

// The passes to trace next, aimed at `target` from `relMse` measured at `passes` (relMSE falls as
// 1 / passes): passes x relMse / target with 25% to spare, rounded up to even, at least passes + 2
// and at most settings.maxPasses.
int referencePassesFor(const ReportSettings& settings, int passes, double relMse, double target);

// Traces the reference in passes of settings.passSpp samples: settings.minPasses, then as many as
// referencePassesFor aims at, until the halves' relMSE estimate (core/halves_noise.h) is at most
// referenceTargetRelMse of the best of `frames`, or settings.maxPasses are traced. A wave's passes
// run as pairs of stages of up to settings.maxStagePasses passes each (stage "trace-CASE-SEED",
// one iblkit-trace run of that many passes' samples, seeds 0, 1, 2, ... in order; even seeds make
// half A, odd seeds half B, and the two stages of a pair hold as many passes). Each half is its
// stages' mean weighted by their passes. Sets result's reference fields (spp, relMSE, convergence,
// the halves' FLIP, trace seconds, scored pixels, FLIP bracket), adds stage 0's command, and marks
// the modes whose frame has the wrong size as failed. When a stage or a frame is not in the cache
// and the cache collects missing stages (StageCache::collectInto), it stops after collecting the
// stages of the current wave (the first minPasses, or the aimed count), with result.pending set:
// the same waves as a local run, each decided once the previous one exists.
Reference traceReference(const ReportSettings& settings, const StageCache& cache, const std::string& caseName,
                         const CaseInputs& inputs, const std::vector<Image>& frames, CaseResult& result);

}  // namespace iblkit
