// A material at one surface point: the GLSL twin of core/surface_material.h (same names:
// SurfaceInputs, SurfaceMaterial, evaluateSurfaceMaterial, surfacePresent, perturbNormal) and of
// TextureTransform::apply (core/texture.h, textureTransformApply here). docs/material-model.md
// "Textures" has the formulas; tests/gl/material_test.cpp compares the two sides.
//
// What the GPU does for the C++ side's texture_sampling.h: the slot's texture is the core's mip
// chain uploaded level by level (engine/gl/material_textures.cpp), sRGB chains as SRGB8_ALPHA8 so
// that the texture unit decodes IEC 61966-2-1 before filtering as srgbToLinear does, with a sampler
// object from the glTF sampler; the level of detail comes from the screen derivatives of the uv
// (OpenGL 4.5 section 8.14.1) and, where the driver offers it, anisotropic filtering.
//
// TEXTURED is the set of slots (TextureSlot bits) whose reads are compiled in: renderer.cpp builds
// one variant per set of slots bound, so a slot a material lacks (or that is switched off) costs
// nothing, and a material without textures (TEXTURED 0, the default) costs what it did before.

#include "shared_constants.glsl"

#ifndef TEXTURED
#define TEXTURED 0
#endif

// SurfaceInputs of surface_material.h. The footprint is the GPU's own (uv derivatives).
struct SurfaceInputs {
  vec2 texcoords[2];  // TEXCOORD_0 and _1 ((0, 0) when the mesh has none)
  vec3 normal;        // unit, turned to the side being shaded
  vec4 tangent;       // xyz unit (turned like the normal), w handedness; zero xyz: no tangent
  int slots;          // TextureSlot bits switched on and present
  vec4 vertexColor;   // interpolated COLOR_0 ((1, 1, 1, 1) when the mesh has none)
};

// SurfaceMaterial of surface_material.h, with the Material fields the shaders read.
struct SurfaceMaterial {
  vec3 baseColor;
  float metallic;
  float roughness;
  vec3 emissive;
  float alpha;
  float occlusion;  // 1 + strength (R - 1)
  vec3 normal;
};

// Material (core/material.h), its factors clamped on the CPU (clampedToGltfRanges).
uniform vec3 baseColor;
uniform float metallic;
uniform float roughness;
uniform vec3 emissive;
uniform float baseAlpha;  // baseColorFactor.a
uniform float normalScale;
uniform float occlusionStrength;
uniform int alphaMode;  // kAlphaMode*
uniform float alphaCutoff;
// Per slot, in TextureSlot bit order: the TEXCOORD set and the KHR_texture_transform matrix.
uniform int slotTexCoord[5];
uniform mat3 slotTransform[5];

#if (TEXTURED & SLOT_BIT_BASE_COLOR) != 0
layout(binding = kTextureUnitBaseColor) uniform sampler2D baseColorTexture;
#endif
#if (TEXTURED & SLOT_BIT_METALLIC_ROUGHNESS) != 0
layout(binding = kTextureUnitMetallicRoughness) uniform sampler2D metallicRoughnessTexture;
#endif
#if (TEXTURED & SLOT_BIT_NORMAL) != 0
layout(binding = kTextureUnitNormal) uniform sampler2D normalTexture;
#endif
#if (TEXTURED & SLOT_BIT_OCCLUSION) != 0
layout(binding = kTextureUnitOcclusion) uniform sampler2D occlusionTexture;
#endif
#if (TEXTURED & SLOT_BIT_EMISSIVE) != 0
layout(binding = kTextureUnitEmissive) uniform sampler2D emissiveTexture;
#endif

// TextureTransform::apply: uv' = T(offset) R(rotation) S(scale) uv, the matrix built on the CPU
// by TextureTransform::matrix (column-major, acting on (u, v, 1)).
vec2 textureTransformApply(mat3 transform, vec2 uv) { return (transform * vec3(uv, 1.0)).xy; }

// perturbNormal of surface_material.cpp: texel rgb in [0, 1] -> (2 rgb - 1), x and y times scale,
// to world space by (t, w cross(n, t), n) (glTF 2.0 section 3.9.3, "normal"), normalised; n for a
// zero tangent.
vec3 perturbNormal(vec3 n, vec4 tangent, vec3 texel, float scale) {
  if (dot(tangent.xyz, tangent.xyz) == 0.0) return n;
  vec3 m = texel * 2.0 - 1.0;
  m.xy *= scale;
  vec3 t = tangent.xyz;
  vec3 b = tangent.w * cross(n, t);
  vec3 perturbed = m.x * t + m.y * b + m.z * n;
  float length2 = dot(perturbed, perturbed);
  return length2 > 0.0 ? perturbed * inversesqrt(length2) : n;
}

