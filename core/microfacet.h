#pragma once
// The isotropic Trowbridge-Reitz (GGX) microfacet distribution with the Smith masking function:
// the specular lobe of the glTF material (brdf.h, docs/material-model.md). alpha = roughness^2.
// Everything is in the local frame where z is the macro-surface normal (frame.h); microfacet
// normals wm and directions w are unit vectors.
//
// References: Trowbridge & Reitz 1975; Walter et al. 2007, "Microfacet Models for Refraction
// through Rough Surfaces" (GGX); Heitz 2014, "Understanding the Masking-Shadowing Function in
// Microfacet-Based BRDFs" (JCGT 3(2)); Heitz 2018, "Sampling the GGX Distribution of Visible
// Normals" (JCGT 7(4)).

#include <glm/glm.hpp>

namespace iblkit {

// Normal distribution D(wm) = alpha^2 / (pi ((wm.z)^2 (alpha^2 - 1) + 1)^2) for wm.z > 0, else 0
// (glTF 2.0 Appendix B.3.2). Normalised so that the projected microfacet area is 1:
// integral of D(wm) wm.z over the hemisphere = 1. Per steradian of wm.
float ggxD(const glm::vec3& wm, float alpha);

// Smith's auxiliary function Lambda(w) = (sqrt(1 + alpha^2 tan^2(theta)) - 1) / 2 (Heitz 2014) and the
// masking function G1(w) = 1 / (1 + Lambda(w)) for w.z > 0.
float ggxLambda(const glm::vec3& w, float alpha);
float ggxG1(const glm::vec3& w, float alpha);

// Height-correlated Smith visibility V = G2 / (4 cos(theta_i) cos(theta_o)) with
// G2 = 1 / (1 + Lambda(wo) + Lambda(wi)) (Heitz 2014), written as in glTF 2.0 Appendix
// B.3.2:  V = 0.5 / (cosI sqrt(cosO^2 (1 - a2) + a2) + cosO sqrt(cosI^2 (1 - a2) + a2)), a2 = alpha^2.
// Requires cosI, cosO > 0.
float ggxSmithVisibility(float cosThetaI, float cosThetaO, float alpha);

// Distribution of normals visible from wo (wo.z > 0), as defined in Heitz 2018:
//   D_wo(wm) = G1(wo) max(0, wo.wm) D(wm) / wo.z,  per steradian of wm.
// Sampling (Heitz 2018, Sections 3-4): stretch wo into the alpha = 1 configuration, sample the
// projected hemisphere there -- a uniform disk sample (here by the concentric map, which keeps
// strata compact; Heitz uses polar coordinates, any uniform disk map is valid) whose second
// coordinate is warped to cover the visible half-ellipse -- lift it onto the hemisphere and
// unstretch the normal.
glm::vec3 sampleGgxVisibleNormal(const glm::vec3& wo, float alpha, glm::vec2 u);
float ggxVisibleNormalPdf(const glm::vec3& wo, const glm::vec3& wm, float alpha);
// The exact inverse of sampleGgxVisibleNormal for a visible normal wm (wm.z > 0, wo.wm > 0):
// stretch wm, project it onto the disk perpendicular to the stretched wo, undo the warp of the
// second coordinate (an affine map, t2 = (t2' - (1 - s) sqrt(1 - t1^2)) / s with s >= 1/2), then
// invert the concentric map.
glm::vec2 invertGgxVisibleNormalSample(const glm::vec3& wo, const glm::vec3& wm, float alpha);

}  // namespace iblkit
