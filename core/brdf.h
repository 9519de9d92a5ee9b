#pragma once
// The material model every program shares (docs/material-model.md has the formulas and their
// sources; the GLSL engine implements the same ones): the glTF 2.0 metallic-roughness BRDF
// (glTF 2.0 Specification, Appendix B) with KHR_materials_specular,
//
//   f = (1 - metallic) (1 - specular max_rgb(Fd(v.h))) baseColor / pi    (diffuse base)
//     + F(v.h) D(h) V(l, v)                                              (GGX specular layer)
//
//   Fd = Schlick(f0 = min(0.04 specularColor, 1), f90 = 1)
//   F  = Schlick(F0, F90), F0 = mix(specular min(0.04 specularColor, 1), baseColor, metallic),
//                          F90 = mix(specular, 1, metallic)
//   D = Trowbridge-Reitz (GGX), V = height-correlated Smith visibility, alpha = roughness^2.
//
// So specular = 0 and metallic = 0 give exactly Lambert, baseColor / pi. Parameters are clamped
// to their glTF ranges (baseColor, metallic, roughness, specular in [0,1]; specularColor >= 0).
//
// Conventions: n is the unit shading normal on the side of wo; wo (towards the viewer) and wi
// (towards the light) are unit vectors pointing away from the surface. Directions below the
// surface (wo.n <= 0 or wi.n <= 0) reflect nothing: eval and pdf are 0, sampling fails.
// eval returns the BRDF value f (per steradian, without the cosine).
//
// Sampling picks a lobe with probability from the reflectance each lobe has at wo (see
// specularLobeProbability), then samples the diffuse lobe with a cosine-weighted hemisphere and the
// specular lobe with GGX visible normals (Heitz 2018). The pdf is the mixture of both lobes' pdfs,
// so weight = f cos / pdf and MIS with other strategies works.
//
// Perfect mirrors: alpha < kDeltaAlpha makes the specular lobe a Dirac delta (the reflection
// direction). Sampling it returns delta = true, weight = F(wo.n) / P(specular) and pdf =
// P(specular); evalBrdf and pdfBrdf contain only the non-delta (diffuse) part.

#include <glm/glm.hpp>

#include "core/frame.h"
#include "core/material.h"

