#include "score/score_images.h"

#include "core/error.h"
#include "core/image_io.h"
#include "score/image_metrics.h"

namespace iblkit {

namespace {

FlipErrorMap flipMap(const Image& reference, const Image& test, const ScoreOptions& options,
                     ExposureRange& exposures) {
  if (!options.highDynamicRange) return ldrFlip(reference, test, options.pixelsPerDegree);
  exposures = options.exposures ? *options.exposures : automaticExposureRange(reference);
  return hdrFlip(reference, test, exposures, options.pixelsPerDegree);
}

}  // namespace

ImageScores scoreImages(const Image& reference, const Image& test, std::span<const std::uint8_t> mask,
                        const ScoreOptions& options, FlipErrorMap* flip) {
  if (reference.width() != test.width() || reference.height() != test.height())
    fail("scoreImages", "the test image's size differs from the reference's");
  ImageScores scores;
  scores.scoredPixels = scoredPixelCount(mask, reference.pixelCount());
  const PixelRepairCounts invalid = countInvalidPixels(test);
  scores.invalidPixels = invalid.nan + invalid.inf;
  if (scores.invalidPixels > 0) return scores;

  if (options.mse) {
    scores.mse = meanSquaredError(reference, test, mask);
    scores.psnr = peakSignalToNoiseRatio(scores.mse);
  }
  if (options.relMse) scores.relMse = relativeMeanSquaredError(reference, test, mask);
  if (options.ssim) scores.ssim = structuralSimilarity(reference, test, mask);
  if (options.meanRelativeError) scores.meanRelativeError = meanRelativeLuminanceError(reference, test, mask);
  if (options.flip) {
    FlipErrorMap map = flipMap(reference, test, options, scores.flipExposures);
    scores.meanFlip = maskedMean(map.error, mask);
    if (flip) *flip = std::move(map);
  }
  return scores;
}

}  // namespace iblkit
