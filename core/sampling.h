#pragma once
// Sampling warps: maps from uniform random numbers u in [0,1)^2 to points distributed with a known
// density, in the family style of pbrt-v4 (Pharr, Jakob, Humphreys, "Physically Based Rendering",
// 4th ed., Appendix A "Sampling Algorithms"): for each warp `sampleX(u)`, its density `xPdf` and its
// inverse `invertXSample` (point -> u, so that invertXSample(sampleX(u)) == u).
//
// Directions are in a local frame with z = the axis (the surface normal; see frame.h), so
// cos(theta) = w.z and phi = atan2(w.y, w.x). Densities of directions are per steradian. The GGX
// visible-normal warp lives with the distribution it samples, in microfacet.h.

#include <glm/glm.hpp>

namespace iblkit {

// Unit disk by the concentric mapping of Shirley & Chiu 1997, "A Low Distortion Map Between Disk
// and Square" (JGT 2(3)): squares around the centre become rings, so strata stay compact.
// Uniform in area: density 1/pi per unit area.
glm::vec2 sampleUniformDiskConcentric(glm::vec2 u);
glm::vec2 invertUniformDiskConcentricSample(glm::vec2 p);

// Uniform over the hemisphere z >= 0: z = u.x, phi = 2 pi u.y. Density 1/(2 pi) for w.z >= 0.
glm::vec3 sampleUniformHemisphere(glm::vec2 u);
float uniformHemispherePdf(const glm::vec3& w);
glm::vec2 invertUniformHemisphereSample(const glm::vec3& w);

// Cosine-weighted hemisphere (Malley's method: the concentric disk sample lifted onto the
// hemisphere). Density cos(theta)/pi for w.z > 0, else 0.
glm::vec3 sampleCosineHemisphere(glm::vec2 u);
float cosineHemispherePdf(float cosTheta);
glm::vec2 invertCosineHemisphereSample(const glm::vec3& w);

// Uniform over the whole sphere: z = 1 - 2 u.x, phi = 2 pi u.y. Density 1/(4 pi).
glm::vec3 sampleUniformSphere(glm::vec2 u);
float uniformSpherePdf();
glm::vec2 invertUniformSphereSample(const glm::vec3& w);

// Uniform over the cone of directions with cos(theta) >= cosThetaMax (in [-1, 1)):
// cos(theta) = 1 - u.x (1 - cosThetaMax), phi = 2 pi u.y. Density 1/(2 pi (1 - cosThetaMax))
// inside, 0 outside.
glm::vec3 sampleUniformCone(glm::vec2 u, float cosThetaMax);
float uniformConePdf(float cosTheta, float cosThetaMax);
glm::vec2 invertUniformConeSample(const glm::vec3& w, float cosThetaMax);

// Cosine-power lobe around z, density (n+1)/(2 pi) cos^n(theta) for cos(theta) > 0: the sampling
// density of the modified Phong lobe (Lafortune & Willems 1994), cos(theta) = u.x^(1/(n+1)),
// phi = 2 pi u.y. The exponent n >= 0; n = 1 is the cosine lobe, n = 0 the uniform hemisphere.
glm::vec3 sampleCosinePowerLobe(glm::vec2 u, float exponent);
float cosinePowerLobePdf(float cosTheta, float exponent);
glm::vec2 invertCosinePowerLobeSample(const glm::vec3& w, float exponent);

// Uniform over a triangle, as barycentric coordinates (b0, b1) of vertices 0 and 1 (b2 = 1 - b0 -
// b1): b0 = 1 - sqrt(u.x), b1 = u.y sqrt(u.x) (Osada et al. 2002, "Shape Distributions", eq. 1).
// The density is 1/area on the triangle, i.e. 2 per unit area of the (b0, b1) plane.
glm::vec2 sampleUniformTriangle(glm::vec2 u);
glm::vec2 invertUniformTriangleSample(glm::vec2 b);

}  // namespace iblkit
