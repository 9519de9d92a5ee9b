#include "core/brdf.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

#include "core/frame.h"
#include "core/image.h"
#include "core/microfacet.h"
#include "core/sampling.h"

namespace iblkit {

namespace {

constexpr float kPi = glm::pi<float>();

float maxComponent(const glm::vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }

// Schlick 1994: F = f0 + (f90 - f0) (1 - cos)^5, cos = v.h (glTF 2.0 Appendix B.3.4).
glm::vec3 schlickFresnel(const glm::vec3& f0, const glm::vec3& f90, float cosTheta) {
  const float m = std::clamp(1.0f - cosTheta, 0.0f, 1.0f);
  const float m2 = m * m;
  return f0 + (f90 - f0) * (m2 * m2 * m);
}

using Lobes = BrdfLobes;

}  // namespace

BrdfLobes brdfLobes(const Material& material) { return brdfLobes(clampedFactors(material)); }

BrdfLobes brdfLobes(const GltfRangeFactors& m) {
  BrdfLobes l;
  l.baseColor = m.baseColor;
  l.metallic = m.metallic;
  l.specular = m.specular;
  // KHR_materials_specular, "Implementation": the product of specular color and the f0 of
  // ior 1.5 is clamped to 1 before the specular factor scales it.
  l.dielectricF0 = glm::min(0.04f * m.specularColor, glm::vec3(1.0f));
  l.f0 = glm::mix(l.specular * l.dielectricF0, l.baseColor, l.metallic);
  l.f90 = glm::vec3(glm::mix(l.specular, 1.0f, l.metallic));
  l.alpha = m.roughness * m.roughness;
  l.delta = l.alpha < kDeltaAlpha;
  // The diffuse weight (1 - specular max(Fd)) vanishes everywhere only when specular = 1 and
  // max(dielectricF0) = 1, because max(Fd) ranges over [max(dielectricF0), 1].
  l.hasDiffuse = (1.0f - l.metallic) * maxComponent(l.baseColor) > 0.0f &&
                 l.specular * maxComponent(l.dielectricF0) < 1.0f;
  l.hasSpecular = maxComponent(l.f90) > 0.0f;
  return l;
}

glm::vec3 specularFresnel(const BrdfLobes& l, float cosThetaD) {
  return schlickFresnel(l.f0, l.f90, cosThetaD);
}

float diffuseWeight(const BrdfLobes& l, float cosThetaD) {
  const float fresnelMax = maxComponent(schlickFresnel(l.dielectricF0, glm::vec3(1.0f), cosThetaD));
  return (1.0f - l.metallic) * (1.0f - l.specular * fresnelMax);
}

namespace {

float specularProbability(const Lobes& l, float cosThetaO) {
  if (!l.hasSpecular) return 0.0f;
  if (!l.hasDiffuse) return 1.0f;
  const float es = luminance(specularFresnel(l, cosThetaO));
  const float ed = luminance(diffuseWeight(l, cosThetaO) * l.baseColor);
  const float p = es + ed > 0.0f ? es / (es + ed) : 0.5f;
  return std::clamp(p, 0.1f, 0.9f);
}

// Local frame (z = n) versions of eval, pdf and sample.
glm::vec3 evalLocal(const Lobes& l, const glm::vec3& wo, const glm::vec3& wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
  const glm::vec3 wm = glm::normalize(wo + wi);
  const float cosThetaD = std::clamp(glm::dot(wo, wm), 0.0f, 1.0f);
  glm::vec3 f = (diffuseWeight(l, cosThetaD) * l.baseColor) / kPi;
  if (l.hasSpecular && !l.delta) {
    f += specularFresnel(l, cosThetaD) * (ggxD(wm, l.alpha) * ggxSmithVisibility(wi.z, wo.z, l.alpha));
  }
  return f;
}

// pSpecular = specularProbability(l, wo.z), passed in because sampling needs it too.
float pdfLocal(const Lobes& l, const glm::vec3& wo, const glm::vec3& wi, float pSpecular) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  float pdf = (1.0f - pSpecular) * cosineHemispherePdf(wi.z);
  if (pSpecular > 0.0f && !l.delta) {
    // Reflection maps the microfacet-normal density to directions with the Jacobian
    // 1 / (4 wo.wm) (Walter et al. 2007, eq. 14).
    const glm::vec3 wm = glm::normalize(wo + wi);
    pdf += pSpecular * ggxVisibleNormalPdf(wo, wm, l.alpha) / (4.0f * glm::dot(wo, wm));
  }
  return pdf;
}

// A sample in the local frame; wi is converted to world space by the caller.
BrdfSample sampleLocal(const Lobes& l, const glm::vec3& wo, glm::vec2 u, float uLobe) {
  BrdfSample s;
  if (wo.z <= 0.0f) return s;
  const float pSpecular = specularProbability(l, wo.z);
  glm::vec3 wi;
  if (uLobe < pSpecular) {
    if (l.delta) {
      s.wi = glm::vec3(-wo.x, -wo.y, wo.z);
      s.weight = specularFresnel(l, wo.z) / pSpecular;
      s.pdf = pSpecular;
      s.delta = true;
      return s;
    }
    const glm::vec3 wm = sampleGgxVisibleNormal(wo, l.alpha, u);
    wi = glm::normalize(glm::reflect(-wo, wm));
  } else {
    wi = sampleCosineHemisphere(u);
  }
  if (wi.z <= 0.0f) return s;  // reflected below the horizon: absorbed
  s.pdf = pdfLocal(l, wo, wi, pSpecular);
  if (s.pdf <= 0.0f) return BrdfSample{};
  s.wi = wi;
  s.weight = evalLocal(l, wo, wi) * (wi.z / s.pdf);
  return s;
}

BrdfSample toWorld(BrdfSample s, const Frame& frame) {
  if (s.valid()) s.wi = frame.toWorld(s.wi);
  return s;
}

}  // namespace

