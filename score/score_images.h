#pragma once
// One scoring of a test image against its reference, the numbers both iblkit-score and the report
// give (docs/scoring.md): each metric is computed once, here, so the two cannot disagree.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "core/image.h"
#include "score/flip.h"

namespace iblkit {

// Which metrics to compute and how FLIP sees the images. Every metric is on by default.
struct ScoreOptions {
  bool mse = true;  // and PSNR, which is a function of it
  bool relMse = true, ssim = true, flip = true, meanRelativeError = true;
  bool highDynamicRange = true;  // HDR-FLIP; false: LDR-FLIP (both images PNG)
  // HDR-FLIP's exposure bracket; none: automaticExposureRange of the reference.
  std::optional<ExposureRange> exposures;
  float pixelsPerDegree = kDefaultPixelsPerDegree;
};

// The scores over the mask's pixels (image_metrics.h, flip.h); a metric not asked for stays 0.
struct ImageScores {
  std::size_t scoredPixels = 0;
  std::size_t invalidPixels = 0;   // NaN or infinite values in the test image
  double mse = 0.0, psnr = 0.0;    // linear RGB; psnr is +infinity for identical images
  double relMse = 0.0;             // linear RGB
  double ssim = 0.0;               // luminance of the tone-mapped images
  double meanFlip = 0.0;           // mean of the FLIP map over scored pixels
  double meanRelativeError = 0.0;  // luminance-weighted (meanRelativeLuminanceError)
  ExposureRange flipExposures;     // the HDR-FLIP bracket used (HDR-FLIP only)
};

// Scores `test` against `reference` (same size) over `mask` (empty: every pixel). When the test
// image has NaN or infinite values, only scoredPixels and invalidPixels are set: those pixels are a
// failure to report, not a number to average. `flip` (optional) receives the FLIP error map of the
// whole image when options.flip is set. Throws Error when the sizes differ or the mask scores nothing.
ImageScores scoreImages(const Image& reference, const Image& test, std::span<const std::uint8_t> mask,
                        const ScoreOptions& options = {}, FlipErrorMap* flip = nullptr);

}  // namespace iblkit
