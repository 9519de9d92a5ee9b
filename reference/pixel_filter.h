#pragma once
// The pixel reconstruction filter of the reference renderer (--filter box|gaussian), applied by
// filter importance sampling (Ernst, Stamminger and Greiner 2006, "Filter Importance Sampling";
// pbrt-v4's FilterSampler): each camera sample's position in the pixel is drawn from the filter
// itself, so every sample weighs 1 and a pixel stays the plain mean of its samples (its variance
// layer and the thread-count independence keep working).
//
//   box       offsets uniform in [-0.5, 0.5)^2: the pixel's own square.
//   gaussian  separable, sigma = 0.5 pixel, truncated at radius 1.5 pixels and shifted down to 0
//             there (pbrt-v4's GaussianFilter): exp(-x^2 / (2 sigma^2)) - exp(-r^2 / (2 sigma^2))
//             per axis. Sampled from a 256-cell piecewise-constant table per axis, whose density
//             pdf() returns.

#include <glm/glm.hpp>
#include <string>

#include "core/distribution.h"
#include "core/enum_names.h"

namespace iblkit {

enum class PixelFilterKind { Box, Gaussian };

inline constexpr EnumName<PixelFilterKind> kPixelFilterNames[] = {{PixelFilterKind::Box, "box"},
                                                                  {PixelFilterKind::Gaussian, "gaussian"}};

// A name of the table above; anything else throws Error("--filter: unknown filter 'x' (expected
// one of box, gaussian)").
PixelFilterKind parsePixelFilter(const std::string& name);

class PixelFilter {
 public:
  static constexpr float kGaussianSigma = 0.5f;
  static constexpr float kGaussianRadius = 1.5f;
  static constexpr int kTableCells = 256;

  explicit PixelFilter(PixelFilterKind kind = PixelFilterKind::Box);

  PixelFilterKind kind() const { return kind_; }
  // Half-width of the filter's support, in pixels (0.5 for box).
  float radius() const { return kind_ == PixelFilterKind::Box ? 0.5f : kGaussianRadius; }
  // A sample position relative to the pixel's corner (its centre is (0.5, 0.5)), in pixels, for u
  // in [0, 1)^2. Box returns u itself, so box renders are those of a plain uniform jitter.
  glm::vec2 sample(glm::vec2 u) const;
  // Density of sample() per unit area (pixels^2) at `offset` from the pixel's centre; 0 outside
  // the support.
  float pdf(glm::vec2 offset) const;

 private:
  PixelFilterKind kind_;
  PiecewiseConstant1D axis_;  // gaussian: the table over [-radius, radius] mapped to [0, 1]
};

}  // namespace iblkit