glm::vec3 evalBrdf(const Material& material, const glm::vec3& n, const glm::vec3& wo, const glm::vec3& wi) {
  const Frame frame = Frame::fromZ(n);
  return evalLocal(brdfLobes(material), frame.toLocal(wo), frame.toLocal(wi));
}

BrdfSample sampleBrdf(const Material& material, const glm::vec3& n, const glm::vec3& wo, glm::vec2 u,
                      float uLobe) {
  const Frame frame = Frame::fromZ(n);
  return toWorld(sampleLocal(brdfLobes(material), frame.toLocal(wo), u, uLobe), frame);
}

float pdfBrdf(const Material& material, const glm::vec3& n, const glm::vec3& wo, const glm::vec3& wi) {
  const Frame frame = Frame::fromZ(n);
  const Lobes lobes = brdfLobes(material);
  const glm::vec3 woLocal = frame.toLocal(wo);
  return pdfLocal(lobes, woLocal, frame.toLocal(wi), specularProbability(lobes, woLocal.z));
}

BrdfAtPoint::BrdfAtPoint(const Material& material, const glm::vec3& n, const glm::vec3& wo)
    : BrdfAtPoint(brdfLobes(material), n, wo) {}

BrdfAtPoint::BrdfAtPoint(const BrdfLobes& lobes, const glm::vec3& n, const glm::vec3& wo)
    : frame_(Frame::fromZ(n)), woLocal_(frame_.toLocal(wo)), lobes_(lobes) {
  pSpecular_ = specularProbability(lobes_, woLocal_.z);
}

glm::vec3 BrdfAtPoint::eval(const glm::vec3& wi) const {
  return evalLocal(lobes_, woLocal_, frame_.toLocal(wi));
}

float BrdfAtPoint::pdf(const glm::vec3& wi) const {
  return pdfLocal(lobes_, woLocal_, frame_.toLocal(wi), pSpecular_);
}

BrdfSample BrdfAtPoint::sample(glm::vec2 u, float uLobe) const {
  return toWorld(sampleLocal(lobes_, woLocal_, u, uLobe), frame_);
}

float specularLobeProbability(const Material& material, float cosThetaO) {
  return specularProbability(brdfLobes(material), cosThetaO);
}

float evalPhongLobe(const PhongLobe& lobe, const glm::vec3& n, const glm::vec3& wo, const glm::vec3& wi) {
  if (glm::dot(wo, n) <= 0.0f || glm::dot(wi, n) <= 0.0f) return 0.0f;
  const glm::vec3 mirror = glm::reflect(-wo, n);
  const float cosAlpha = std::max(0.0f, glm::dot(wi, mirror));
  return (lobe.exponent + 2.0f) / (2.0f * kPi) * std::pow(cosAlpha, lobe.exponent);
}

float pdfPhongLobe(const PhongLobe& lobe, const glm::vec3& n, const glm::vec3& wo, const glm::vec3& wi) {
  if (glm::dot(wo, n) <= 0.0f || glm::dot(wi, n) <= 0.0f) return 0.0f;
  return cosinePowerLobePdf(glm::dot(wi, glm::reflect(-wo, n)), lobe.exponent);
}

BrdfSample samplePhongLobe(const PhongLobe& lobe, const glm::vec3& n, const glm::vec3& wo, glm::vec2 u) {
  BrdfSample s;
  const float cosThetaO = glm::dot(wo, n);
  if (cosThetaO <= 0.0f) return s;
  const glm::vec3 mirror = glm::reflect(-wo, n);
  const glm::vec3 local = sampleCosinePowerLobe(u, lobe.exponent);
  const glm::vec3 wi = glm::normalize(Frame::fromZ(mirror).toWorld(local));
  const float cosThetaI = glm::dot(wi, n);
  if (cosThetaI <= 0.0f) return s;  // the lobe reaches below the surface: absorbed
  s.pdf = pdfPhongLobe(lobe, n, wo, wi);
  if (s.pdf <= 0.0f) return BrdfSample{};
  s.wi = wi;
  s.weight = glm::vec3(evalPhongLobe(lobe, n, wo, wi) * cosThetaI / s.pdf);
  return s;
}

}  // namespace iblkit
