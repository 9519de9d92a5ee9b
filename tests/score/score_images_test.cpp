#include "score/score_images.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "score/image_metrics.h"

namespace iblkit {
namespace {

// A noisy HDR image and a second one off by a few percent plus noise, so every metric is non-zero.
Image noisy(int w, int h, std::uint64_t seed, float scale) {
  Image image(w, h);
  PCG32 rng(seed);
  for (glm::vec4& pixel : image.pixels())
    pixel = glm::vec4(
        scale * glm::vec3(4.0f * rng.uniformFloat(), rng.uniformFloat(), 0.3f * rng.uniformFloat()), 1);
  return image;
}

std::vector<std::uint8_t> checkerMask(int w, int h) {
  std::vector<std::uint8_t> mask(std::size_t(w) * h);
  for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = (i / 7) % 3 != 0;
  return mask;
}

TEST(ScoreImages, EachScoreIsItsMetricExactly) {
  const Image reference = noisy(40, 24, 1, 1.0f), test = noisy(40, 24, 2, 1.05f);
  const std::vector<std::uint8_t> mask = checkerMask(40, 24);
  const ExposureRange exposures{-3.0f, 1.5f, 5};
  ScoreOptions options;
  options.exposures = exposures;
  FlipErrorMap flip;
  const ImageScores scores = scoreImages(reference, test, mask, options, &flip);
  EXPECT_EQ(scores.scoredPixels, std::size_t(std::count(mask.begin(), mask.end(), 1)));
  EXPECT_EQ(scores.invalidPixels, 0u);
  EXPECT_EQ(scores.mse, meanSquaredError(reference, test, mask));
  EXPECT_EQ(scores.psnr, peakSignalToNoiseRatio(scores.mse));
  EXPECT_EQ(scores.relMse, relativeMeanSquaredError(reference, test, mask));
  EXPECT_EQ(scores.ssim, structuralSimilarity(reference, test, mask));
  EXPECT_EQ(scores.meanRelativeError, meanRelativeLuminanceError(reference, test, mask));
  const FlipErrorMap expected = hdrFlip(reference, test, exposures);
  EXPECT_EQ(flip.error, expected.error);
  EXPECT_EQ(scores.meanFlip, maskedMean(expected.error, mask));
  EXPECT_EQ(scores.flipExposures.start, exposures.start);
  EXPECT_EQ(scores.flipExposures.count, exposures.count);
  EXPECT_GT(scores.meanFlip, 0.0);
  EXPECT_GT(scores.meanRelativeError, 0.0);
}

TEST(ScoreImages, FlipBracketDefaultsToTheReferencesAndLdrUsesLdrFlip) {
  const Image reference = noisy(24, 16, 3, 1.0f), test = noisy(24, 16, 4, 1.0f);
  const ImageScores hdr = scoreImages(reference, test, {});
  const ExposureRange automatic = automaticExposureRange(reference);
  EXPECT_EQ(hdr.flipExposures.start, automatic.start);
  EXPECT_EQ(hdr.flipExposures.stop, automatic.stop);
  EXPECT_EQ(hdr.meanFlip, maskedMean(hdrFlip(reference, test, automatic).error));
  EXPECT_EQ(hdr.scoredPixels, reference.pixelCount());

  ScoreOptions ldr;
  ldr.highDynamicRange = false;
  ldr.pixelsPerDegree = 30.0f;
  EXPECT_EQ(scoreImages(reference, test, {}, ldr).meanFlip,
            maskedMean(ldrFlip(reference, test, 30.0f).error));
}

TEST(ScoreImages, MetricsNotAskedForStayZero) {
  const Image reference = noisy(16, 16, 5, 1.0f), test = noisy(16, 16, 6, 1.0f);
  ScoreOptions options;
  options.mse = options.ssim = options.flip = options.meanRelativeError = false;
  FlipErrorMap flip;
  const ImageScores scores = scoreImages(reference, test, {}, options, &flip);
  EXPECT_GT(scores.relMse, 0.0);
  EXPECT_EQ(scores.mse, 0.0);
  EXPECT_EQ(scores.psnr, 0.0);
  EXPECT_EQ(scores.ssim, 0.0);
  EXPECT_EQ(scores.meanFlip, 0.0);
  EXPECT_EQ(scores.meanRelativeError, 0.0);
  EXPECT_TRUE(flip.error.empty());
}

TEST(ScoreImages, InvalidTestPixelsAreCountedNotScored) {
  const Image reference = noisy(8, 8, 7, 1.0f);
  Image test = reference;
  test.at(1, 2).b = std::numeric_limits<float>::quiet_NaN();
  test.at(5, 5).r = -std::numeric_limits<float>::infinity();
  const ImageScores scores = scoreImages(reference, test, {});
  EXPECT_EQ(scores.invalidPixels, 2u);
  EXPECT_EQ(scores.scoredPixels, 64u);
  EXPECT_EQ(scores.relMse, 0.0);
  EXPECT_EQ(scores.meanFlip, 0.0);
}

TEST(ScoreImages, SizeMismatchAndEmptyMaskThrow) {
  const Image reference = noisy(8, 8, 8, 1.0f);
  EXPECT_THROW(scoreImages(reference, noisy(8, 4, 9, 1.0f), {}), Error);
  EXPECT_THROW(scoreImages(reference, reference, std::vector<std::uint8_t>(64, 0)), Error);
}

TEST(ImageMetrics, MeanRelativeLuminanceErrorIsLuminanceWeighted) {
  // Pixel 0 10% too bright on a reference of 1, pixel 1 exact on 3, pixel 2 unscored: 0.1 / 4.
  Image reference(3, 1, glm::vec4(1.0f)), test(3, 1, glm::vec4(1.0f));
  reference.at(1, 0) = test.at(1, 0) = glm::vec4(3, 3, 3, 1);
  test.at(0, 0) = glm::vec4(1.1f, 1.1f, 1.1f, 1);
  test.at(2, 0) = glm::vec4(9, 9, 9, 1);
  EXPECT_NEAR(meanRelativeLuminanceError(reference, test, std::vector<std::uint8_t>{1, 1, 0}), 0.1 / 4.0,
              1e-6);
  // A black reference: no relative error to speak of, 0 rather than a division by 0.
  EXPECT_EQ(meanRelativeLuminanceError(Image(2, 1, glm::vec4(0, 0, 0, 1)), Image(2, 1, glm::vec4(1.0f))),
            0.0);
  EXPECT_EQ(scoredPixelCount(std::vector<std::uint8_t>{0, 1, 1}, 3), 2u);
  EXPECT_EQ(scoredPixelCount({}, 5), 5u);
}

}  // namespace
}  // namespace iblkit
