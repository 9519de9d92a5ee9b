#pragma once
// The report's pictures of a case: the reference and each frame as PNG at one exposure, and each
// mode's FLIP heat map (docs/report.md, "Pictures").

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/image.h"
#include "report/reference_passes.h"
#include "report/report_case.h"
#include "score/flip.h"

namespace iblkit {

// Exposure (stops) that brings the log-average luminance of the scored reference pixels to 0.18
// (keyExposure, core/auto_exposure.h: the viewer's automatic exposure).
float thumbnailExposure(const Image& reference, std::span<const std::uint8_t> mask);

// Writes OUT/images/CASE-reference.png and, for each mode not failed, CASE-MODE.png and
// CASE-MODE-flip.png (from flipMaps, in mode order), and CASE-linear.js, the reference and the
// frames linear for the page (page_images.h); sets result's exposure and picture paths.
void writeCasePictures(const std::filesystem::path& outDir, const std::string& caseName,
                       const Reference& reference, const std::vector<Image>& frames,
                       const std::vector<FlipErrorMap>& flipMaps, CaseResult& result);

}  // namespace iblkit
