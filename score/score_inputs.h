#pragma once
// Loading what iblkit-score compares: the reference, the test image and the mask of scored pixels,
// with the checks a scorer needs (same size, no NaN or infinite values, LDR against LDR).

#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/image.h"

namespace iblkit {

struct ScoreInputs {
  Image reference, test;
  // One byte per pixel, 1 where scored; empty when every pixel is scored.
  std::vector<std::uint8_t> mask;
  // False when both images are PNG (LDR-FLIP), true when both are HDR (.exr, .hdr: HDR-FLIP).
  bool highDynamicRange = false;
};

// Reads the images with their values as stored (no repair, so negative values stay: see
// docs/scoring.md). Throws Error naming the file for: a missing or unreadable file, NaN or infinite
// values ("<file>: 12 NaN or infinite pixel values"), a size mismatch ("<test>: image is 64x32,
// reference is 128x64"), a PNG compared with an HDR image, and a mask that scores nothing.
// maskFile empty: the test image's alpha is the mask when some alpha is below 1. A mask image
// scores pixels whose alpha (when it has alpha below 1) or else luminance is above 0.5.
ScoreInputs loadScoreInputs(const std::filesystem::path& referenceFile, const std::filesystem::path& testFile,
                            const std::filesystem::path& maskFile = {});

}  // namespace iblkit
