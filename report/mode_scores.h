#pragma once
// The report's scoring stage: every engine frame of a case against its converged reference.

#include <vector>

#include "core/image.h"
#include "report/reference_passes.h"
#include "report/report_case.h"
#include "score/flip.h"

namespace iblkit {

// Scores each mode not failed so far (scoreFrame over the reference's mask, with the case's one
// FLIP bracket, result.flipExposures) into result.modes; a frame with NaN or infinite pixels
// becomes a failed mode. Returns the FLIP maps in mode order, empty where a mode failed.
std::vector<FlipErrorMap> scoreModes(const Reference& reference, const std::vector<Image>& frames,
                                     CaseResult& result);

}  // namespace iblkit
