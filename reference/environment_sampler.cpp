#include "reference/environment_sampler.h"

#include <algorithm>

namespace iblkit {

EnvironmentSampler::EnvironmentSampler(const EnvironmentMap& map, bool misCompensation)
    : texels_(map),
      distribution_(texels_.weights(misCompensation, &compensated_), map.width(), map.height()) {
  black_ = distribution_.integral() <= 0.0f;
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
