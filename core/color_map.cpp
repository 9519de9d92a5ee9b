#include "core/color_map.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/tone_curve.h"

namespace iblkit {

glm::vec3 magma(float t) {
  // Six evenly spaced samples of the published map (the sRGB hex codes #000004, #3b0f70, #8c2981,
  // #de4968, #fe9f6d, #fcfdbf), interpolated in sRGB, where the map is defined.
  static constexpr unsigned kSamples[] = {0x000004, 0x3b0f70, 0x8c2981, 0xde4968, 0xfe9f6d, 0xfcfdbf};
  constexpr int kLast = static_cast<int>(std::size(kSamples)) - 1;
  const auto srgb = [](unsigned hex) {
    return glm::vec3(float((hex >> 16) & 0xff), float((hex >> 8) & 0xff), float(hex & 0xff)) / 255.0f;
  };
  const float x = (std::isnan(t) ? 0.0f : std::clamp(t, 0.0f, 1.0f)) * kLast;
  const int i = std::min(static_cast<int>(x), kLast - 1);
  const glm::vec3 encoded = glm::mix(srgb(kSamples[i]), srgb(kSamples[i + 1]), x - float(i));
  return {srgbDecode(encoded.r), srgbDecode(encoded.g), srgbDecode(encoded.b)};
}

}  // namespace iblkit
