#include "reference/pixel_filter.h"

#include <cmath>
#include <vector>

#include "core/error.h"

namespace iblkit {

namespace {

float gaussian(float x) {
  constexpr float s = PixelFilter::kGaussianSigma;
  return std::exp(-x * x / (2.0f * s * s));
}

// The truncated Gaussian averaged over each of the table's cells (Simpson's rule, exact enough
// for a function this smooth on cells of 3/256 pixel).
std::vector<float> gaussianTable() {
  constexpr float r = PixelFilter::kGaussianRadius;
  constexpr int n = PixelFilter::kTableCells;
  const float floor = gaussian(r);
  std::vector<float> table(n);
  for (int i = 0; i < n; ++i) {
    const float a = -r + 2.0f * r * static_cast<float>(i) / n,
                b = -r + 2.0f * r * static_cast<float>(i + 1) / n;
    const float mean = (gaussian(a) + 4.0f * gaussian(0.5f * (a + b)) + gaussian(b)) / 6.0f;
    table[static_cast<std::size_t>(i)] = std::max(0.0f, mean - floor);
  }
  return table;
}

std::vector<float> boxTable() { return {1.0f}; }

}  // namespace

PixelFilterKind parsePixelFilter(const std::string& name) {
  return parseEnumName(kPixelFilterNames, name, "--filter", "filter");
}

PixelFilter::PixelFilter(PixelFilterKind kind)
    : kind_(kind), axis_(kind == PixelFilterKind::Gaussian ? gaussianTable() : boxTable()) {}

glm::vec2 PixelFilter::sample(glm::vec2 u) const {
  if (kind_ == PixelFilterKind::Box) return u;
  const float diameter = 2.0f * kGaussianRadius;
  return glm::vec2(axis_.sample(u.x).x, axis_.sample(u.y).x) * diameter + (0.5f - kGaussianRadius);
}

float PixelFilter::pdf(glm::vec2 offset) const {
  const float r = radius();
  if (std::fabs(offset.x) > r || std::fabs(offset.y) > r) return 0.0f;
  if (kind_ == PixelFilterKind::Box) return 1.0f;
  const float diameter = 2.0f * r;
  const glm::vec2 unit = (offset + r) / diameter;
  return axis_.pdf(unit.x) * axis_.pdf(unit.y) / (diameter * diameter);
}

}  // namespace iblkit
