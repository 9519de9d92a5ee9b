#include "core/material.h"

#include <algorithm>

namespace iblkit {

Material clampedToGltfRanges(const Material& material) {
  Material clamped = material;
  clamped.baseColor = glm::clamp(material.baseColor, 0.0f, 1.0f);
  clamped.metallic = std::clamp(material.metallic, 0.0f, 1.0f);
  clamped.roughness = std::clamp(material.roughness, 0.0f, 1.0f);
  clamped.specular = std::clamp(material.specular, 0.0f, 1.0f);
  clamped.specularColor = glm::max(material.specularColor, 0.0f);
  return clamped;
}

}  // namespace iblkit
