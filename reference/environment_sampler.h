#pragma once
// Importance sampling of a lat-long environment map (the reference path tracer's light sampler).
//
// Texels are drawn from a piecewise-constant distribution proportional to their weights
// (marginal over rows, conditional over columns: PiecewiseConstant2D), the standard inverted-CDF
// construction (pbrt-v4 13.6 / Mitsuba 3 `envmap`). The weights are each texel's mean bilinear
// luminance x solid angle, and the point inside the texel is drawn by the bilinear luminance itself
// (EnvironmentTexels::sampleWithin), the row's fraction picking cos(theta) linearly between the
// row's edges, not theta: the density per steradian is that bilinear function over its mean times
//   pdf_uv(texel) / (2 pi H (cos theta_top - cos theta_bottom)),
// so a constant map is sampled exactly uniformly over the sphere (the usual uniform-in-theta row,
// with its density pdf_uv / (2 pi^2 sin theta), varies by 2x and more across the rows nearest the
// poles of a small map, which costs the white furnace test its noise floor). With MIS compensation
// the weights are the compensated maxima and the point inside a texel is uniform. Weights and
// points are EnvironmentTexels' (environment_texels.h), shared with the median-cut sampler.
//
// Oriented sampling (oriented_environment.h): with LightOrientation::ByNormal the sampler also
// has a distribution per bucket of normals (normal_buckets.h), the weights times a bound of the
// cosine with the bucket's normals, for next-event estimation at a vertex whose normal is known.
// The *(bucket, ...) calls take bucketOf(normal); a bucket of kNoBucket is the plain sampler.
//
// MIS compensation (Karlik et al. 2019, "MIS Compensation: Optimizing Sampling Techniques in
// Multiple Importance Sampling") leaves directions that BRDF sampling finds well to it: only valid
// combined with BRDF sampling by MIS.

#include <glm/glm.hpp>
#include <vector>

#include "core/distribution.h"
#include "core/enum_names.h"
#include "core/environment_map.h"
#include "reference/environment_texels.h"
#include "reference/oriented_environment.h"

#include <mutex>
#include <optional>

namespace iblkit {

enum class LightOrientation { None, ByNormal };
inline constexpr EnumName<LightOrientation> kLightOrientationNames[] = {{LightOrientation::None, "none"},
                                                                        {LightOrientation::ByNormal, "normal"}};

class EnvironmentSampler {
 public:
  // Keeps a reference to `map`, which must outlive the sampler. A black map is never oriented.
  explicit EnvironmentSampler(const EnvironmentMap& map, bool misCompensation = false,
                              LightOrientation orientation = LightOrientation::ByNormal);
  EnvironmentSampler(const EnvironmentSampler&) = delete;
  EnvironmentSampler& operator=(const EnvironmentSampler&) = delete;

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
  Lookup lookup(const glm::vec3& worldDirection) const { return lookupAt(mapUv(worldDirection)); }
  // The lat-long coordinates lookup(w) finds w at, and lookup(w) from them.
  glm::vec2 mapUv(const glm::vec3& worldDirection) const { return texels_.mapUv(worldDirection); }
  Lookup lookupAt(glm::vec2 uv) const;

  // Software prefetch for a batch of lookups, so that their cache misses overlap instead of each
  // waiting for its own (the integrator's escaping rays): what lookupAt(uv) reads. It changes no
  // result.
  void prefetchLookup(glm::vec2 uv) const;

  // Oriented sampling, for a vertex whose shading normal lies in `bucket` (bucketOf(normal)):
  // the same results as above for bucket == kNoBucket.
  static constexpr int kNoBucket = -1;
  bool oriented() const { return oriented_.has_value(); }
  // The bucket of a non-zero normal; kNoBucket when the sampler is not oriented.
  int bucketOf(const glm::vec3& normal) const { return oriented_ ? NormalBuckets::of(normal) : kNoBucket; }
  Sample sample(int bucket, glm::vec2 u) const;
  // The same draw, but empty (pdf 0) where it can be known from the oriented sampler's cell alone
  // that the direction lies outside the cone of world directions about the unit `axis` with
  // cos(half-angle) `cosRadius` (OrientedEnvironment::sample's `within`); every direction it does
  // return is the one sample(bucket, u) returns. Without an oriented sampler, sample(bucket, u).
  Sample sampleWithin(int bucket, glm::vec2 u, const glm::vec3& axis, float cosRadius) const;
  float pdf(int bucket, const glm::vec3& worldDirection) const;
  Lookup lookupAt(int bucket, glm::vec2 uv) const;
  void prefetchLookup(int bucket, glm::vec2 uv) const;
  const OrientedEnvironment* orientedTables() const { return oriented_ ? &*oriented_ : nullptr; }

  // True when the map is black everywhere: the sampler then samples uniformly in (u, v).
  bool isBlack() const { return black_; }
  bool misCompensated() const { return compensated_; }

 private:
  // The direction at point `within` of `texel` (uniform, or warped by the bilinear luminance),
  // whose texel has density pdfUv per unit (u, v) area.
  Sample pointIn(glm::ivec2 texel, glm::vec2 within, float pdfUv) const;
  // sample(bucket, u), stopped early outside `within` when it is set (sampleWithin).
  Sample sampleOriented(int bucket, glm::vec2 u, const OrientedEnvironment::DirectionCone* within) const;
  // The within-texel density of the point a lookup found (1 unless bilinear).
  float withinDensity(const EnvironmentTexels::Location& at) const;

  // The plain sampler's distribution over the texels, built on first use (by then from the
  // oriented tables' weights): an oriented sampler's integrator never reads it (every vertex has a
  // bucket), and on a large map it is 12 bytes a texel (the function, the CDF and the guide):
  // 384 MiB for 8192 x 4096.
  const PiecewiseConstant2D& plain() const;

  EnvironmentTexels texels_;
  bool compensated_ = false;
  bool bilinear_ = false;  // the point inside a texel by the bilinear luminance (uncompensated maps)
  bool black_ = false;
  mutable std::once_flag plainBuilt_;
  mutable std::optional<PiecewiseConstant2D> distribution_;
  std::optional<OrientedEnvironment> oriented_;
};

}  // namespace iblkit
