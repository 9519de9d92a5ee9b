// Order-3 real spherical harmonics (core/spherical_harmonics.h: Sloan 2008, "Stupid
// Spherical Harmonics (SH) Tricks", Appendix A1; k = l(l+1) + m, orthonormal).

// shBasis9 of core/spherical_harmonics.h (Sloan 2008, Appendix A1).
void shBasis9(vec3 d, out float y[9]) {
  y[0] = 0.282094792;
  y[1] = 0.488602512 * d.y;
  y[2] = 0.488602512 * d.z;
  y[3] = 0.488602512 * d.x;
  y[4] = 1.092548431 * d.x * d.y;
  y[5] = 1.092548431 * d.y * d.z;
  y[6] = 0.315391565 * (3.0 * d.z * d.z - 1.0);
  y[7] = 1.092548431 * d.x * d.z;
  y[8] = 0.546274215 * (d.x * d.x - d.y * d.y);
}

// SphericalHarmonics9::irradiance of core/spherical_harmonics.h, the radiance coefficients L_k
// standing for the object: E(n) = sum_k A_l L_k Y_k(n) with A_0 = pi, A_1 = 2pi/3, A_2 = pi/4
// (Ramamoorthi and Hanrahan 2001, "An Efficient Representation for Irradiance Environment Maps",
// eq. 8). Clamped at 0 (windowing keeps it >= 0 for baked environments).
vec3 sphericalHarmonics9Irradiance(vec3 L[9], vec3 n) {
  float y[9];
  shBasis9(n, y);
  const float A[9] = float[9](kPi, 2.0 * kPi / 3.0, 2.0 * kPi / 3.0, 2.0 * kPi / 3.0, kPi / 4.0, kPi / 4.0,
                              kPi / 4.0, kPi / 4.0, kPi / 4.0);
  vec3 e = vec3(0.0);
  for (int k = 0; k < 9; ++k) e += A[k] * L[k] * y[k];
  return max(e, vec3(0.0));
}

// Shadowed irradiance of precomputed radiance transfer (Sloan, Kautz and Snyder 2002, section 5):
// E = sum_k t_k L_k with the baked transfer t (docs/baker.md, "Normalisation").
vec3 irradiancePrtSloan(vec3 t012, vec3 t345, vec3 t678, vec3 L[9]) {
  float t[9] = float[9](t012.x, t012.y, t012.z, t345.x, t345.y, t345.z, t678.x, t678.y, t678.z);
  vec3 e = vec3(0.0);
  for (int k = 0; k < 9; ++k) e += t[k] * L[k];
  return max(e, vec3(0.0));
}
