#include "core/surface_material.h"

#include <cmath>

namespace iblkit {

namespace {

// The lookups of one point's slots, gathered for one SceneTextures::sampleSlots call: a slot that
// is off or has no texture gets none (its factors then stand alone), nor does one whose texture
// has no chain in that colour space (an image that did not load: found stays false).
struct SlotLookups {
  SceneTextures::SlotLookup lookups[5];
  int count = 0;
  // The index of the slot's lookup, -1 for none. channels: the SceneTextures channel mask the slot
  // uses (the others are not read).
  int add(const TextureRef& ref, unsigned bit, ColorSpace colorSpace, unsigned channels, const SurfaceInputs& inputs) {
    if (!(inputs.slots & bit) || !ref.present()) return -1;
    SceneTextures::SlotLookup& lookup = lookups[count];
    lookup.ref = &ref;
    lookup.colorSpace = colorSpace;
    lookup.channels = channels;
    return count++;
  }
  // The slot's value, or nullptr when it has none.
  const glm::vec4* value(int index) const {
    return index >= 0 && lookups[index].found ? &lookups[index].value : nullptr;
  }
};

}  // namespace

SurfaceMaterial evaluateSurfaceMaterial(const Material& material, const SceneTextures& textures,
                                        const SurfaceInputs& inputs) {
  SurfaceMaterial out;
  Material& m = out.material;
  // Every field but the name (copying a std::string could allocate, once per hit) and the texture
  // refs (left cleared: the result is ready for the BRDF).
  m.baseColor = material.baseColor;
  m.metallic = material.metallic;
  m.roughness = material.roughness;
  m.specular = material.specular;
  m.specularColor = material.specularColor;
  m.emissive = material.emissive;
  m.alpha = material.alpha;
  m.normalScale = material.normalScale;
  m.occlusionStrength = material.occlusionStrength;
  m.alphaMode = material.alphaMode;
  m.alphaCutoff = material.alphaCutoff;
  m.doubleSided = material.doubleSided;
  out.normal = inputs.normal;
  SlotLookups slots;
  const int base = slots.add(material.baseColorTexture, kSlotBaseColor, ColorSpace::Srgb, SceneTextures::kRgba, inputs);
  const int metallicRoughness = slots.add(material.metallicRoughnessTexture, kSlotMetallicRoughness,
                                          ColorSpace::Linear, SceneTextures::kGreenBlue, inputs);
  const int occlusion =
      slots.add(material.occlusionTexture, kSlotOcclusion, ColorSpace::Linear, SceneTextures::kRed, inputs);
  const int emissive = slots.add(material.emissiveTexture, kSlotEmissive, ColorSpace::Srgb, SceneTextures::kRgb, inputs);
  const bool tangent = inputs.tangent.x != 0.0f || inputs.tangent.y != 0.0f || inputs.tangent.z != 0.0f;
  const int normal =
      tangent ? slots.add(material.normalTexture, kSlotNormal, ColorSpace::Linear, SceneTextures::kRgb, inputs) : -1;
  textures.sampleSlots(slots.lookups, slots.count, inputs.texcoords, inputs.footprintUv);
  // glTF 2.0 section 3.9.2: base colour and its alpha are factor times the (decoded) texel.
  if (const glm::vec4* value = slots.value(base)) {
    m.baseColor *= glm::vec3(*value);
    m.alpha *= value->a;
  }
  out.alpha = m.alpha;
  // Section 3.9.2: roughness in G, metallic in B.
  if (const glm::vec4* value = slots.value(metallicRoughness)) {
    m.roughness *= value->g;
    m.metallic *= value->b;
  }
  // Section 3.9.3: occlusion = 1 + strength (R - 1).
  if (const glm::vec4* value = slots.value(occlusion)) out.occlusion = 1.0f + material.occlusionStrength * (value->r - 1.0f);
  // Section 3.9.3: emissive = factor times the sRGB-decoded texel.
  if (const glm::vec4* value = slots.value(emissive)) m.emissive *= glm::vec3(*value);
  if (const glm::vec4* value = slots.value(normal))
    out.normal = perturbNormal(inputs.normal, inputs.tangent, glm::vec3(*value), material.normalScale);
  return out;
}

float surfaceAlpha(const Material& material, const SceneTextures& textures, const SurfaceInputs& inputs) {
  SlotLookups slots;
  const int base = slots.add(material.baseColorTexture, kSlotBaseColor, ColorSpace::Srgb, SceneTextures::kAlpha, inputs);
  textures.sampleSlots(slots.lookups, slots.count, inputs.texcoords, inputs.footprintUv);
  if (const glm::vec4* value = slots.value(base)) return material.alpha * value->a;
  return material.alpha;
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
