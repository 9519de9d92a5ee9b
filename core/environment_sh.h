#pragma once
// Diffuse lighting of an environment map: its SH9 projection (the irradiance the engine
// evaluates), the optional ringing window, and a brute-force irradiance (every texel as a light) to
// check the SH approximation against. docs/prefilter.md. The env/sh9.json file that stores the
// projection is bakefile/sh9_json.h.

#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "core/cube_map.h"
#include "core/environment_map.h"
#include "core/spherical_harmonics.h"

namespace iblkit {

// L_k = integral L(w) Y_k(w) dw of the environment's world radiance (rotation and intensity
// applied), as the texel-by-texel sum of texelRadiance * Y_k(texelDirection) * texelSolidAngle
// (the midpoint rule with the exact solid angle of each texel). Basis and normalisation are those
// of spherical_harmonics.h (Sloan 2008, Appendix A1). Parallel over rows (TBB), with the same
// result to the last bit on every run and any number of threads.
SphericalHarmonics9 projectEnvironmentSh9(const EnvironmentMap& environment);

// The smallest RGB component of sh.irradiance(n) over `directions`.
float minimumIrradiance(const SphericalHarmonics9& sh, std::span<const glm::vec3> directions);

// `count` unit directions spread evenly over the sphere (the spherical Fibonacci point set,
// Keinert et al. 2015, "Spherical Fibonacci Mapping", section 3), for searches over the sphere.
std::vector<glm::vec3> fibonacciSphere(int count);

// The automatic ringing window (Sloan 2017, "Deringing Spherical Harmonics"): the largest sinc^4
// cutoff (windowSh9) whose windowed irradiance is >= 0 everywhere, found by bisection (16 steps)
// on cutoff in [1, 64]. "Everywhere" is the minimum over 4096 Fibonacci directions (spacing about
// 3.2 degrees; the irradiance is a degree-2 polynomial, so the true minimum is within a hair of it).
// Returns 0 (no window) when the unwindowed irradiance is already >= 0. The bisection assumes the
// minimum rises as the cutoff falls; at cutoff 1 only band 0 is left, so a non-negative
// environment always has a solution.
float automaticShWindowCutoff(const SphericalHarmonics9& sh);

// Irradiance E(n) = sum over texels of L * max(0, n.w) * dOmega (every texel of the environment a
// small light; rotation and intensity applied), at each unit normal. Exact up to the texel
// quadrature; O(normals x texels), parallel over normals (TBB). For tests and comparisons.
std::vector<glm::vec3> bruteForceIrradiance(const EnvironmentMap& environment,
                                            std::span<const glm::vec3> normals);

// A size x size cube map of bruteForceIrradiance at every texel centre (for comparison with the
// SH irradiance; 16 is plenty for a function this smooth). Throws std::invalid_argument for size < 1.
CubeMap bruteForceIrradianceCube(const EnvironmentMap& environment, int size);

}  // namespace iblkit