// shadingNormalFacingViewer of surface_material.cpp: n where n . wo >= kMinShadingCosine, else n
// turned towards wo in their plane until n . wo = kMinShadingCosine; `geometric` for n = -wo.
vec3 shadingNormalFacingViewer(vec3 n, vec3 wo, vec3 geometric) {
  float cosine = dot(n, wo);
  if (cosine >= kMinShadingCosine) return n;
  vec3 p = n - cosine * wo;
  float length2 = dot(p, p);
  if (!(length2 > 0.0)) return geometric;
  return p * (sqrt(1.0 - kMinShadingCosine * kMinShadingCosine) * inversesqrt(length2)) + kMinShadingCosine * wo;
}

#if TEXTURED != 0
vec2 slotUv(SurfaceInputs inputs, int slot) {
  return textureTransformApply(slotTransform[slot], inputs.texcoords[slotTexCoord[slot] == 1 ? 1 : 0]);
}
#endif

// evaluateSurfaceMaterial: the factors times what the switched-on slots read. Every texture is
// read here, before any discard, so that the implicit derivatives are those of the whole quad.
SurfaceMaterial evaluateSurfaceMaterial(SurfaceInputs inputs) {
  SurfaceMaterial s;
  s.baseColor = baseColor;
  s.metallic = metallic;
  s.roughness = roughness;
  s.emissive = emissive;
  s.alpha = baseAlpha;
  s.occlusion = 1.0;
  s.normal = inputs.normal;
#if (TEXTURED & SLOT_BIT_BASE_COLOR) != 0
  vec4 base = texture(baseColorTexture, slotUv(inputs, 0));
  if ((inputs.slots & kSlotBaseColor) != 0) {
    s.baseColor *= base.rgb;
    s.alpha *= base.a;
  }
#endif
  // COLOR_0 multiplies the base colour and its alpha (glTF 2.0 section 3.9.2), after the texture.
  s.baseColor *= inputs.vertexColor.rgb;
  s.alpha *= inputs.vertexColor.a;
#if (TEXTURED & SLOT_BIT_METALLIC_ROUGHNESS) != 0
  vec4 metallicRoughness = texture(metallicRoughnessTexture, slotUv(inputs, 1));
  if ((inputs.slots & kSlotMetallicRoughness) != 0) {
    s.roughness *= metallicRoughness.g;
    s.metallic *= metallicRoughness.b;
  }
#endif
#if (TEXTURED & SLOT_BIT_NORMAL) != 0
  vec3 normalTexel = texture(normalTexture, slotUv(inputs, 2)).rgb;
  if ((inputs.slots & kSlotNormal) != 0) s.normal = perturbNormal(inputs.normal, inputs.tangent, normalTexel, normalScale);
#endif
#if (TEXTURED & SLOT_BIT_OCCLUSION) != 0
  float occlusionTexel = texture(occlusionTexture, slotUv(inputs, 3)).r;
  if ((inputs.slots & kSlotOcclusion) != 0) s.occlusion = 1.0 + occlusionStrength * (occlusionTexel - 1.0);
#endif
#if (TEXTURED & SLOT_BIT_EMISSIVE) != 0
  vec3 emissiveTexel = texture(emissiveTexture, slotUv(inputs, 4)).rgb;
  if ((inputs.slots & kSlotEmissive) != 0) s.emissive *= emissiveTexel;
#endif
  return s;
}

// surfacePresent: OPAQUE always; MASK alpha >= cutoff; BLEND u < alpha (u uniform in [0, 1)).
bool surfacePresent(float alpha, float u) {
  if (alphaMode == kAlphaModeMask) return alpha >= alphaCutoff;
  if (alphaMode == kAlphaModeBlend) return u < alpha;
  return true;
}

// The BLEND coverage mask (docs/engine.md "Alpha"): sample i of the pixel's n is covered when
// surfacePresent(alpha, fract(h + i / n)), h a hash of the pixel (Wyman and McGuire 2017, "Hashed
// Alpha Testing", with the pixel as the hash's key): round(alpha n) stratified samples, each covered
// with probability alpha, as the tracer keeps a hit with probability alpha. OPAQUE and MASK: all.
uint pixelHashPcg(uvec2 p) {
  // PCG-based 2D hash (Jarzynski and Olano 2020, "Hash Functions for GPU Rendering", pcg2d).
  uvec2 v = p * 1664525u + 1013904223u;
  v.x += v.y * 1664525u;
  v.y += v.x * 1664525u;
  v ^= v >> 16u;
  v.x += v.y * 1664525u;
  v.y += v.x * 1664525u;
  v ^= v >> 16u;
  return v.x;
}

int coverageMask(float alpha, uvec2 pixel, int samples) {
  if (alphaMode != kAlphaModeBlend) return -1;
  float h = float(pixelHashPcg(pixel) >> 8u) * (1.0 / 16777216.0);
  int mask = 0;
  for (int i = 0; i < samples; ++i)
    if (surfacePresent(alpha, fract(h + float(i) / float(samples)))) mask |= 1 << i;
  return mask;
}
