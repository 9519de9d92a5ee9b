#pragma once
// Importance sampling of a lat-long environment map (the reference path tracer's light sampler).
//
// Texels are drawn from a piecewise-constant distribution proportional to luminance x solid
// angle (marginal over rows, conditional over columns: PiecewiseConstant2D), the standard
// inverted-CDF construction (pbrt-v4 13.6 / Mitsuba 3 `envmap`). Within the chosen texel the
// direction is uniform over its solid angle: the row's fraction picks cos(theta) linearly between
// the row's edges, not theta. The density per steradian is then exactly constant on each texel,
//   pdf(w) = pdf_uv(texel) / (2 pi H (cos theta_top - cos theta_bottom)),
// so a constant map is sampled exactly uniformly over the sphere (the usual uniform-in-theta row,
// with its density pdf_uv / (2 pi^2 sin theta), varies by 2x and more across the rows nearest the
// poles of a small map, which costs the white furnace test its noise floor).
// Lookups are bilinear, which spreads a texel's radiance into its neighbours; each texel's weight
// is therefore the maximum luminance of its 3x3 neighbourhood (wrapped in longitude), so the pdf
// is non-zero wherever the looked-up radiance is (no bias when used alone).
//
// MIS compensation (Karlik et al. 2019, "MIS Compensation: Optimizing Sampling Techniques in
// Multiple Importance Sampling"; pbrt-v4's ImageInfiniteLight, Mitsuba 3's `mis_compensation`):
// the mean weight is subtracted, keeping a floor of 0.1% of the mean, so directions that BRDF
// sampling finds well are left to it. Only valid combined with BRDF sampling by MIS; it is skipped
// for near-constant maps (max - min <= 1% of the mean), where it would leave almost nothing.

#include <glm/glm.hpp>
#include <vector>

#include "core/distribution.h"
#include "core/environment_map.h"

namespace iblkit {

class EnvironmentSampler {
 public:
  // Keeps a reference to `map`, which must outlive the sampler.
  explicit EnvironmentSampler(const EnvironmentMap& map, bool misCompensation = false);

  struct Sample {
    glm::vec3 direction{0.0f};  // world direction, unit length
    glm::vec3 radiance{0.0f};   // map.radiance(direction)
    float pdf = 0.0f;           // per steradian; 0 only at the exact poles
  };
  // Draws a direction from u in [0,1)^2.
  Sample sample(glm::vec2 u) const;
  // Density per steradian of sampling world direction w (any non-zero length).
  float pdf(const glm::vec3& worldDirection) const;
  // map.radiance(w) and pdf(w) together, from one lat-long lookup (what a path that escapes in
  // direction w needs for its MIS weight).
  struct Lookup {
    glm::vec3 radiance{0.0f};
    float pdf = 0.0f;
  };
  Lookup lookup(const glm::vec3& worldDirection) const;

  // True when the map is black everywhere: the sampler then samples uniformly in (u, v).
  bool isBlack() const { return black_; }
  bool misCompensated() const { return compensated_; }

 private:
  // Luminance (3x3 maximum) x solid angle per texel; rowCosTheta: the rows' edges (rowCosTheta_).
  static std::vector<float> texelWeights(const EnvironmentMap& map, const std::vector<float>& rowCosTheta,
                                         bool misCompensation, bool* compensated);
  // Density per steradian of a direction in the texel row `row` whose density in (u, v) is pdfUv.
  float solidAnglePdf(float pdfUv, int row) const { return pdfUv * rowPdfScale_[static_cast<std::size_t>(row)]; }

  const EnvironmentMap& map_;
  bool compensated_ = false;
  bool black_ = false;
  std::vector<float> rowCosTheta_;   // height + 1 row edges: cos of the polar angle from +Y, 1 to -1
  PiecewiseConstant2D distribution_;
  std::vector<float> rowPdfScale_;   // per row: 1 / (2 pi H (rowCosTheta_[y] - rowCosTheta_[y + 1]))
};

}  // namespace iblkit