namespace iblkit {

// GGX alpha below which the specular lobe is treated as a perfect mirror: pbrt-v4's
// TrowbridgeReitzDistribution::EffectivelySmooth threshold (roughness < ~0.0316).
inline constexpr float kDeltaAlpha = 1e-3f;

struct BrdfSample {
  glm::vec3 wi{0.0f};      // sampled direction (world space, unit)
  glm::vec3 weight{0.0f};  // f cos(theta_i) / pdf; for a delta sample F / P(specular)
  float pdf = 0.0f;        // mixture pdf per steradian; for a delta sample the lobe probability
  bool delta = false;      // wi is the mirror direction of a perfectly smooth specular lobe
  // False when no direction was produced (wo below the surface, or wi fell below it).
  bool valid() const { return pdf > 0.0f; }
};

// f(wo, wi), RGB, per steradian.
glm::vec3 evalBrdf(const Material& material, const glm::vec3& n, const glm::vec3& wo, const glm::vec3& wi);
// Samples wi for wo from u in [0,1)^2 (the direction) and uLobe in [0,1) (the lobe choice).
BrdfSample sampleBrdf(const Material& material, const glm::vec3& n, const glm::vec3& wo, glm::vec2 u,
                      float uLobe);
// The pdf (per steradian) with which sampleBrdf returns the non-delta direction wi.
float pdfBrdf(const Material& material, const glm::vec3& n, const glm::vec3& wo, const glm::vec3& wi);

// The material's lobes in the form the formulas use (docs/material-model.md); BrdfAtPoint keeps
// one so that it is derived once per shading point.
struct BrdfLobes {
  glm::vec3 baseColor{0.0f};
  float metallic = 0.0f;
  float specular = 0.0f;
  glm::vec3 dielectricF0{0.0f};   // min(0.04 specularColor, 1), before the specular factor
  glm::vec3 f0{0.0f}, f90{0.0f};  // the specular layer's Fresnel endpoints, metal and dielectric mixed
  float alpha = 1.0f;
  bool delta = false;        // mirror: alpha < kDeltaAlpha
  bool hasDiffuse = false;   // the diffuse term is non-zero somewhere
  bool hasSpecular = false;  // the specular term is non-zero somewhere
};
// The lobes of `material` (its factors clamped by clampedToGltfRanges, clampedFactors).
BrdfLobes brdfLobes(const Material& material);
// The lobes of factors already clamped to the glTF ranges (clampedFactors, clampedToGltfRanges):
// brdfLobes(material) is brdfLobes(clampedFactors(material)). A textured hit's factors go here
// without a Material (its name and texture refs) built per hit.
BrdfLobes brdfLobes(const GltfRangeFactors& clamped);
// The specular layer's Fresnel tint F(v.h) = Schlick(f0, f90) at cosThetaD = v.h.
glm::vec3 specularFresnel(const BrdfLobes& lobes, float cosThetaD);
// The diffuse base's weight, (1 - metallic)(1 - specular max_rgb(Fd(v.h))) with
// Fd = Schlick(dielectricF0, 1) (KHR_materials_specular fresnel_mix, then glTF's
// mix(dielectric, metal, metallic)).
float diffuseWeight(const BrdfLobes& lobes, float cosThetaD);

// The BRDF of one material at one shading point seen from one direction wo, with what the three
// functions above would each derive again (the lobes, the shading frame, wo in it, the lobe
// probability) derived once: eval, pdf and sample return exactly evalBrdf, pdfBrdf and
// sampleBrdf's results for the same arguments. For a path tracer's vertex, which calls all three.
class BrdfAtPoint {
 public:
  BrdfAtPoint(const Material& material, const glm::vec3& n, const glm::vec3& wo);
  // The same with the material's lobes derived beforehand (brdfLobes(material)), for a renderer
  // that keeps them per material instead of deriving them at every vertex.
  BrdfAtPoint(const BrdfLobes& lobes, const glm::vec3& n, const glm::vec3& wo);
  glm::vec3 eval(const glm::vec3& wi) const;
  float pdf(const glm::vec3& wi) const;
  BrdfSample sample(glm::vec2 u, float uLobe) const;

 private:
  Frame frame_;
  glm::vec3 woLocal_;
  BrdfLobes lobes_;
  float pSpecular_ = 0.0f;
};

// Probability that sampleBrdf picks the specular lobe at cos(theta_o) = n.wo: the reflectances
// both lobes would have if the microfacet normal were n, Es = lum(F(n.wo)) for the specular layer
// and Ed = lum((1 - metallic)(1 - specular max_rgb(Fd(n.wo))) baseColor) for the diffuse base, as
// Es / (Es + Ed) (lum: Rec.709 luminance). Clamped to [0.1, 0.9] when both lobes can reflect, so
// that neither is starved; 1 or 0 when only one can.
float specularLobeProbability(const Material& material, float cosThetaO);

// The modified Phong lobe of Lafortune & Willems 1994, "Using the Modified Phong Reflectance Model
// for Physically Based Rendering": f = (e + 2) / (2 pi) cos^e(alpha), alpha the angle between wi
// and the mirror direction of wo, e the exponent. Energy conserving (albedo exactly 1 at normal
// incidence, below 1 elsewhere). Not a glTF material: a second model for sampling studies, sampled
// by the cosine-power lobe around the mirror direction (pdf (e + 1) / (2 pi) cos^e(alpha)).
// Same conventions as the glTF BRDF above; the weight is grey.
struct PhongLobe {
  float exponent = 1.0f;
};
// The largest exponent the programs take (--phong): far larger ones overflow the lobe's float
// normalisation and pdf into Inf and NaN.
inline constexpr float kMaxPhongExponent = 1e6f;
float evalPhongLobe(const PhongLobe& lobe, const glm::vec3& n, const glm::vec3& wo, const glm::vec3& wi);
BrdfSample samplePhongLobe(const PhongLobe& lobe, const glm::vec3& n, const glm::vec3& wo, glm::vec2 u);
float pdfPhongLobe(const PhongLobe& lobe, const glm::vec3& n, const glm::vec3& wo, const glm::vec3& wi);

}  // namespace iblkit
