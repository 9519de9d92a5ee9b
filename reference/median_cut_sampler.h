#pragma once
// Median-cut importance sampling of a lat-long environment map (--env-sampling mediancut;
// docs/reference-tracer.md "Median-cut sampling"): the map is cut into 2^levels regions of equal
// energy (medianCutLights, Debevec 2005, core/environment_lights.h); a sample picks a region by its
// power, then a texel inside it by the region's own piecewise-constant distribution, then the
// point inside the texel by its bilinear luminance, as EnvironmentSampler draws it (EnvironmentTexels,
// shared with EnvironmentSampler). The region is chosen with u.x, which is then rescaled to [0,1) and, with u.y,
// picks the texel (marginal over the region's rows, conditional over its columns), so one 2D sample
// does all three steps and a stratified u spreads the samples evenly over the equal-energy regions.
//
// A region's power is the sum of the sampler's texel weights inside it (the mean bilinear luminance
// x solid angle of EnvironmentTexels; the compensated maxima when asked), not the light's own luminance
// power: a region whose texels are black can still receive bilinear radiance across its border,
// and must keep a non-zero density there. The density of texel t in region r is then
//   P(r) p(t | r) = (W_r / W) (w_t / W_r) = w_t / W,
// the same as EnvironmentSampler's: the two draw the same distribution through different warps of
// [0,1)^2, and the estimator is unbiased wherever EnvironmentSampler's is. The pdf is exact:
//   pdf(w) = P(r) pdf_r(texel) (W / w_r) (H / h_r) / (2 pi H (cos theta_top - cos theta_bottom)),
// pdf_r the region's density per unit of its own [0,1)^2 and w_r x h_r its size in texels.

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "core/distribution.h"
#include "core/environment_lights.h"
#include "core/environment_map.h"
#include "reference/environment_sampler.h"
#include "reference/environment_texels.h"

namespace iblkit {

// The median-cut levels that give `regions` regions (--env-lights): log2(regions) for a power of 2
// in 1..4096, nothing otherwise.
std::optional<int> medianCutLevelsOf(int regions);

class MedianCutSampler {
 public:
  // Keeps a reference to `map`, which must outlive the sampler. levels in [0, 12] (throws
  // std::invalid_argument otherwise, as medianCutLights does).
  MedianCutSampler(const EnvironmentMap& map, int levels, bool misCompensation = false);

  using Sample = EnvironmentSampler::Sample;
  using Lookup = EnvironmentSampler::Lookup;
  // Draws a direction from u in [0,1)^2.
  Sample sample(glm::vec2 u) const;
  // Density per steradian of sampling world direction w (any non-zero length).
  float pdf(const glm::vec3& worldDirection) const;
  // map.radiance(w) and pdf(w) together.
  Lookup lookup(const glm::vec3& worldDirection) const;

  // The regions, as medianCutLights returns them for this map and level count.
  const std::vector<EnvironmentLight>& regions() const { return regions_; }
  // The probability of picking region i.
  float regionProbability(int i) const;
  bool misCompensated() const { return compensated_; }

 private:
  // The region's density per unit area of the whole map's (u, v) at texel (x, y) of region i.
  float uvPdf(int i, int x, int y) const;

  EnvironmentTexels texels_;
  bool compensated_ = false;
  bool bilinear_ = false;  // texels by their mean bilinear luminance, the point inside by the luminance itself
  std::vector<EnvironmentLight> regions_;
  std::vector<PiecewiseConstant2D> regionTexels_;  // per region, over its own texels
  // Over the regions, by their summed weights; built in the constructor's body, after the
  // regions' own distributions, from the same pass over the texel weights.
  PiecewiseConstant1D regionDistribution_{std::vector<float>{1.0f}};
  std::vector<std::uint16_t> regionOf_;  // per texel (row by row): its region
};

}  // namespace iblkit
