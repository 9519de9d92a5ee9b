#pragma once
// Real spherical harmonics up to band 2 (9 coefficients), the basis of the SH9 irradiance every
// program shares: the baker projects the environment, the engine evaluates irradiance, the path
// tracer's analytic test checks against it.
//
// Basis: the real, orthonormal SH of Sloan, "Stupid Spherical Harmonics (SH) Tricks" (2008),
// Appendix A1, evaluated on the world direction (x, y, z) as written there (our +Y is simply the
// y argument; the basis is orthonormal whichever axis is up). Index k = l(l+1) + m.
// Normalisation: integral over the sphere of Y_k Y_j dw = delta_kj (no 4pi or 1/pi folded in).
// Coefficients of radiance: L_k = integral of L(w) Y_k(w) dw (units: radiance x steradian).

#include <array>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

namespace iblkit {

inline constexpr int kShBands = 3;
inline constexpr int kShCoefficients = 9;

using ShBasis9 = std::array<float, kShCoefficients>;

// The 9 basis functions at unit direction d.
ShBasis9 shBasis9(const glm::vec3& d);

// Nine RGB coefficients of a function on the sphere.
struct SphericalHarmonics9 {
  std::array<glm::vec3, kShCoefficients> coefficients{};

  // Reconstructed value sum_k c_k Y_k(d).
  glm::vec3 evaluate(const glm::vec3& d) const;
  // Irradiance E(n) = sum_k A_l c_k Y_k(n) of a radiance projection, with the clamped-cosine
  // convolution constants A_0 = pi, A_1 = 2pi/3, A_2 = pi/4 (Ramamoorthi & Hanrahan, "An
  // Efficient Representation for Irradiance Environment Maps", SIGGRAPH 2001, eq. 8).
  // Lambert radiance of albedo rho is rho * E / pi.
  glm::vec3 irradiance(const glm::vec3& n) const;

  // Adds w * value * Y_k(d) to every coefficient (one term of a quadrature).
  void accumulate(const glm::vec3& d, const glm::vec3& value, float weight);
  SphericalHarmonics9& operator*=(float s);
  SphericalHarmonics9& operator+=(const SphericalHarmonics9& other);
};

// Clamped-cosine convolution constant A_l for band l (0, 1, 2).
float shCosineLobeBand(int l);

// Projects f (a callable glm::vec3(const glm::vec3& direction)) by the midpoint rule on a
// thetaSteps x 2*thetaSteps grid in (theta, phi) around +Y, each cell weighted by its exact solid
// angle. For analytic functions and tests; environment maps project texel by texel.
template <class Function>
SphericalHarmonics9 projectSh9(Function&& f, int thetaSteps) {
  SphericalHarmonics9 sh;
  const int phiSteps = 2 * thetaSteps;
  const float pi = glm::pi<float>();
  const float dPhi = 2.0f * pi / static_cast<float>(phiSteps);
  for (int i = 0; i < thetaSteps; ++i) {
    const float theta0 = pi * static_cast<float>(i) / static_cast<float>(thetaSteps);
    const float theta1 = pi * static_cast<float>(i + 1) / static_cast<float>(thetaSteps);
    const float theta = 0.5f * (theta0 + theta1);
    const float cellSolidAngle = dPhi * (std::cos(theta0) - std::cos(theta1));
    for (int j = 0; j < phiSteps; ++j) {
      const float phi = (static_cast<float>(j) + 0.5f) * dPhi;
      const glm::vec3 d(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      sh.accumulate(d, f(d), cellSolidAngle);
    }
  }
  return sh;
}

// Ringing reduction: multiplies band l by the sinc^4 window w_l = (sin(x)/x)^4, x = pi l / cutoff,
// and 0 for l >= cutoff (a zonal low-pass filter; Sloan, "Deringing Spherical Harmonics",
// SIGGRAPH Asia 2017 technical brief, and Filament's cmgen). cutoff <= 0 returns sh unchanged.
SphericalHarmonics9 windowSh9(const SphericalHarmonics9& sh, float cutoff);

}  // namespace iblkit
