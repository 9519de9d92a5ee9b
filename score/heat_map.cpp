#include "score/heat_map.h"

#include <algorithm>

#include "core/color_map.h"
#include "core/error.h"
#include "core/image_io.h"

namespace iblkit {

Image heatMapImage(std::span<const float> values, int width, int height, float maxValue) {
  if (width < 1 || height < 1 ||
      values.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    throw Error("heatMapImage: values do not match the size");
  if (!(maxValue > 0.0f)) throw Error("heatMapImage: maxValue must be positive");
  const int band = std::max(4, height / 16);
  Image image(width, height + 2 * band, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      image.at(x, y) = glm::vec4(magma(values[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                              static_cast<std::size_t>(x)] /
                                       maxValue),
                                 1.0f);
  for (int x = 0; x < width; ++x) {
    const float t = width == 1 ? 0.0f : float(x) / float(width - 1);
    // A tick where t crosses a quarter: the column whose interval [t, t + dt) holds it.
    const float next = width == 1 ? 1.0f : float(x + 1) / float(width - 1);
    bool tick = false;
    for (float q : {0.25f, 0.5f, 0.75f}) tick = tick || (t <= q && q < next);
    for (int y = height + band; y < height + 2 * band; ++y)
      image.at(x, y) = tick && y < height + band + band / 2 ? glm::vec4(1.0f) : glm::vec4(magma(t), 1.0f);
  }
  return image;
}

void writeHeatMap(const std::filesystem::path& file, std::span<const float> values, int width, int height,
                  float maxValue) {
  writePng(file, heatMapImage(values, width, height, maxValue), ToneMapping{0.0f, ToneCurve::Clamp});
}

}  // namespace iblkit
