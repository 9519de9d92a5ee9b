#include "core/material.h"

#include <algorithm>

namespace iblkit {

GltfRangeFactors clampedFactors(const Material& material) {
  return {glm::clamp(material.baseColor, 0.0f, 1.0f), std::clamp(material.metallic, 0.0f, 1.0f),
          std::clamp(material.roughness, 0.0f, 1.0f), std::clamp(material.specular, 0.0f, 1.0f),
          glm::max(material.specularColor, 0.0f)};
}

Material clampedToGltfRanges(const Material& material) {
  Material clamped = material;
  const GltfRangeFactors factors = clampedFactors(material);
  clamped.baseColor = factors.baseColor;
  clamped.metallic = factors.metallic;
  clamped.roughness = factors.roughness;
  clamped.specular = factors.specular;
  clamped.specularColor = factors.specularColor;
  return clamped;
}

}  // namespace iblkit
