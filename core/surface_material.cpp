#include "core/surface_material.h"

#include <cmath>

namespace iblkit {

namespace {

// The lookups of one material's slots, gathered for a SceneTextures::SlotSet: a slot that is off
// or has no texture gets none (its factors then stand alone), nor does one whose texture has no
// chain in that colour space (an image that did not load: SlotSet::found is false).
struct SlotLookups {
  SceneTextures::SlotLookup lookups[5];
  int count = 0;
  // The index of the slot's lookup, -1 for none. channels: the SceneTextures channel mask the slot
  // uses (the others are not read).
  int add(const TextureRef& ref, unsigned bit, ColorSpace colorSpace, unsigned channels, unsigned slots) {
    if (!(slots & bit) || !ref.present()) return -1;
    SceneTextures::SlotLookup& lookup = lookups[count];
    lookup.ref = &ref;
    lookup.colorSpace = colorSpace;
    lookup.channels = channels;
    return count++;
  }
};

// perturbNormal, inlined into PreparedSurfaceMaterial::evaluate (one call per textured hit).
[[gnu::always_inline]] inline glm::vec3 perturbedNormal(const glm::vec3& n, const glm::vec4& tangent, const glm::vec3& texel, float scale) {
  // glTF 2.0 section 3.9.3 (normalTexture): scaledNormal = normalize((2 texel - 1) * (scale, scale, 1)),
  // in the tangent frame (t, b, n), b = w cross(n, t) (section 3.7.2.1).
  // The interpolated frame is used as it is, not re-orthogonalised: the notes of Mikkelsen's
  // reference implementation (mikktspace.h, on the pixel shader) ask for exactly this, so that the
  // frame is the one the map was baked against; shaders/material.glsl does the same.
  const glm::vec3 t(tangent);
  if (t == glm::vec3(0.0f)) return n;
  const glm::vec3 b = (tangent.w < 0.0f ? -1.0f : 1.0f) * glm::cross(n, t);
  const glm::vec3 m = 2.0f * texel - 1.0f;
  const glm::vec3 world = t * (m.x * scale) + b * (m.y * scale) + n * m.z;
  const float length = glm::length(world);
  if (!(length > 0.0f) || !std::isfinite(length)) return n;
  return world / length;
}

}  // namespace

PreparedSurfaceMaterial::PreparedSurfaceMaterial(const Material& material, const SceneTextures& textures,
                                                 unsigned slots) {
  factors_.baseColor = material.baseColor;
  factors_.metallic = material.metallic;
  factors_.roughness = material.roughness;
  factors_.specular = material.specular;
  factors_.specularColor = iorScaledSpecularColor(material);
  factors_.emissive = material.emissive;
  factors_.alpha = material.alpha;
  normalScale_ = material.normalScale;
  occlusionStrength_ = material.occlusionStrength;
  SlotLookups lookups;
  base_ = lookups.add(material.baseColorTexture, kSlotBaseColor, ColorSpace::Srgb, SceneTextures::kRgba, slots);
  metallicRoughness_ = lookups.add(material.metallicRoughnessTexture, kSlotMetallicRoughness, ColorSpace::Linear,
                                   SceneTextures::kGreenBlue, slots);
  occlusion_ =
      lookups.add(material.occlusionTexture, kSlotOcclusion, ColorSpace::Linear, SceneTextures::kRed, slots);
  emissive_ = lookups.add(material.emissiveTexture, kSlotEmissive, ColorSpace::Srgb, SceneTextures::kRgb, slots);
  normal_ = lookups.add(material.normalTexture, kSlotNormal, ColorSpace::Linear, SceneTextures::kRgb, slots);
  lookups_ = SceneTextures::SlotSet(textures, lookups.lookups, lookups.count);
  for (int* slot : {&base_, &metallicRoughness_, &occlusion_, &emissive_, &normal_})
    if (*slot >= 0 && !lookups_.found(*slot)) *slot = -1;
}

SurfaceMaterial PreparedSurfaceMaterial::evaluate(const SurfaceInputs& inputs) const {
  SurfaceMaterial out = factors_;
  out.normal = inputs.normal;
  // The normal texture only with a tangent frame.
  const bool tangent = inputs.tangent.x != 0.0f || inputs.tangent.y != 0.0f || inputs.tangent.z != 0.0f;
  const int normal = tangent ? normal_ : -1;
  unsigned active = ~0u;
  if (normal_ >= 0 && normal < 0) active &= ~(1u << normal_);
  glm::vec4 values[5];
  lookups_.sample(inputs.texcoords, inputs.footprintUv, values, active);
  // glTF 2.0 section 3.9.2: base colour and its alpha are factor times the (decoded) texel.
  if (base_ >= 0) {
    out.baseColor *= glm::vec3(values[base_]);
    out.alpha *= values[base_].a;
  }
  // Section 3.9.2: COLOR_0, when present, multiplies the base colour (and its alpha) too.
  out.baseColor *= glm::vec3(inputs.vertexColor);
  out.alpha *= inputs.vertexColor.a;
  // Section 3.9.2: roughness in G, metallic in B.
  if (metallicRoughness_ >= 0) {
    out.roughness *= values[metallicRoughness_].g;
    out.metallic *= values[metallicRoughness_].b;
  }
  // Section 3.9.3: occlusion = 1 + strength (R - 1).
  if (occlusion_ >= 0) out.occlusion = 1.0f + occlusionStrength_ * (values[occlusion_].r - 1.0f);
  // Section 3.9.3: emissive = factor times the sRGB-decoded texel.
  if (emissive_ >= 0) out.emissive *= glm::vec3(values[emissive_]);
  if (normal >= 0) out.normal = perturbedNormal(inputs.normal, inputs.tangent, glm::vec3(values[normal]), normalScale_);
  return out;
}

SurfaceMaterial evaluateSurfaceMaterial(const Material& material, const SceneTextures& textures,
                                        const SurfaceInputs& inputs) {
  return PreparedSurfaceMaterial(material, textures, inputs.slots).evaluate(inputs);
}

float surfaceAlpha(const Material& material, const SceneTextures& textures, const SurfaceInputs& inputs) {
  SlotLookups slots;
  const int base =
      slots.add(material.baseColorTexture, kSlotBaseColor, ColorSpace::Srgb, SceneTextures::kAlpha, inputs.slots);
  textures.sampleSlots(slots.lookups, slots.count, inputs.texcoords, inputs.footprintUv);
  if (base >= 0 && slots.lookups[base].found) return material.alpha * slots.lookups[base].value.a * inputs.vertexColor.a;
  return material.alpha * inputs.vertexColor.a;
}

bool surfacePresent(const Material& material, float alpha, float u) {
  switch (material.alphaMode) {
    case AlphaMode::Mask:
      return alpha >= material.alphaCutoff;
    case AlphaMode::Blend:
      return u < alpha;
    case AlphaMode::Opaque:
    default:
      return true;
  }
}

glm::vec3 perturbNormal(const glm::vec3& n, const glm::vec4& tangent, const glm::vec3& texel, float scale) {
  return perturbedNormal(n, tangent, texel, scale);
}

glm::vec3 shadingNormalFacingViewer(const glm::vec3& n, const glm::vec3& wo, const glm::vec3& geometric) {
  const float cosine = glm::dot(n, wo);
  if (cosine >= kMinShadingCosine) return n;
  // n = cosine wo + p, p perpendicular to wo: keep p's direction, set the cosine to the least.
  const glm::vec3 p = n - cosine * wo;
  const float length = glm::length(p);
  if (!(length > 0.0f)) return geometric;
  return p * (std::sqrt(1.0f - kMinShadingCosine * kMinShadingCosine) / length) + kMinShadingCosine * wo;
}

}  // namespace iblkit
