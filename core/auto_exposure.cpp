#include "core/auto_exposure.h"

#include <algorithm>
#include <cmath>

namespace iblkit {

std::optional<float> logAverageLuminance(const Image& image, std::span<const std::uint8_t> mask) {
  double sum = 0.0;
  std::size_t count = 0;
  const std::span<const glm::vec4> pixels = image.pixels();
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    if (!mask.empty() && !mask[i]) continue;
    const float y = luminance(glm::vec3(pixels[i]));
    if (!(y > 0.0f) || !std::isfinite(y)) continue;
    sum += std::log(double(y));
    ++count;
  }
  if (count == 0) return std::nullopt;
  return float(std::exp(sum / double(count)));
}

float keyExposure(const Image& image, std::span<const std::uint8_t> mask) {
  const std::optional<float> key = logAverageLuminance(image, mask);
  if (!key || !(*key > 0.0f)) return 0.0f;
  return std::clamp(float(std::log2(double(kMiddleGrey) / double(*key))), -16.0f, 16.0f);
}

}  // namespace iblkit
