#include "score/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.h"
#include "core/tone_curve.h"

namespace iblkit {

namespace {

bool scored(std::span<const std::uint8_t> mask, std::size_t i) { return mask.empty() || mask[i] != 0; }

void checkSizes(const Image& reference, const Image& test, std::span<const std::uint8_t> mask) {
  if (reference.width() != test.width() || reference.height() != test.height())
    throw Error("image metrics: reference and test differ in size");
  if (!mask.empty() && mask.size() != reference.pixelCount())
    throw Error("image metrics: mask and images differ in size");
}

// Mean over scored pixels and RGB channels of error(ref, test).
template <class PerChannel>
double meanChannelError(const Image& reference, const Image& test, std::span<const std::uint8_t> mask,
                        PerChannel error) {
  checkSizes(reference, test, mask);
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < reference.pixelCount(); ++i) {
    if (!scored(mask, i)) continue;
    for (int c = 0; c < 3; ++c) sum += error(double(reference.pixels()[i][c]), double(test.pixels()[i][c]));
    count += 3;
  }
  if (count == 0) throw Error("image metrics: the mask scores no pixel");
  return sum / double(count);
}

// Filters a plane with the normalised 11x11 Gaussian window of sigma 1.5 (separable), the image's
// border pixels repeated outside it.
std::vector<double> gaussianWindow(const std::vector<double>& plane, int width, int height) {
  constexpr int kRadius = 5;
  constexpr double kSigma = 1.5;
  double taps[2 * kRadius + 1], total = 0.0;
  for (int i = -kRadius; i <= kRadius; ++i)
    total += taps[i + kRadius] = std::exp(-i * i / (2.0 * kSigma * kSigma));
  for (double& t : taps) t /= total;
  const auto at = [width](int x, int y) {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
  };
  std::vector<double> rows(plane.size()), out(plane.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double sum = 0.0;
      for (int i = -kRadius; i <= kRadius; ++i)
        sum += taps[i + kRadius] * plane[at(std::clamp(x + i, 0, width - 1), y)];
      rows[at(x, y)] = sum;
    }
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double sum = 0.0;
      for (int j = -kRadius; j <= kRadius; ++j)
        sum += taps[j + kRadius] * rows[at(x, std::clamp(y + j, 0, height - 1))];
      out[at(x, y)] = sum;
    }
  return out;
}

}  // namespace

double meanSquaredError(const Image& reference, const Image& test, std::span<const std::uint8_t> mask) {
  return meanChannelError(reference, test, mask, [](double r, double t) { return (t - r) * (t - r); });
}

double relativeMeanSquaredError(const Image& reference, const Image& test,
                                std::span<const std::uint8_t> mask) {
  return meanChannelError(reference, test, mask, relativeSquaredError);
}

std::vector<float> relativeSquaredErrorMap(const Image& reference, const Image& test) {
  checkSizes(reference, test, {});
  std::vector<float> map(reference.pixelCount());
  for (std::size_t i = 0; i < map.size(); ++i) {
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) sum += relativeSquaredError(reference.pixels()[i][c], test.pixels()[i][c]);
    map[i] = static_cast<float>(sum / 3.0);
  }
  return map;
}

double peakSignalToNoiseRatio(double meanSquaredError) {
  if (meanSquaredError <= 0.0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(1.0 / meanSquaredError);
}

double structuralSimilarity(const Image& reference, const Image& test, std::span<const std::uint8_t> mask) {
  checkSizes(reference, test, mask);
  const int w = reference.width(), h = reference.height();
  const std::size_t n = reference.pixelCount();
  std::vector<double> x(n), y(n), xx(n), yy(n), xy(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = luminance(toneMap(glm::vec3(reference.pixels()[i]), ToneMapping{}));
    y[i] = luminance(toneMap(glm::vec3(test.pixels()[i]), ToneMapping{}));
    xx[i] = x[i] * x[i];
    yy[i] = y[i] * y[i];
    xy[i] = x[i] * y[i];
  }
  // Local statistics (eq. 14-16) as Gaussian-weighted moments.
  const std::vector<double> muX = gaussianWindow(x, w, h), muY = gaussianWindow(y, w, h);
  const std::vector<double> mXX = gaussianWindow(xx, w, h), mYY = gaussianWindow(yy, w, h),
                            mXY = gaussianWindow(xy, w, h);
  constexpr double kC1 = (0.01 * 1.0) * (0.01 * 1.0), kC2 = (0.03 * 1.0) * (0.03 * 1.0);  // (K L)^2, L = 1
  std::vector<float> map(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double varX = mXX[i] - muX[i] * muX[i], varY = mYY[i] - muY[i] * muY[i],
                 cov = mXY[i] - muX[i] * muY[i];
    map[i] = static_cast<float>((2.0 * muX[i] * muY[i] + kC1) * (2.0 * cov + kC2) /
                                ((muX[i] * muX[i] + muY[i] * muY[i] + kC1) * (varX + varY + kC2)));
  }
  return maskedMean(map, mask);
}

double meanRelativeLuminanceError(const Image& reference, const Image& test,
                                  std::span<const std::uint8_t> mask) {
  checkSizes(reference, test, mask);
  double difference = 0.0, total = 0.0;
  for (std::size_t i = 0; i < reference.pixelCount(); ++i) {
    if (!scored(mask, i)) continue;
    const double referenceLuminance = luminance(glm::vec3(reference.pixels()[i]));
    difference += std::abs(double(luminance(glm::vec3(test.pixels()[i]))) - referenceLuminance);
    total += referenceLuminance;
  }
  return total > 0.0 ? difference / total : 0.0;
}

std::size_t scoredPixelCount(std::span<const std::uint8_t> mask, std::size_t pixelCount) {
  return mask.empty()
             ? pixelCount
             : std::size_t(std::count_if(mask.begin(), mask.end(), [](std::uint8_t m) { return m != 0; }));
}

double maskedMean(std::span<const float> values, std::span<const std::uint8_t> mask) {
  if (!mask.empty() && mask.size() != values.size())
    throw Error("image metrics: mask and values differ in size");
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < values.size(); ++i)
    if (scored(mask, i)) {
      sum += values[i];
      ++count;
    }
  if (count == 0) throw Error("image metrics: the mask scores no pixel");
  return sum / double(count);
}

}  // namespace iblkit
