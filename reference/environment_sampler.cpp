#include "reference/environment_sampler.h"

#include <algorithm>

namespace iblkit {

EnvironmentSampler::EnvironmentSampler(const EnvironmentMap& map, bool misCompensation,
                                       LightOrientation orientation)
    : texels_(map) {
  // Uncompensated: each texel by its mean bilinear luminance and the point inside it by the
  // bilinear luminance itself (EnvironmentTexels::sampleWithin), so the density follows the
  // lookups' radiance instead of being flat across a texel next to a sun.
  std::vector<float> weights = texels_.samplingWeights(misCompensation, &compensated_);
  bilinear_ = !compensated_;
  // Black: every weight 0 (the weights are finite and non-negative: the map's radiance is).
  black_ = std::none_of(weights.begin(), weights.end(), [](float w) { return w > 0.0f; });
  if (black_) bilinear_ = false;
  if (orientation == LightOrientation::ByNormal && !black_) {
    oriented_.emplace(texels_, std::move(weights));
    return;
  }
  // Built here, through the flag, so that plain() does not build it again.
  std::call_once(plainBuilt_, [&] { distribution_.emplace(weights, map.width(), map.height()); });
}

const PiecewiseConstant2D& EnvironmentSampler::plain() const {
  std::call_once(plainBuilt_, [&] {
    distribution_.emplace(oriented_->weights(), texels_.map().width(), texels_.map().height());
  });
  return *distribution_;
}

EnvironmentSampler::Sample EnvironmentSampler::pointIn(glm::ivec2 texel, glm::vec2 within, float pdfUv) const {
  if (bilinear_) {
    const EnvironmentTexels::WithinTexel w = texels_.sampleWithin(texel, within);
    within = w.point;
    pdfUv *= w.density;
  }
  const float across = (static_cast<float>(texel.x) + within.x) / static_cast<float>(texels_.map().width());
  const EnvironmentTexels::Point point = texels_.pointInRow(across, texel.y, within.y);
  return {point.direction, point.radiance, texels_.solidAnglePdf(pdfUv, texel.y)};
}

float EnvironmentSampler::withinDensity(const EnvironmentTexels::Location& at) const {
  return bilinear_ ? texels_.densityAtUv(at.texel, at.uv) : 1.0f;
}

EnvironmentSampler::Sample EnvironmentSampler::sample(glm::vec2 u) const {
  const PiecewiseConstant2D& distribution = plain();
  const PiecewiseConstant2D::Sample s = distribution.sample(u);
  // The point inside the texel: across its columns, and down its row's solid angle (linear in
  // cos(theta)), uniform or by the bilinear luminance.
  const glm::vec2 within(
      std::clamp(s.p.x * static_cast<float>(distribution.width()) - static_cast<float>(s.offset.x), 0.0f, 1.0f),
      std::clamp(s.p.y * static_cast<float>(distribution.height()) - static_cast<float>(s.offset.y), 0.0f, 1.0f));
  return pointIn(s.offset, within, s.pdf);
}

float EnvironmentSampler::pdf(const glm::vec3& worldDirection) const { return lookup(worldDirection).pdf; }

EnvironmentSampler::Lookup EnvironmentSampler::lookupAt(glm::vec2 uv) const {
  const EnvironmentTexels::Location at = texels_.locateUv(uv);
  return {at.radiance, texels_.solidAnglePdf(plain().pdf(at.uv) * withinDensity(at), at.texel.y)};
}

void EnvironmentSampler::prefetchLookup(glm::vec2 uv) const {
  plain().prefetchPdf(uv);
  texels_.prefetchAround(texels_.texelAt(uv));
}

EnvironmentSampler::Sample EnvironmentSampler::sample(int bucket, glm::vec2 u) const {
  return sampleOriented(bucket, u, nullptr);
}

EnvironmentSampler::Sample EnvironmentSampler::sampleOriented(int bucket, glm::vec2 u,
                                                           const OrientedEnvironment::DirectionCone* within) const {
  if (bucket == kNoBucket) return sample(u);
  const OrientedEnvironment::Pick pick = oriented_->sample(bucket, u, within);
  if (pick.pdfUv <= 0.0f) return {};
  return pointIn(pick.texel, pick.within, pick.pdfUv);
}

EnvironmentSampler::Sample EnvironmentSampler::sampleWithin(int bucket, glm::vec2 u, const glm::vec3& axis,
                                                         float cosRadius) const {
  OrientedEnvironment::DirectionCone cone;
  cone.axis = texels_.map().toMapDirection(axis);
  cone.cosRadius = std::clamp(cosRadius, -1.0f, 1.0f);
  cone.sinRadius = std::sqrt(std::max(0.0f, (1.0f - cone.cosRadius) * (1.0f + cone.cosRadius)));
  return sampleOriented(bucket, u, &cone);
}

float EnvironmentSampler::pdf(int bucket, const glm::vec3& worldDirection) const {
  return lookupAt(bucket, mapUv(worldDirection)).pdf;
}

EnvironmentSampler::Lookup EnvironmentSampler::lookupAt(int bucket, glm::vec2 uv) const {
  if (bucket == kNoBucket) return lookupAt(uv);
  const EnvironmentTexels::Location at = texels_.locateUv(uv);
  return {at.radiance, texels_.solidAnglePdf(oriented_->pdfUv(bucket, at.texel) * withinDensity(at), at.texel.y)};
}

void EnvironmentSampler::prefetchLookup(int bucket, glm::vec2 uv) const {
  if (bucket == kNoBucket) return prefetchLookup(uv);
  const glm::ivec2 texel = texels_.texelAt(uv);
  oriented_->prefetchPdf(bucket, texel);
  texels_.prefetchAround(texel);
}

}  // namespace iblkit
