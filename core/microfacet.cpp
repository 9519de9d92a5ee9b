#include "core/microfacet.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <limits>

#include "core/sampling.h"

namespace iblkit {

namespace {

// The orthonormal basis (t1, t2, vh) of Heitz 2018, Section 4.1, around the stretched view
// direction vh; t1 is horizontal, with a fixed choice when vh is the normal.
struct ProjectionBasis {
  glm::vec3 vh, t1, t2;
};

ProjectionBasis projectionBasis(const glm::vec3& wo, float alpha) {
  ProjectionBasis basis;
  basis.vh = glm::normalize(glm::vec3(alpha * wo.x, alpha * wo.y, wo.z));
  const float lengthSquared = basis.vh.x * basis.vh.x + basis.vh.y * basis.vh.y;
  basis.t1 = lengthSquared > 0.0f ? glm::vec3(-basis.vh.y, basis.vh.x, 0.0f) / std::sqrt(lengthSquared)
                                  : glm::vec3(1.0f, 0.0f, 0.0f);
  basis.t2 = glm::cross(basis.vh, basis.t1);
  return basis;
}

}  // namespace

float ggxD(const glm::vec3& wm, float alpha) {
  if (wm.z <= 0.0f) return 0.0f;
  // (wm.z^2 (alpha^2 - 1) + 1) written as sin^2 + alpha^2 cos^2, without the cancellation near
  // wm = n that loses the peak of small alphas in float.
  const float alpha2 = alpha * alpha;
  const float t = wm.x * wm.x + wm.y * wm.y + alpha2 * wm.z * wm.z;
  return alpha2 / (glm::pi<float>() * t * t);
}

float ggxLambda(const glm::vec3& w, float alpha) {
  if (w.z <= 0.0f) return std::numeric_limits<float>::infinity();
  // e = alpha^2 tan^2(theta); (sqrt(1 + e) - 1) / 2 as e / (2 (sqrt(1 + e) + 1)), exact for small e.
  const float e = alpha * alpha * (w.x * w.x + w.y * w.y) / (w.z * w.z);
  return e / (2.0f * (std::sqrt(1.0f + e) + 1.0f));
}

float ggxG1(const glm::vec3& w, float alpha) { return 1.0f / (1.0f + ggxLambda(w, alpha)); }

float ggxSmithVisibility(float cosThetaI, float cosThetaO, float alpha) {
  const float alpha2 = alpha * alpha;
  const float viewTerm = cosThetaI * std::sqrt(cosThetaO * cosThetaO * (1.0f - alpha2) + alpha2);
  const float lightTerm = cosThetaO * std::sqrt(cosThetaI * cosThetaI * (1.0f - alpha2) + alpha2);
  return 0.5f / (viewTerm + lightTerm);
}

glm::vec3 sampleGgxVisibleNormal(const glm::vec3& wo, float alpha, glm::vec2 u) {
  const ProjectionBasis basis = projectionBasis(wo, alpha);
  const glm::vec2 p = sampleUniformDiskConcentric(u);
  // Section 4.2: an affine map of t2 from [-h, h] (h = sqrt(1 - t1^2)) to [-vh.z h, h], the
  // projection of the hemisphere's part above the horizon onto the disk perpendicular to vh.
  const float h = std::sqrt(std::max(0.0f, 1.0f - p.x * p.x));
  const float s = 0.5f * (1.0f + basis.vh.z);
  const float t2 = (1.0f - s) * h + s * p.y;
  // Section 4.3: lift onto the hemisphere around vh; Section 3.4: unstretch.
  const glm::vec3 nh =
      p.x * basis.t1 + t2 * basis.t2 + std::sqrt(std::max(0.0f, 1.0f - p.x * p.x - t2 * t2)) * basis.vh;
  return glm::normalize(glm::vec3(alpha * nh.x, alpha * nh.y, std::max(0.0f, nh.z)));
}

float ggxVisibleNormalPdf(const glm::vec3& wo, const glm::vec3& wm, float alpha) {
  if (wo.z <= 0.0f) return 0.0f;
  const float cosThetaOM = glm::dot(wo, wm);
  if (cosThetaOM <= 0.0f) return 0.0f;
  return ggxG1(wo, alpha) * cosThetaOM * ggxD(wm, alpha) / wo.z;
}

glm::vec2 invertGgxVisibleNormalSample(const glm::vec3& wo, const glm::vec3& wm, float alpha) {
  const ProjectionBasis basis = projectionBasis(wo, alpha);
  const glm::vec3 nh = glm::normalize(glm::vec3(wm.x / alpha, wm.y / alpha, wm.z));
  const float t1 = glm::dot(nh, basis.t1);
  const float h = std::sqrt(std::max(0.0f, 1.0f - t1 * t1));
  const float s = 0.5f * (1.0f + basis.vh.z);
  const float t2 = (glm::dot(nh, basis.t2) - (1.0f - s) * h) / s;
  return invertUniformDiskConcentricSample({t1, t2});
}

}  // namespace iblkit
