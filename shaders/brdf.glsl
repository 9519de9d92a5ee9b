// The image-based-lighting terms of the material model (docs/material-model.md, glTF 2.0
// Appendix B with KHR_materials_specular, as core/brdf.cpp).

float maxComponent(vec3 v) { return max(v.r, max(v.g, v.b)); }

// BrdfLobes of core/brdf.h: the material's lobes in the form the formulas use, its factors already
// clamped to their glTF ranges (clampedToGltfRanges, on the CPU).
// SPECULAR_LAYER 0: a program for materials without a specular layer (specular and metallic
// factors 0, core/material.h hasSpecularLayer): f0 = f90 = 0, so the specular terms are compiled
// out (mesh.frag, lights.glsl) and the diffuse weight is 1.
#ifndef SPECULAR_LAYER
#define SPECULAR_LAYER 1
#endif

struct BrdfLobes {
  vec3 baseColor;
  float metallic;
  float specular;
  vec3 dielectricF0;  // min(0.04 specularColor, 1), before the specular factor
  vec3 f0, f90;       // the specular layer's Fresnel endpoints, metal and dielectric mixed
  float alpha;
};

// brdfLobes of core/brdf.cpp (glTF 2.0 Appendix B with KHR_materials_specular, "Implementation").
BrdfLobes brdfLobes(vec3 baseColor, float metallic, float roughness, float specular, vec3 specularColor) {
  BrdfLobes l;
  l.baseColor = baseColor;
  l.metallic = metallic;
  l.specular = specular;
  l.dielectricF0 = min(0.04 * specularColor, vec3(1.0));
  l.f0 = mix(specular * l.dielectricF0, baseColor, metallic);
  l.f90 = vec3(mix(specular, 1.0, metallic));
  l.alpha = roughness * roughness;
  return l;
}

// Split-sum specular (Karis 2013, "Real Shading in Unreal Engine 4", "Image Based Lighting"):
// the directional albedo of the lobe with Schlick's Fresnel F0 + (F90 - F0)(1 - v.h)^5 is
// F0 A + F90 B, with (A, B) read from the DFG table at (NoV, roughness) (baker/brdf_lut.h).
vec3 splitSumKaris(vec3 f0, vec3 f90, vec2 dfg) { return f0 * dfg.x + f90 * dfg.y; }

// diffuseWeight of core/brdf.cpp, (1 - metallic)(1 - specular max_rgb(Fd)) with the dielectric
// Fresnel Fd = Schlick(dielectricF0, 1) in split-sum form (splitSumKaris): `fresnel` = (A, B)
// weights Fd = dielectricF0 A + B. The DFG table's (A, B) give Fd's directional average, as
// fullMaterialModel uses it; (1 - (1 - cos)^5, (1 - cos)^5) give Schlick's Fd at cos, the C++ term.
float diffuseWeight(BrdfLobes l, vec2 fresnel) {
  return (1.0 - l.metallic) * (1.0 - l.specular * maxComponent(splitSumKaris(l.dielectricF0, vec3(1.0), fresnel)));
}

// Multiple-scattering energy compensation (Fdez-Aguera 2019, JCGT 8(1); Filament section 4.7.2):
// the single-scattering lobe of albedo E (f0 = 1) is scaled by 1 + f0 (1 / E - 1).
vec3 energyCompensationFdezAguera(vec3 f0, float E) { return 1.0 + f0 * (1.0 / max(E, 1e-4) - 1.0); }

// Solid angle of the intersection of two cones of half-angle cosines cos1, cos2 whose axes are
// at cosine cosD (Oat and Sander 2007, "Ambient Aperture Lighting", section 3: exact when one cone
// holds the other or they are apart, a smoothstep between).
float coneIntersectionSolidAngleOat(float cos1, float cos2, float cosD) {
  float a1 = acos(clamp(cos1, -1.0, 1.0)), a2 = acos(clamp(cos2, -1.0, 1.0));
  float d = acos(clamp(cosD, -1.0, 1.0));
  float smaller = 2.0 * kPi * (1.0 - max(cos1, cos2));
  if (d <= abs(a1 - a2)) return smaller;
  if (d >= a1 + a2) return 0.0;
  float t = 1.0 - (d - abs(a1 - a2)) / (a1 + a2 - abs(a1 - a2));
  return smaller * smoothstep(0.0, 1.0, t);
}

// Specular occlusion from the baked visibility cone (Jimenez et al. 2016, "Practical Real-Time
// Strategies for Accurate Indirect Occlusion", section 6: the cone-cone approximation): the
// visible directions are a cone about the bent normal whose cosine-weighted solid angle is the AO
// (cos = sqrt(1 - ao)); the specular lobe a cone about the reflection r with cos = 0.1^alpha (a
// point for a mirror, about 84 degrees at alpha 1); the occlusion is the share of the lobe's cone
// inside the visibility cone.
float specularOcclusionCone(vec3 bentNormal, float ao, vec3 r, float alpha) {
  float cosVisible = sqrt(clamp(1.0 - ao, 0.0, 1.0));
  float cosLobe = clamp(exp2(-3.32193 * alpha), 0.0, 0.9999);
  float lobe = 2.0 * kPi * (1.0 - cosLobe);
  return clamp(coneIntersectionSolidAngleOat(cosVisible, cosLobe, dot(bentNormal, r)) / lobe, 0.0, 1.0);
}

// Multi-bounce ambient occlusion (Jimenez et al. 2016, "Practical Real-Time Strategies for
// Accurate Indirect Occlusion", section 5, eq. 10): the cubic fit of the occlusion with
// interreflections of a surface of albedo `albedo`, per channel; >= ao.
vec3 multiBounceAoJimenez(float ao, vec3 albedo) {
  vec3 a = 2.0404 * albedo - 0.3324;
  vec3 b = -4.7951 * albedo + 0.6417;
  vec3 c = 2.7552 * albedo + 0.6903;
  return max(vec3(ao), ((ao * a + b) * ao + c) * ao);
}
