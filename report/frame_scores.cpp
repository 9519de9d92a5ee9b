#include "report/frame_scores.h"

#include "core/error.h"
#include "score/image_metrics.h"

namespace iblkit {

FrameScores scoreFrame(const Image& reference, const Image& test, std::span<const std::uint8_t> mask,
                       const ExposureRange& exposures, FlipErrorMap* flip) {
  ScoreOptions options;
  options.mse = false;
  options.exposures = exposures;
  return scoreImages(reference, test, mask, options, flip);
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
