#include "report/frame_scores.h"

#include <cmath>

#include "core/error.h"
#include "core/image_io.h"
#include "score/image_metrics.h"

namespace iblkit {

FrameScores scoreFrame(const Image& reference, const Image& test, std::span<const std::uint8_t> mask,
                       const ExposureRange& exposures, FlipErrorMap* flip) {
  if (reference.width() != test.width() || reference.height() != test.height())
    fail("scoreFrame", "the test image's size differs from the reference's");
  FrameScores scores;
  const PixelRepairCounts invalid = countInvalidPixels(test);
  scores.invalidPixels = invalid.nan + invalid.inf;
  if (scores.invalidPixels > 0) return scores;

  FlipErrorMap flipMap = hdrFlip(reference, test, exposures);
  scores.meanFlip = maskedMean(flipMap.error, mask);
  scores.relMse = relativeMeanSquaredError(reference, test, mask);
  scores.ssim = structuralSimilarity(reference, test, mask);
  double difference = 0.0, total = 0.0;
  for (std::size_t i = 0; i < reference.pixelCount(); ++i) {
    if (!mask.empty() && mask[i] == 0) continue;
    const double referenceLuminance = luminance(glm::vec3(reference.pixels()[i]));
    difference += std::abs(double(luminance(glm::vec3(test.pixels()[i]))) - referenceLuminance);
    total += referenceLuminance;
  }
  scores.meanRelativeError = total > 0.0 ? difference / total : 0.0;
  if (flip) *flip = std::move(flipMap);
  return scores;
}

double halvesRelMseEstimate(const Image& a, const Image& b, std::span<const std::uint8_t> mask) {
  // (a - mean)^2 = (a - b)^2 / 4, which is the estimate itself.
  return relativeMeanSquaredError(averageImages(a, b), a, mask);
}

std::vector<std::uint8_t> geometryMask(const Image& depth) {
  std::vector<std::uint8_t> mask(depth.pixelCount());
  for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = depth.pixels()[i].r > 0.0f ? 1 : 0;
  return mask;
}

std::vector<std::uint8_t> erodeMask(std::span<const std::uint8_t> mask, int width, int height) {
  if (mask.size() != std::size_t(width) * std::size_t(height)) fail("erodeMask", "mask size does not match");
  auto at = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < width && y < height && mask[std::size_t(y) * width + x] != 0;
  };
  std::vector<std::uint8_t> eroded(mask.size(), 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      eroded[std::size_t(y) * width + x] = at(x, y) && at(x - 1, y) && at(x + 1, y) && at(x, y - 1) && at(x, y + 1);
  return eroded;
}

Image averageImages(const Image& a, const Image& b) {
  if (a.width() != b.width() || a.height() != b.height()) fail("averageImages", "images differ in size");
  Image mean(a.width(), a.height());
  for (std::size_t i = 0; i < a.pixelCount(); ++i) mean.pixels()[i] = 0.5f * (a.pixels()[i] + b.pixels()[i]);
  return mean;
}

}  // namespace iblkit
