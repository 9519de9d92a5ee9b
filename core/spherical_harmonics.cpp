#include "core/spherical_harmonics.h"

namespace iblkit {

ShBasis9 shBasis9(const glm::vec3& d) {
  // Sloan 2008, Appendix A1: the constants are sqrt((2l+1)/(4pi) (l-|m|)!/(l+|m|)!) times the
  // Legendre factors, written out.
  const float x = d.x, y = d.y, z = d.z;
  return {0.282094792f,
          0.488602512f * y,
          0.488602512f * z,
          0.488602512f * x,
          1.092548431f * x * y,
          1.092548431f * y * z,
          0.315391565f * (3.0f * z * z - 1.0f),
          1.092548431f * x * z,
          0.546274215f * (x * x - y * y)};
}

float shCosineLobeBand(int l) {
  const float pi = glm::pi<float>();
  switch (l) {
    case 0:
      return pi;
    case 1:
      return 2.0f * pi / 3.0f;
    case 2:
      return pi / 4.0f;
    default:
      return 0.0f;
  }
}

namespace {
int bandOf(int k) { return k == 0 ? 0 : (k < 4 ? 1 : 2); }
}  // namespace

glm::vec3 SphericalHarmonics9::evaluate(const glm::vec3& d) const {
  const ShBasis9 y = shBasis9(d);
  glm::vec3 sum(0.0f);
  for (int k = 0; k < kShCoefficients; ++k) sum += coefficients[k] * y[k];
  return sum;
}

glm::vec3 SphericalHarmonics9::irradiance(const glm::vec3& n) const {
  const ShBasis9 y = shBasis9(n);
  glm::vec3 sum(0.0f);
  for (int k = 0; k < kShCoefficients; ++k) sum += shCosineLobeBand(bandOf(k)) * coefficients[k] * y[k];
  return sum;
}

void SphericalHarmonics9::accumulate(const glm::vec3& d, const glm::vec3& value, float weight) {
  const ShBasis9 y = shBasis9(d);
  for (int k = 0; k < kShCoefficients; ++k) coefficients[k] += value * (weight * y[k]);
}

SphericalHarmonics9& SphericalHarmonics9::operator*=(float s) {
  for (glm::vec3& c : coefficients) c *= s;
  return *this;
}

SphericalHarmonics9& SphericalHarmonics9::operator+=(const SphericalHarmonics9& other) {
  for (int k = 0; k < kShCoefficients; ++k) coefficients[k] += other.coefficients[k];
  return *this;
}

SphericalHarmonics9 windowSh9(const SphericalHarmonics9& sh, float cutoff) {
  if (cutoff <= 0.0f) return sh;
  SphericalHarmonics9 out = sh;
  for (int k = 0; k < kShCoefficients; ++k) {
    const int l = bandOf(k);
    float w = 1.0f;
    if (l >= cutoff) {
      w = 0.0f;
    } else if (l > 0) {
      const float x = glm::pi<float>() * static_cast<float>(l) / cutoff;
      const float sinc = std::sin(x) / x;
      w = sinc * sinc * sinc * sinc;
    }
    out.coefficients[k] *= w;
  }
  return out;
}

}  // namespace iblkit
