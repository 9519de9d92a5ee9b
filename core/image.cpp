#include "core/image.h"

#include <algorithm>
#include <limits>

namespace iblkit {

Image::Image(int width, int height, glm::vec4 fill)
    : width_(width), height_(height),
      pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill) {}

Image::Stats Image::stats() const {
  Stats s;
  if (pixels_.empty()) return s;
  s.min = glm::vec3(std::numeric_limits<float>::max());
  s.max = glm::vec3(std::numeric_limits<float>::lowest());
  glm::dvec3 sum(0.0);
  double sumLuminance = 0.0;
  for (const glm::vec4& p : pixels_) {
    const glm::vec3 rgb(p);
    s.min = glm::min(s.min, rgb);
    s.max = glm::max(s.max, rgb);
    sum += glm::dvec3(rgb);
    const float y = luminance(rgb);
    s.maxLuminance = std::max(s.maxLuminance, y);
    sumLuminance += y;
  }
  const double n = static_cast<double>(pixels_.size());
  s.mean = glm::vec3(sum / n);
  s.meanLuminance = static_cast<float>(sumLuminance / n);
  return s;
}

Image downsample2x(const Image& image) {
  const int w = std::max(1, (image.width() + 1) / 2), h = std::max(1, (image.height() + 1) / 2);
  Image out(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      glm::vec4 sum(0.0f);
      for (int dy = 0; dy < 2; ++dy) {
        for (int dx = 0; dx < 2; ++dx) {
          const int sx = std::min(2 * x + dx, image.width() - 1), sy = std::min(2 * y + dy, image.height() - 1);
          sum += image.at(sx, sy);
        }
      }
      out.at(x, y) = sum * 0.25f;
    }
  }
  return out;
}

}  // namespace iblkit
