// The image-based-lighting terms of the material model (docs/material-model.md, glTF 2.0
// Appendix B with KHR_materials_specular, as engine/core/brdf.cpp).

// Split-sum specular (Karis 2013, "Real Shading in Unreal Engine 4", "Image Based Lighting"):
// the directional albedo of the lobe with Schlick's Fresnel F0 + (F90 - F0)(1 - v.h)^5 is
// F0 A + F90 B, with (A, B) read from the DFG table at (NoV, roughness) (baker/brdf_lut.h).
vec3 splitSumKaris(vec3 f0, vec3 f90, vec2 dfg) { return f0 * dfg.x + f90 * dfg.y; }

// Multiple-scattering energy compensation (Fdez-Aguera 2019, JCGT 8(1); Filament section 4.7.2):
// the single-scattering lobe of albedo E (f0 = 1) is scaled by 1 + f0 (1 / E - 1).
vec3 energyCompensationFdezAguera(vec3 f0, float E) { return 1.0 + f0 * (1.0 / max(E, 1e-4) - 1.0); }

// Specular occlusion from ambient occlusion (Lagarde and de Rousiers 2014, "Moving Frostbite to
// PBR", section 4.10.2, eq. 41): saturate((NoV + ao)^exp2(-16 alpha - 1) - 1 + ao).
float specularOcclusionLagarde(float NoV, float ao, float alpha) {
  return clamp(pow(NoV + ao, exp2(-16.0 * alpha - 1.0)) - 1.0 + ao, 0.0, 1.0);
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

float maxComponent(vec3 v) { return max(v.r, max(v.g, v.b)); }
