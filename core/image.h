#pragma once
// Image: a 2D grid of linear RGBA float pixels, row 0 at the top (the OpenEXR, PNG and Radiance
// convention). Radiance is linear Rec.709 (docs/conventions.md). Alpha is coverage: 1 where a
// surface or the sky is, used by the scorer as a mask.

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace iblkit {

class Image {
public:
  Image() = default;
  Image(int width, int height, glm::vec4 fill = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return pixels_.empty(); }
  std::size_t pixelCount() const { return pixels_.size(); }

  glm::vec4& at(int x, int y) { return pixels_[index(x, y)]; }
  const glm::vec4& at(int x, int y) const { return pixels_[index(x, y)]; }

  std::vector<glm::vec4>& pixels() { return pixels_; }
  const std::vector<glm::vec4>& pixels() const { return pixels_; }

  // Pixel statistics over RGB (alpha ignored).
  struct Stats {
    glm::vec3 min{0.0f}, max{0.0f}, mean{0.0f};
    float maxLuminance = 0.0f, meanLuminance = 0.0f;
  };
  Stats stats() const;

private:
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
  }
  int width_ = 0, height_ = 0;
  std::vector<glm::vec4> pixels_;
};

// Relative luminance of linear Rec.709 RGB (ITU-R BT.709 weights).
inline float luminance(const glm::vec3& rgb) { return glm::dot(rgb, glm::vec3(0.2126f, 0.7152f, 0.0722f)); }

// Box-filtered half-size image (odd sizes round up; the last row/column is reused). Used for mips.
Image downsample2x(const Image& image);

}  // namespace iblkit
