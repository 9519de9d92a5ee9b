#include "reference/median_cut_sampler.h"

#include <algorithm>

namespace iblkit {

namespace {
// The largest float below 1: a rescaled u stays in [0, 1).
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;
}  // namespace

std::optional<int> medianCutLevelsOf(int regions) {
  for (int levels = 0; levels <= 12; ++levels)
    if (regions == 1 << levels) return levels;
  return std::nullopt;
}

MedianCutSampler::MedianCutSampler(const EnvironmentMap& map, int levels, bool misCompensation)
    : texels_(map), regions_(medianCutLights(map, levels)) {
  const int width = map.width();
  // As the environment sampler has them (environment_sampler.h), so the two densities are one.
  const std::vector<float> weights = texels_.samplingWeights(misCompensation, &compensated_);
  bilinear_ = !compensated_;
  regionOf_.assign(weights.size(), 0);
  std::vector<float> regionWeights;
  regionTexels_.reserve(regions_.size());
  for (std::size_t i = 0; i < regions_.size(); ++i) {
    const EnvironmentLight& r = regions_[i];
    std::vector<float> inside;
    inside.reserve(static_cast<std::size_t>(r.x1 - r.x0) * static_cast<std::size_t>(r.y1 - r.y0));
    double sum = 0.0;
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) {
        const std::size_t texel = static_cast<std::size_t>(y) * width + x;
        inside.push_back(weights[texel]);
        sum += weights[texel];
        regionOf_[texel] = static_cast<std::uint16_t>(i);
      }
    regionTexels_.emplace_back(inside, r.x1 - r.x0, r.y1 - r.y0);
    regionWeights.push_back(static_cast<float>(sum));
  }
  regionDistribution_ = PiecewiseConstant1D(regionWeights);
}

float MedianCutSampler::regionProbability(int i) const {
  const std::span<const float> cdf = regionDistribution_.cdf();
  return cdf[static_cast<std::size_t>(i) + 1] - cdf[static_cast<std::size_t>(i)];
}

float MedianCutSampler::uvPdf(int i, int x, int y) const {
  const EnvironmentLight& r = regions_[static_cast<std::size_t>(i)];
  const float columns = static_cast<float>(r.x1 - r.x0), rows = static_cast<float>(r.y1 - r.y0);
  // The region's density is constant on each of its texels: read it at the texel's centre.
  const glm::vec2 centre((static_cast<float>(x - r.x0) + 0.5f) / columns,
                         (static_cast<float>(y - r.y0) + 0.5f) / rows);
  const float areaScale = static_cast<float>(texels_.map().width()) / columns *
                          (static_cast<float>(texels_.map().height()) / rows);
  return regionProbability(i) * regionTexels_[static_cast<std::size_t>(i)].pdf(centre) * areaScale;
}

MedianCutSampler::Sample MedianCutSampler::sample(glm::vec2 u) const {
  const PiecewiseConstant1D::Sample picked = regionDistribution_.sample(u.x);
  const int i = picked.offset;
  const EnvironmentLight& r = regions_[static_cast<std::size_t>(i)];
  // u.x's place inside the region's CDF interval, reused for the texel.
  const float rescaled =
      std::clamp(picked.x * static_cast<float>(regionDistribution_.size()) - static_cast<float>(i), 0.0f,
                 kOneMinusEpsilon);
  const PiecewiseConstant2D::Sample s = regionTexels_[static_cast<std::size_t>(i)].sample({rescaled, u.y});
  const int x = r.x0 + s.offset.x, y = r.y0 + s.offset.y;
  const float rows = static_cast<float>(r.y1 - r.y0), columns = static_cast<float>(r.x1 - r.x0);
  glm::vec2 within(std::clamp(s.p.x * columns - static_cast<float>(s.offset.x), 0.0f, 1.0f),
                   std::clamp(s.p.y * rows - static_cast<float>(s.offset.y), 0.0f, 1.0f));
  float density = 1.0f;
  if (bilinear_) {
    const EnvironmentTexels::WithinTexel w = texels_.sampleWithin({x, y}, within);
    within = w.point;
    density = w.density;
  }
  const float u0 = (static_cast<float>(x) + within.x) / static_cast<float>(texels_.map().width());
  const EnvironmentTexels::Point point = texels_.pointInRow(u0, y, within.y);
  return {point.direction, point.radiance, texels_.solidAnglePdf(uvPdf(i, x, y) * density, y)};
}

float MedianCutSampler::pdf(const glm::vec3& worldDirection) const { return lookup(worldDirection).pdf; }

MedianCutSampler::Lookup MedianCutSampler::lookup(const glm::vec3& worldDirection) const {
  const EnvironmentTexels::Location at = texels_.locate(worldDirection);
  const int i = regionOf_[static_cast<std::size_t>(at.texel.y) * texels_.map().width() + at.texel.x];
  const float density = bilinear_ ? texels_.densityAtUv(at.texel, at.uv) : 1.0f;
  return {at.radiance, texels_.solidAnglePdf(uvPdf(i, at.texel.x, at.texel.y) * density, at.texel.y)};
}

}  // namespace iblkit
