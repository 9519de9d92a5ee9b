#include "core/material.h"

#include <algorithm>

namespace iblkit {

GltfRangeFactors clampedFactors(const Material& material) {
  return clampedToGltfRanges(GltfRangeFactors{material.baseColor, material.metallic, material.roughness,
                                              material.specular, material.specularColor});
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

bool hasSpecularLayer(const Material& material) {
  const GltfRangeFactors f = clampedFactors(material);
  return f.specular > 0.0f || f.metallic > 0.0f;
}

AlphaMode drawnAlphaMode(const Material& material, bool alphaVaries) {
  if (material.alphaMode == AlphaMode::Opaque || alphaVaries) return material.alphaMode;
  // BLEND keeps a point with probability alpha (u < alpha, u in [0, 1)); MASK where alpha >= cutoff.
  const float alpha = std::clamp(material.alpha, 0.0f, 1.0f);
  const bool alwaysPresent = material.alphaMode == AlphaMode::Blend ? alpha >= 1.0f : alpha >= material.alphaCutoff;
  return alwaysPresent ? AlphaMode::Opaque : material.alphaMode;
}

}  // namespace iblkit
