#include "core/surface_material.h"

#include <cmath>

namespace iblkit {

namespace {

// The slot's texture value, or nullptr-like `false` when the slot is off, empty, or names a
// texture without a chain in that colour space (an image that did not load): then its factors
// stand alone, as for a slot without a texture.
// log2Footprint: SceneTextures::log2Footprint of inputs.footprintUv, once per set for all slots.
// channels: the SceneTextures channel mask the slot uses (the others are not read).
bool readSlot(const TextureRef& ref, unsigned bit, ColorSpace colorSpace, const SceneTextures& textures,
              const SurfaceInputs& inputs, const float* log2Footprint, unsigned channels, glm::vec4& value) {
  if (!(inputs.slots & bit) || !ref.present()) return false;
  const int set = ref.texCoord == 1 ? 1 : 0;
  return textures.trySample(ref, colorSpace, inputs.texcoords[set], log2Footprint[set], value, channels);
}

struct Log2Footprints {
  float set[2];
  explicit Log2Footprints(const SurfaceInputs& inputs)
      : set{SceneTextures::log2Footprint(inputs.footprintUv[0]),
            SceneTextures::log2Footprint(inputs.footprintUv[1])} {}
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
  const Log2Footprints lf(inputs);
  glm::vec4 value;
  // glTF 2.0 section 3.9.2: base colour and its alpha are factor times the (decoded) texel.
  if (readSlot(material.baseColorTexture, kSlotBaseColor, ColorSpace::Srgb, textures, inputs, lf.set,
               SceneTextures::kRgba, value)) {
    m.baseColor *= glm::vec3(value);
    m.alpha *= value.a;
  }
  out.alpha = m.alpha;
  // Section 3.9.2: roughness in G, metallic in B.
  if (readSlot(material.metallicRoughnessTexture, kSlotMetallicRoughness, ColorSpace::Linear, textures,
               inputs, lf.set, SceneTextures::kGreenBlue, value)) {
    m.roughness *= value.g;
    m.metallic *= value.b;
  }
  // Section 3.9.3: occlusion = 1 + strength (R - 1).
  if (readSlot(material.occlusionTexture, kSlotOcclusion, ColorSpace::Linear, textures, inputs, lf.set,
               SceneTextures::kRed, value))
    out.occlusion = 1.0f + material.occlusionStrength * (value.r - 1.0f);
  // Section 3.9.3: emissive = factor times the sRGB-decoded texel.
  if (readSlot(material.emissiveTexture, kSlotEmissive, ColorSpace::Srgb, textures, inputs, lf.set,
               SceneTextures::kRgb, value))
    m.emissive *= glm::vec3(value);
  if (inputs.tangent.x != 0.0f || inputs.tangent.y != 0.0f || inputs.tangent.z != 0.0f)
    if (readSlot(material.normalTexture, kSlotNormal, ColorSpace::Linear, textures, inputs, lf.set,
                 SceneTextures::kRgb, value))
      out.normal = perturbNormal(inputs.normal, inputs.tangent, glm::vec3(value), material.normalScale);
  return out;
}

float surfaceAlpha(const Material& material, const SceneTextures& textures, const SurfaceInputs& inputs) {
  const Log2Footprints lf(inputs);
  glm::vec4 value;
  if (readSlot(material.baseColorTexture, kSlotBaseColor, ColorSpace::Srgb, textures, inputs, lf.set,
               SceneTextures::kAlpha, value))
    return material.alpha * value.a;
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
