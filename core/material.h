#pragma once
// The material parameters every program shares: glTF 2.0 metallic-roughness with the
// KHR_materials_specular factor (0 gives a pure Lambert surface, which the diffuse-only
// approximations are scored against), and the glTF texture slots, alpha mode and doubleSided.
// Evaluation and sampling live in brdf.h; a material with its textures read at one surface point
// (what brdf.h then evaluates) is surface_material.h.

#include <string>

#include <glm/glm.hpp>

#include "core/texture.h"

namespace iblkit {

// glTF alphaMode. OPAQUE ignores alpha. MASK: a point is there where alpha >= alphaCutoff, in
// every program and for every ray (camera, shadow, AO). BLEND: alpha is coverage (the fraction
// of the point's footprint the surface covers), docs/material-model.md "Alpha": the tracer keeps a
// hit with probability alpha, the raster covers that fraction of the pixel's samples.
enum class AlphaMode { Opaque, Mask, Blend };

struct Material {
  std::string name;
  glm::vec3 baseColor{1.0f};  // linear, glTF baseColorFactor.rgb
  float metallic = 1.0f;      // glTF defaults: metallicFactor 1, roughnessFactor 1
  float roughness = 1.0f;     // perceptual roughness r; alpha = r^2 (docs/conventions.md)
  float specular = 1.0f;      // KHR_materials_specular specularFactor (scales the dielectric F0 and Fresnel)
  glm::vec3 specularColor{1.0f};  // KHR_materials_specular specularColorFactor
  glm::vec3 emissive{0.0f};       // glTF emissiveFactor (linear), times KHR_materials_emissive_strength
  float alpha = 1.0f;             // glTF baseColorFactor.a
  // KHR_materials_ior: the dielectric's F0 is dielectricF0(ior) where the core model has 0.04 (the
  // F0 of the default, 1.5). 0 or >= 1.
  float ior = 1.5f;

  // Texture slots (glTF 2.0 section 5.19-5.22); each multiplies its factors above.
  TextureRef baseColorTexture{};          // sRGB RGB, linear A
  TextureRef metallicRoughnessTexture{};  // linear; G roughness, B metallic
  TextureRef normalTexture{};             // linear tangent-space normal, X and Y scaled by normalScale
  TextureRef occlusionTexture{};          // linear R; 1 + occlusionStrength (R - 1)
  TextureRef emissiveTexture{};           // sRGB RGB
  float normalScale = 1.0f;
  float occlusionStrength = 1.0f;

  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;
  bool doubleSided = false;
};

// The F0 of a dielectric of index of refraction `ior` against air, ((ior - 1) / (ior + 1))^2
// (KHR_materials_ior): 0.04 at 1.5, 0 at 1, 1 at 0.
float dielectricF0(float ior);

// The specular colour with the material's ior folded in: specularColor * dielectricF0(ior) / 0.04.
// The model's dielectric F0 is min(0.04 specularColor, 1) (KHR_materials_specular), and
// KHR_materials_ior's is min(dielectricF0(ior) specularColor, 1), so this is exact; every program
// reads the specular colour through it (clampedFactors, PreparedSurfaceMaterial), so no BRDF
// needs the ior on its own.
glm::vec3 iorScaledSpecularColor(const Material& material);

// `material` with its factors clamped to their glTF ranges (docs/material-model.md, "Parameters"):
// baseColor, metallic, roughness and specular to [0, 1], specularColor to >= 0 (glTF 2.0 and
// KHR_materials_specular allow it above 1) after folding the ior in (iorScaledSpecularColor; ior
// is then 1.5, so the result folds nothing twice); name and emissive unchanged. The one clamp
// that the CPU BRDF (brdfLobes) and the engine's material uniforms both apply.
Material clampedToGltfRanges(const Material& material);

// The factors clampedToGltfRanges clamps, clamped the same way, without copying the rest of the
// material (its name and five texture refs): brdfLobes runs once per textured hit.
struct GltfRangeFactors {
  glm::vec3 baseColor;
  float metallic, roughness, specular;
  glm::vec3 specularColor;
};
GltfRangeFactors clampedFactors(const Material& material);

// The alpha mode that draws `material` exactly as its own does with the fewest tests: OPAQUE where
// its alpha cannot take a point away (BLEND with baseColorFactor.a >= 1, MASK with it >= the
// cutoff), when no base colour texture is read and no vertex colour's alpha is below 1
// (`alphaVaries` false: either would multiply the factor); its own mode otherwise. Exporters often mark opaque materials BLEND; the
// engine draws them as opaque meshes, which keep the early depth test and the shadow mask.
AlphaMode drawnAlphaMode(const Material& material, bool alphaVaries);

// Whether `material` has a specular layer: false when its specular and metallic factors are 0
// (after clampedToGltfRanges), so that f0 = f90 = 0 whatever its textures (metallicRoughness
// multiplies the factor) and the BRDF is Lambert's, diffuse weight 1. The engine compiles its
// programs without the specular terms for such materials (the bundled scenes' ground and bunny).
bool hasSpecularLayer(const Material& material);
// The same clamp of factors given on their own (a textured hit's, SurfaceMaterial's).
inline GltfRangeFactors clampedToGltfRanges(const GltfRangeFactors& f) {
  return {glm::clamp(f.baseColor, 0.0f, 1.0f), glm::clamp(f.metallic, 0.0f, 1.0f),
          glm::clamp(f.roughness, 0.0f, 1.0f), glm::clamp(f.specular, 0.0f, 1.0f),
          glm::max(f.specularColor, 0.0f)};
}

}  // namespace iblkit
