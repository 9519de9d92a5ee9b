#include "core/halves_noise.h"

#include "core/error.h"
#include "core/relative_squared_error.h"

namespace iblkit {

double halvesRelMseEstimate(const Image& a, const Image& b, std::span<const std::uint8_t> mask) {
  if (a.width() != b.width() || a.height() != b.height())
    fail("halvesRelMseEstimate", "halves differ in size");
  if (!mask.empty() && mask.size() != a.pixelCount())
    fail("halvesRelMseEstimate", "mask and halves differ in size");
  double sum = 0.0;
  std::size_t pixels = 0;
  for (std::size_t i = 0; i < a.pixelCount(); ++i) {
    if (!mask.empty() && mask[i] == 0) continue;
    ++pixels;
    const glm::vec4 pa = a.pixels()[i], pb = b.pixels()[i];
    // (a - m)^2 = (a - b)^2 / 4; m in float, as the mean image holds it.
    for (int c = 0; c < 3; ++c) sum += relativeSquaredError(0.5f * (pa[c] + pb[c]), pa[c]);
  }
  if (pixels == 0) fail("halvesRelMseEstimate", "the mask scores no pixel");
  return sum / (3.0 * double(pixels));
}

double halvesPartRelMseEstimate(const Image& aPart, const Image& bPart, const Image& a, const Image& b,
                                std::span<const std::uint8_t> mask) {
  for (const Image* image : {&b, &aPart, &bPart})
    if (image->width() != a.width() || image->height() != a.height())
      fail("halvesPartRelMseEstimate", "halves and parts differ in size");
  if (!mask.empty() && mask.size() != a.pixelCount())
    fail("halvesPartRelMseEstimate", "mask and halves differ in size");
  double sum = 0.0;
  std::size_t pixels = 0;
  for (std::size_t i = 0; i < a.pixelCount(); ++i) {
    if (!mask.empty() && mask[i] == 0) continue;
    ++pixels;
    const glm::vec4 pa = a.pixels()[i], pb = b.pixels()[i], qa = aPart.pixels()[i], qb = bPart.pixels()[i];
    for (int c = 0; c < 3; ++c) {
      const double m = 0.5 * (double(pa[c]) + double(pb[c])), d = 0.5 * (double(qa[c]) - double(qb[c]));
      sum += d * d / (m * m + kRelMseEpsilon);
    }
  }
  if (pixels == 0) fail("halvesPartRelMseEstimate", "the mask scores no pixel");
  return sum / (3.0 * double(pixels));
}

}  // namespace iblkit
