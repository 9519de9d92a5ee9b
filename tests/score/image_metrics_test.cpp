#include "score/image_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/error_capture.h"

namespace iblkit {
namespace {

// Reference and test 2x2 images with hand-chosen values.
Image twoByTwo(std::initializer_list<glm::vec4> pixels) {
  Image image(2, 2);
  std::copy(pixels.begin(), pixels.end(), image.pixels().begin());
  return image;
}
const Image kReference = twoByTwo({{0.5f, 0.5f, 0.5f, 1}, {1, 0, 0, 1}, {0, 0, 0, 1}, {0.2f, 0.4f, 0.6f, 1}});
const Image kTest =
    twoByTwo({{0.5f, 0.5f, 0.5f, 1}, {0.9f, 0, 0, 1}, {0.1f, 0, 0, 1}, {0.2f, 0.4f, 0.8f, 1}});

TEST(ImageMetrics, MseRelMseAndPsnrMatchHandComputedValues) {
  // Squared differences: 0.01 (red of pixel 1), 0.01 (red of pixel 2), 0.04 (blue of pixel 3).
  const double mse = (0.01 + 0.01 + 0.04) / 12.0;
  EXPECT_NEAR(meanSquaredError(kReference, kTest), mse, 1e-7);
  const double relMse = (0.01 / 1.01 + 0.01 / 0.01 + 0.04 / 0.37) / 12.0;
  EXPECT_NEAR(relativeMeanSquaredError(kReference, kTest), relMse, 1e-6);
  EXPECT_NEAR(peakSignalToNoiseRatio(mse), 10.0 * std::log10(1.0 / mse), 1e-9);
  EXPECT_NEAR(peakSignalToNoiseRatio(0.01), 20.0, 1e-12);
}

TEST(ImageMetrics, IdenticalImagesScorePerfectly) {
  EXPECT_EQ(meanSquaredError(kReference, kReference), 0.0);
  EXPECT_EQ(relativeMeanSquaredError(kReference, kReference), 0.0);
  EXPECT_TRUE(std::isinf(peakSignalToNoiseRatio(0.0)));
  EXPECT_GT(peakSignalToNoiseRatio(0.0), 0.0);
  EXPECT_NEAR(structuralSimilarity(kReference, kReference), 1.0, 1e-12);
}

TEST(ImageMetrics, MaskRestrictsEveryMetric) {
  // Only pixel 2 (reference black, test red 0.1) is scored.
  const std::vector<std::uint8_t> mask = {0, 0, 1, 0};
  EXPECT_NEAR(meanSquaredError(kReference, kTest, mask), 0.01 / 3.0, 1e-7);
  EXPECT_NEAR(relativeMeanSquaredError(kReference, kTest, mask), 1.0 / 3.0, 1e-6);
  // Pixel 0 is identical in both images, but its SSIM window sees its neighbours.
  const std::vector<std::uint8_t> firstOnly = {1, 0, 0, 0};
  EXPECT_NE(structuralSimilarity(kReference, kTest, firstOnly), structuralSimilarity(kReference, kTest));
  EXPECT_NEAR(maskedMean(std::vector<float>{1.0f, 2.0f, 3.0f, 4.0f}, std::vector<std::uint8_t>{0, 1, 1, 0}),
              2.5, 1e-12);
  EXPECT_EQ(test::errorMessage([] { maskedMean(std::vector<float>{1.0f}, std::vector<std::uint8_t>{0}); }),
            "image metrics: the mask scores no pixel");
}

TEST(ImageMetrics, SsimFallsWithNoiseAmplitude) {
  Image reference(32, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) reference.at(x, y) = glm::vec4(glm::vec3(float(x + y) / 64.0f), 1.0f);
  double previous = 1.0;
  for (float amplitude : {0.02f, 0.05f, 0.1f, 0.3f}) {
    Image test = reference;
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x)
        test.at(x, y) += glm::vec4(glm::vec3((x * 7 + y * 13) % 5 - 2) * amplitude / 2.0f, 0);
    const double ssim = structuralSimilarity(reference, test);
    EXPECT_LT(ssim, previous) << amplitude;
    previous = ssim;
  }
}

TEST(ImageMetrics, RelativeSquaredErrorMapIsPerPixelMeanOverChannels) {
  const std::vector<float> map = relativeSquaredErrorMap(kReference, kTest);
  ASSERT_EQ(map.size(), 4u);
  EXPECT_EQ(map[0], 0.0f);
  EXPECT_NEAR(map[2], 1.0 / 3.0, 1e-6);
}

}  // namespace
}  // namespace iblkit
