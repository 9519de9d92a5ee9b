// GLSL twin of core/tone_curve.cpp, each function named as its C++ twin (tested against it
// through a render):
//   display = sRGB_OETF( curve( radiance * 2^exposure ) )
// Curve ids are iblkit::ToneCurve's (kToneCurve..., the generated shared_constants.glsl).

#include "shared_constants.glsl"

// Narkowicz 2015, "ACES Filmic Tone Mapping Curve" (the common ALU fit).
float acesFitted(float x) {
  return min((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 1.0);
}

// One exposed linear channel -> linear display light in [0, 1]; negative and NaN give 0, +Inf 1.
float applyToneCurve(float x, int curve) {
  if (!(x > 0.0)) return 0.0;
  if (isinf(x)) return 1.0;
  if (curve == kToneCurveAcesFitted) return acesFitted(x);
  if (curve == kToneCurveReinhard) return x / (1.0 + x);  // Reinhard et al. 2002, eq. 3
  return min(x, 1.0);
}

// IEC 61966-2-1:1999 section 5.2 OETF, input clamped to [0, 1].
float srgbEncode(float linear) {
  float x = clamp(linear, 0.0, 1.0);
  return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

vec3 toneMap(vec3 radiance, float exposure, int curve) {
  vec3 exposed = radiance * exp2(exposure);
  return vec3(srgbEncode(applyToneCurve(exposed.r, curve)), srgbEncode(applyToneCurve(exposed.g, curve)),
              srgbEncode(applyToneCurve(exposed.b, curve)));
}
