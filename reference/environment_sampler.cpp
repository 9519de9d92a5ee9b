#include "reference/environment_sampler.h"

#include <algorithm>

namespace iblkit {

EnvironmentSampler::EnvironmentSampler(const EnvironmentMap& map, bool misCompensation,
                                       LightOrientation orientation)
    : texels_(map), distribution_(std::vector<float>{0.0f}, 1, 1) {
  const std::vector<float> weights = texels_.weights(misCompensation, &compensated_);
  distribution_ = PiecewiseConstant2D(weights, map.width(), map.height());
  black_ = distribution_.integral() <= 0.0f;
  if (orientation == LightOrientation::ByNormal && !black_) oriented_.emplace(texels_, weights);
}

EnvironmentSampler::Sample EnvironmentSampler::sample(glm::vec2 u) const {
  const PiecewiseConstant2D::Sample s = distribution_.sample(u);
  // Uniform over the texel's solid angle: the fraction of the way down the row, linear in cos(theta).
  const float along = std::clamp(
      s.p.y * static_cast<float>(distribution_.height()) - static_cast<float>(s.offset.y), 0.0f, 1.0f);
  const EnvironmentTexels::Point point = texels_.pointInRow(s.p.x, s.offset.y, along);
  return {point.direction, point.radiance, texels_.solidAnglePdf(s.pdf, s.offset.y)};
}

float EnvironmentSampler::pdf(const glm::vec3& worldDirection) const { return lookup(worldDirection).pdf; }

EnvironmentSampler::Lookup EnvironmentSampler::lookupAt(glm::vec2 uv) const {
  const EnvironmentTexels::Location at = texels_.locateUv(uv);
  return {at.radiance, texels_.solidAnglePdf(distribution_.pdf(at.uv), at.texel.y)};
}

void EnvironmentSampler::prefetchSample(glm::vec2 u, int stage) const {
  const glm::ivec2 cell = distribution_.prefetchSample(u, stage);
  if (cell.x >= 0) texels_.prefetchAround(cell);
}

void EnvironmentSampler::prefetchLookup(glm::vec2 uv) const {
  distribution_.prefetchPdf(uv);
  texels_.prefetchAround(texels_.texelAt(uv));
}

}  // namespace iblkit

namespace iblkit {

EnvironmentSampler::Sample EnvironmentSampler::sample(int bucket, glm::vec2 u) const {
  if (bucket == kNoBucket) return sample(u);
  const OrientedEnvironment::Pick pick = oriented_->sample(bucket, u);
  if (pick.pdfUv <= 0.0f) return {};
  const float along = (static_cast<float>(pick.texel.x) + pick.within.x) / static_cast<float>(texels_.map().width());
  const EnvironmentTexels::Point point = texels_.pointInRow(along, pick.texel.y, pick.within.y);
  return {point.direction, point.radiance, texels_.solidAnglePdf(pick.pdfUv, pick.texel.y)};
}

float EnvironmentSampler::pdf(int bucket, const glm::vec3& worldDirection) const {
  return lookupAt(bucket, mapUv(worldDirection)).pdf;
}

EnvironmentSampler::Lookup EnvironmentSampler::lookupAt(int bucket, glm::vec2 uv) const {
  if (bucket == kNoBucket) return lookupAt(uv);
  const EnvironmentTexels::Location at = texels_.locateUv(uv);
  return {at.radiance, texels_.solidAnglePdf(oriented_->pdfUv(bucket, at.texel), at.texel.y)};
}

void EnvironmentSampler::prefetchSample(int bucket, glm::vec2 u, int stage) const {
  if (bucket == kNoBucket) return prefetchSample(u, stage);
  oriented_->prefetchSample(bucket, u, stage);
}

void EnvironmentSampler::prefetchLookup(int bucket, glm::vec2 uv) const {
  if (bucket == kNoBucket) return prefetchLookup(uv);
  const glm::ivec2 texel = texels_.texelAt(uv);
  oriented_->prefetchPdf(bucket, texel);
  texels_.prefetchAround(texel);
}

}  // namespace iblkit
