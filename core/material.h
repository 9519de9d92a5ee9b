#pragma once
// The material parameters every program shares: glTF 2.0 metallic-roughness with the
// KHR_materials_specular factor (0 gives a pure Lambert surface, which the diffuse-only
// approximations are scored against). Evaluation and sampling live in brdf.h.

#include <string>

#include <glm/glm.hpp>

namespace iblkit {

struct Material {
  std::string name;
  glm::vec3 baseColor{1.0f};  // linear, glTF baseColorFactor.rgb
  float metallic = 1.0f;      // glTF defaults: metallicFactor 1, roughnessFactor 1
  float roughness = 1.0f;     // perceptual roughness r; alpha = r^2 (docs/conventions.md)
  float specular = 1.0f;      // KHR_materials_specular specularFactor (scales the dielectric F0 and Fresnel)
  glm::vec3 specularColor{1.0f};  // KHR_materials_specular specularColorFactor
  glm::vec3 emissive{0.0f};       // glTF emissiveFactor (linear)
};

// `material` with its factors clamped to their glTF ranges (docs/material-model.md, "Parameters"):
// baseColor, metallic, roughness and specular to [0, 1], specularColor to >= 0 (glTF 2.0 and
// KHR_materials_specular allow it above 1); name and emissive unchanged. The one clamp that the
// CPU BRDF (brdfLobes) and the engine's material uniforms both apply.
Material clampedToGltfRanges(const Material& material);

}  // namespace iblkit
