#pragma once
// A material at one surface point: its factors times what its texture slots read there, its
// alpha, the glTF occlusion, and the shading normal perturbed by its normal texture. The one
// implementation the reference tracer and the baker use; shaders/material.glsl is its GLSL twin
// (same names) and the tests compare them. docs/material-model.md "Textures" has the formulas.

#include <glm/glm.hpp>

#include "core/brdf.h"
#include "core/material.h"
#include "core/texture_sampling.h"

namespace iblkit {

// What a program knows about the point.
struct SurfaceInputs {
  glm::vec2 texcoords[2]{glm::vec2(0.0f), glm::vec2(0.0f)};  // TEXCOORD_0 and _1 (0 when absent)
  // Unit interpolated vertex normal and tangent (xyz unit, w handedness; zero xyz: no tangent,
  // the normal texture is then ignored), both already turned to the side being shaded (for the
  // back face of a double-sided material: normal and tangent.xyz negated, w kept, so the
  // bitangent w cross(n, t) keeps its direction, as the glTF sample viewer does).
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  glm::vec4 tangent{0.0f};
  // Footprint width in uv units of each texCoord set (0: sharpest level), texture_sampling.h.
  float footprintUv[2]{0.0f, 0.0f};
  unsigned slots = kAllTextureSlots;  // slots switched on (TextureSlot bits)
  // The interpolated vertex colour (Mesh::colors, glTF COLOR_0; 1 when the mesh has none). It
  // multiplies the base colour and its alpha whatever the slots: it is not a texture.
  glm::vec4 vertexColor{1.0f};
};

struct SurfaceMaterial {
  // The factors with the textures applied (glTF 2.0 section 3.9): baseColor = factor * texture.rgb
  // * vertex colour.rgb (section 3.9.2: COLOR_0 multiplies the base colour),
  // metallic = factor * texture.b, roughness = factor * texture.g, emissive = factor *
  // texture.rgb, alpha = factor * texture.a * vertex colour.a; specular and specularColor are the material's
  // (specularColor with the ior folded in, iorScaledSpecularColor)
  // (KHR_materials_specular's textures are not read). Ready for brdfLobes(SurfaceMaterial).
  glm::vec3 baseColor{1.0f};
  float metallic = 1.0f;
  float roughness = 1.0f;
  float specular = 1.0f;
  glm::vec3 specularColor{1.0f};
  glm::vec3 emissive{0.0f};
  float alpha = 1.0f;
  float occlusion = 1.0f;  // 1 + strength (R - 1); the reference ignores it (it traces the truth)
  glm::vec3 normal{0.0f, 0.0f, 1.0f};  // unit shading normal: the perturbed normal, or the input's
};

SurfaceMaterial evaluateSurfaceMaterial(const Material& material, const SceneTextures& textures,
                                        const SurfaceInputs& inputs);

// evaluateSurfaceMaterial for one material and one set of slots, prepared once: the slots'
// lookups resolved against the scene's textures (SceneTextures::SlotSet), for a caller that
// evaluates the material at many points (the tracer: one per material). evaluate(inputs) is
// evaluateSurfaceMaterial(material, textures, inputs) with inputs.slots = `slots`, bit for bit
// (evaluateSurfaceMaterial prepares one per call). It points into `textures`, which must outlive it.
class PreparedSurfaceMaterial {
 public:
  PreparedSurfaceMaterial() = default;
  PreparedSurfaceMaterial(const Material& material, const SceneTextures& textures, unsigned slots);
  // inputs.slots is not read: the slots are the ones prepared.
  SurfaceMaterial evaluate(const SurfaceInputs& inputs) const;

 private:
  SurfaceMaterial factors_;  // the material's factors (the normal is the input's)
  float normalScale_ = 1.0f, occlusionStrength_ = 1.0f;
  SceneTextures::SlotSet lookups_;
  // Each slot's lookup in lookups_, -1 for none (off, no texture, or no chain).
  int base_ = -1, metallicRoughness_ = -1, occlusion_ = -1, emissive_ = -1, normal_ = -1;
};

// The BRDF lobes at a point (brdfLobes of its textured factors, clamped to the glTF ranges as
// brdfLobes(Material) clamps a material's).
inline BrdfLobes brdfLobes(const SurfaceMaterial& surface) {
  // brdfLobes(Material) clamps and reads just these factors.
  return brdfLobes(clampedToGltfRanges(GltfRangeFactors{surface.baseColor, surface.metallic, surface.roughness,
                                                        surface.specular, surface.specularColor}));
}

// The base colour alpha only (factor times texture alpha times the vertex colour's), for alpha
// tests in ray filters.
float surfaceAlpha(const Material& material, const SceneTextures& textures, const SurfaceInputs& inputs);

// Whether a point of `material` with alpha `alpha` is there: OPAQUE always, MASK alpha >= cutoff,
// BLEND when `u` (uniform in [0, 1), the caller's random number) < alpha.
bool surfacePresent(const Material& material, float alpha, float u);

// The least cosine between the shading normal and the direction to the viewer
// (shadingNormalFacingViewer); shared with the shaders (shared_constants.glsl).
inline constexpr float kMinShadingCosine = 0.01f;

// The shading normal on the viewer's side, the rule of every program (docs/material-model.md
// "Shading normal"): `n` (unit: interpolated or normal-mapped, already on the viewer's side of the
// geometric normal) where n . wo >= kMinShadingCosine, `wo` the unit direction to the viewer;
// otherwise n turned towards wo in the plane of the two until n . wo = kMinShadingCosine, the
// nearest normal that faces the viewer that much. The BRDF reflects nothing towards a viewer below
// the shading normal, so such a normal would turn a visible surface black (silhouettes of coarse
// meshes, normal maps seen at grazing angles). Turning it is continuous in n, so a pixel's samples
// average the same normal field in the raster and the tracer; the geometric normal, the old
// fallback, jumped there by the whole perturbation. `geometric` (unit, facing wo) only where n is
// -wo, where the plane is undefined.
glm::vec3 shadingNormalFacingViewer(const glm::vec3& n, const glm::vec3& wo, const glm::vec3& geometric);

// The normal-texture perturbation: texel rgb in [0, 1] -> tangent-space (2 rgb - 1) with x and y
// times `scale`, to world space by (t, w cross(n, t), n), normalised. Returns n for a zero tangent.
glm::vec3 perturbNormal(const glm::vec3& n, const glm::vec4& tangent, const glm::vec3& texel, float scale);

}  // namespace iblkit
