#include "reference/environment_sampler.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

#include "engine/core/latlong.h"

namespace iblkit {

namespace {
constexpr float kTwoPiSquared = 2.0f * glm::pi<float>() * glm::pi<float>();
// Floor of the compensated weights, relative to the mean (pbrt-v4).
constexpr float kCompensationFloor = 1e-3f;
// Maps whose weights vary by less than this fraction of their mean are not compensated (Mitsuba 3).
constexpr float kNearConstant = 1e-2f;
}  // namespace

std::vector<float> EnvironmentSampler::texelWeights(const EnvironmentMap& map, bool misCompensation,
                                                    bool* compensated) {
  const int width = map.width(), height = map.height();
  std::vector<float> luminance(static_cast<std::size_t>(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      luminance[static_cast<std::size_t>(y) * width + x] = map.texelLuminance(x, y);

  std::vector<float> weights(luminance.size());
  for (int y = 0; y < height; ++y) {
    const float sinTheta =
        std::sin(glm::pi<float>() * (static_cast<float>(y) + 0.5f) / static_cast<float>(height));
    for (int x = 0; x < width; ++x) {
      float neighbourhoodMax = 0.0f;
      for (int dy = -1; dy <= 1; ++dy) {
        const int sy = std::clamp(y + dy, 0, height - 1);
        for (int dx = -1; dx <= 1; ++dx) {
          const int sx = (x + dx + width) % width;
          neighbourhoodMax = std::max(neighbourhoodMax, luminance[static_cast<std::size_t>(sy) * width + sx]);
        }
      }
      weights[static_cast<std::size_t>(y) * width + x] = neighbourhoodMax * sinTheta;
    }
  }

  *compensated = false;
  if (misCompensation) {
    double sum = 0.0;
    float lo = weights.front(), hi = weights.front();
    for (const float w : weights) {
      sum += w;
      lo = std::min(lo, w);
      hi = std::max(hi, w);
    }
    const float mean = static_cast<float>(sum / static_cast<double>(weights.size()));
    if (mean > 0.0f && hi - lo > kNearConstant * mean) {
      for (float& w : weights) w = std::max(w - mean, std::min(kCompensationFloor * mean, w));
      *compensated = true;
    }
  }
  return weights;
}

EnvironmentSampler::EnvironmentSampler(const EnvironmentMap& map, bool misCompensation)
    : map_(map), distribution_(texelWeights(map, misCompensation, &compensated_), map.width(), map.height()) {
  black_ = distribution_.integral() <= 0.0f;
}

EnvironmentSampler::Sample EnvironmentSampler::sample(glm::vec2 u) const {
  const PiecewiseConstant2D::Sample s = distribution_.sample(u);
  const glm::vec3 mapDirection = latLongDirection(s.p);
  const float sinTheta = std::hypot(mapDirection.x, mapDirection.z);
  Sample out;
  out.direction = map_.toWorldDirection(mapDirection);
  // The bilinear lookup at the sampled (u, v) itself: map_.radiance(out.direction) would find the
  // same point again through two arctangents.
  out.radiance = map_.intensity() * sampleLatLongBilinear(map_.image(), s.p);
  out.pdf = sinTheta > 0.0f ? s.pdf / (kTwoPiSquared * sinTheta) : 0.0f;
  return out;
}

float EnvironmentSampler::pdf(const glm::vec3& worldDirection) const { return lookup(worldDirection).pdf; }

EnvironmentSampler::Lookup EnvironmentSampler::lookup(const glm::vec3& worldDirection) const {
  const glm::vec3 mapDirection = glm::normalize(map_.toMapDirection(worldDirection));
  const glm::vec2 uv = latLongUv(mapDirection);
  Lookup out;
  out.radiance = map_.intensity() * sampleLatLongBilinear(map_.image(), uv);
  // hypot(x, z), not sqrt(1 - y^2): stays non-zero for directions a float step from a pole.
  const float sinTheta = std::hypot(mapDirection.x, mapDirection.z);
  if (sinTheta > 0.0f) out.pdf = distribution_.pdf(uv) / (kTwoPiSquared * sinTheta);
  return out;
}

}  // namespace iblkit
