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

}  // namespace iblkit
