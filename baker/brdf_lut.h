#pragma once
// The split-sum DFG table of the GGX specular lobe (Karis 2013, "Real Shading in Unreal Engine 4",
// SIGGRAPH course notes, section "Image Based Lighting"): the directional albedo of the specular
// BRDF with Schlick's Fresnel F = f0 + (1 - f0) (1 - V.H)^5 splits into
//   integral f(l, v) cos(theta_l) dl = f0 * A + B,
//   A = integral (f / F) (1 - (1 - V.H)^5) cos(theta_l) dl,   B = integral (f / F) (1 - V.H)^5 cos(theta_l)
//   dl,
// with f / F = D * V_smith (microfacet.h: GGX D, height-correlated Smith visibility, alpha =
// perceptual roughness^2). docs/prefilter.md.

#include <cstdint>
#include <glm/glm.hpp>

#include "core/image.h"

namespace iblkit {

// (A, B, A + B) at one (NoV, perceptual roughness), NoV in (0, 1], roughness in [0, 1]. Sampled
// with `sampleCount` Hammersley points warped to GGX visible normals (Heitz 2018; the estimator
// is then 4 V_smith NoL NoV / G1(V) per sample, low variance at grazing angles too).
// A + B is E(NoV), the directional albedo of the lobe with f0 = 1, which the multiple-scattering
// compensation needs (Fdez-Agüera 2019, "A Multiple-Scattering Microfacet Model for Real-Time
// Image-based Lighting", JCGT 8(1); Filament section 4.7.2): specular *= 1 + f0 (1 / E - 1).
glm::vec3 integrateDfg(float NoV, float roughness, std::uint32_t sampleCount);

// The table as a size x size image. Texel (x, y) holds integrateDfg at its centre:
//   NoV = (x + 0.5) / size (left to right), roughness = (y + 0.5) / size (row 0 = smoothest),
// so uploaded with row 0 first, texture(lut, vec2(NoV, roughness)) reads it.
//   R = A (scale of f0), G = B (bias), B = A + B = E (for the multi-scattering term), alpha 1.
// Parallel over rows (TBB). Throws std::invalid_argument unless size >= 1 and sampleCount >= 1.
Image computeBrdfLut(int size = 128, std::uint32_t sampleCount = 512);

}  // namespace iblkit
