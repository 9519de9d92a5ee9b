#include "core/material.h"

#include <algorithm>

namespace iblkit {

float dielectricF0(float ior) {
  const float r = (ior - 1.0f) / (ior + 1.0f);
  return r * r;
}

glm::vec3 iorScaledSpecularColor(const Material& material) {
  // The default ior keeps the colour bit for bit (0.04 / 0.04 rounds to 1 anyway).
  if (material.ior == 1.5f) return material.specularColor;
  return material.specularColor * (dielectricF0(material.ior) / 0.04f);
}

GltfRangeFactors clampedFactors(const Material& material) {
  return clampedToGltfRanges(GltfRangeFactors{material.baseColor, material.metallic, material.roughness,
                                              material.specular, iorScaledSpecularColor(material)});
}

Material clampedToGltfRanges(const Material& material) {
  Material clamped = material;
  const GltfRangeFactors factors = clampedFactors(material);
  clamped.baseColor = factors.baseColor;
  clamped.metallic = factors.metallic;
  clamped.roughness = factors.roughness;
  clamped.specular = factors.specular;
  clamped.specularColor = factors.specularColor;
  clamped.ior = 1.5f;  // folded into specularColor
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
