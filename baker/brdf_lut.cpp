#include "baker/brdf_lut.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/image_io.h"
#include "core/low_discrepancy.h"
#include "core/microfacet.h"

namespace iblkit {

glm::vec3 integrateDfg(float NoV, float roughness, std::uint32_t sampleCount) {
  // Local frame: n = +z, v in the xz plane.
  const glm::vec3 v(std::sqrt(std::max(0.0f, 1.0f - NoV * NoV)), 0.0f, NoV);
  // alpha = 0 makes the distribution a delta that the warps below cannot represent; the smallest
  // alpha the table uses (its first row) is far from this floor.
  const float alpha = std::max(roughness * roughness, 1e-4f);
  const float g1 = ggxG1(v, alpha);
  double a = 0.0, b = 0.0;
  for (std::uint32_t i = 0; i < sampleCount; ++i) {
    const glm::vec3 h = sampleGgxVisibleNormal(v, alpha, hammersley(i, sampleCount));
    const float VoH = glm::dot(v, h);
    const glm::vec3 l = 2.0f * VoH * h - v;
    if (l.z <= 0.0f || VoH <= 0.0f) continue;
    // f / F * cos(theta_l) / pdf(l) with pdf(l) = D_v(h) / (4 VoH) = G1(v) D(h) / (4 NoV).
    const float weight = 4.0f * ggxSmithVisibility(l.z, NoV, alpha) * l.z * NoV / g1;
    const float fresnel = std::pow(1.0f - VoH, 5.0f);
    a += (1.0f - fresnel) * weight;
    b += fresnel * weight;
  }
  const float scale = 1.0f / static_cast<float>(sampleCount);
  const float A = static_cast<float>(a) * scale, B = static_cast<float>(b) * scale;
  return {A, B, A + B};
}

Image computeBrdfLut(int size, std::uint32_t sampleCount) {
  if (size < 1 || sampleCount < 1)
    throw std::invalid_argument("computeBrdfLut: size and sampleCount must be >= 1");
  Image lut(size, size);
  tbb::parallel_for(0, size, [&](int y) {
    const float roughness = (static_cast<float>(y) + 0.5f) / static_cast<float>(size);
    for (int x = 0; x < size; ++x) {
      const float NoV = (static_cast<float>(x) + 0.5f) / static_cast<float>(size);
      lut.at(x, y) = glm::vec4(integrateDfg(NoV, roughness, sampleCount), 1.0f);
    }
  });
  return lut;
}

}  // namespace iblkit
