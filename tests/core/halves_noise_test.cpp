#include "core/halves_noise.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "core/relative_squared_error.h"
#include "core/rng.h"

namespace iblkit {
namespace {

// Gaussian noise by Box-Muller, for halves whose noise is known exactly.
float gaussian(PCG32& rng) {
  const float u1 = 1.0f - rng.uniformFloat(), u2 = rng.uniformFloat();
  return std::sqrt(-2.0f * std::log(u1)) * std::cos(6.2831853f * u2);
}

// The true relMSE of the halves' mean against the truth, per pixel and channel.
double trueRelMse(const Image& truth, const Image& a, const Image& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < truth.pixelCount(); ++i)
    for (int c = 0; c < 3; ++c)
      sum += relativeSquaredError(truth.pixels()[i][c], 0.5f * (a.pixels()[i][c] + b.pixels()[i][c]));
  return sum / (3.0 * double(truth.pixelCount()));
}

// Two independent halves of a known image with Gaussian noise of known variance (pixels of several
// brightnesses, 10% RMS relative noise per half): the estimate matches the true relMSE of their
// mean, measured against the truth, within 2% over 64k pixels, and the expected relMSE
// var(m) / (mu^2 + eps) too. A factor 2 wrong in either (the variance of a half taken for the
// mean's) would be 100% off.
TEST(HalvesNoise, EstimatesTheRelMseOfTheMeanOfTwoIndependentHalves) {
  const int w = 256, h = 256;
  Image truth(w, h), a(w, h), b(w, h);
  PCG32 rng(7);
  double expected = 0.0;
  for (std::size_t i = 0; i < truth.pixelCount(); ++i) {
    const float mu = 0.25f + 2.0f * float(i % 7);
    const float sigmaHalf = 0.1f * mu;  // each half's noise; the mean's variance is half of it squared
    truth.pixels()[i] = glm::vec4(glm::vec3(mu), 1.0f);
    for (int c = 0; c < 3; ++c) {
      a.pixels()[i][c] = mu + sigmaHalf * gaussian(rng);
      b.pixels()[i][c] = mu + sigmaHalf * gaussian(rng);
    }
    expected += 3.0 * (0.5 * double(sigmaHalf) * double(sigmaHalf)) / (double(mu) * mu + kRelMseEpsilon);
  }
  expected /= 3.0 * double(truth.pixelCount());
  const double estimate = halvesRelMseEstimate(a, b);
  EXPECT_NEAR(estimate / trueRelMse(truth, a, b), 1.0, 0.02);
  EXPECT_NEAR(estimate / expected, 1.0, 0.02);
  EXPECT_EQ(halvesRelMseEstimate(truth, truth), 0.0);
}

// The mask picks the pixels: noise only outside it is not seen.
TEST(HalvesNoise, OnlyTheMasksPixelsCount) {
  Image a(2, 1, glm::vec4(1.0f)), b(2, 1, glm::vec4(1.0f));
  a.at(1, 0) = glm::vec4(3.0f);
  const std::vector<std::uint8_t> first = {1, 0}, second = {0, 1};
  EXPECT_EQ(halvesRelMseEstimate(a, b, first), 0.0);
  EXPECT_NEAR(halvesRelMseEstimate(a, b, second), 1.0 / (4.0 + kRelMseEpsilon), 1e-6);
  EXPECT_THROW(halvesRelMseEstimate(a, b, std::vector<std::uint8_t>{0, 0}), Error);
  EXPECT_THROW(halvesRelMseEstimate(a, Image(1, 1)), Error);
}

// A part's estimate: the whole as its own part is the whole's estimate; a part that is the same in
// both halves carries no noise; half of the difference carries a quarter of it.
TEST(HalvesNoise, PartsOfTheImageCarryTheirShare) {
  PCG32 rng(5, 1);
  Image a(32, 16), b(32, 16), half(32, 16), halfB(32, 16);
  for (std::size_t i = 0; i < a.pixelCount(); ++i) {
    const float truth = 0.2f + float(i % 7);
    for (int c = 0; c < 3; ++c) {
      a.pixels()[i][c] = truth * (1.0f + 0.1f * gaussian(rng));
      b.pixels()[i][c] = truth * (1.0f + 0.1f * gaussian(rng));
      half.pixels()[i][c] = 0.5f * a.pixels()[i][c];
      halfB.pixels()[i][c] = 0.5f * b.pixels()[i][c];
    }
  }
  const double whole = halvesRelMseEstimate(a, b);
  EXPECT_NEAR(halvesPartRelMseEstimate(a, b, a, b), whole, 1e-6 * whole);
  EXPECT_EQ(halvesPartRelMseEstimate(a, a, a, b), 0.0);
  EXPECT_NEAR(halvesPartRelMseEstimate(half, halfB, a, b), 0.25 * whole, 1e-6 * whole);
  EXPECT_THROW(halvesPartRelMseEstimate(Image(2, 2), b, a, b), Error);
}

}  // namespace
}  // namespace iblkit
