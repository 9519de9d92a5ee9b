#include "core/tone_curve.h"

#include <algorithm>
#include <cmath>

#include "core/tone_curve_constants.h"

namespace iblkit {

namespace {

// Narkowicz 2015, "ACES Filmic Tone Mapping Curve": a rational fit of the ACES RRT+ODT with
// a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14. Evaluated in double so x² cannot overflow
// for any finite float; the fit passes 1 near x = 7.25 and tends to a/c = 1.033, hence the clamp.
float acesFitted(float x) {
  const double v = x;
  const AcesFitCoefficients& k = kAcesFitted;
  const double mapped = (v * (k.a * v + k.b)) / (v * (k.c * v + k.d) + k.e);
  return static_cast<float>(std::min(mapped, 1.0));
}

}  // namespace

float applyToneCurve(float x, ToneCurve curve) {
  // Negative radiance and NaN map to black, +Inf to white, so no curve ever returns NaN.
  if (!(x > 0.0f)) return 0.0f;
  if (std::isinf(x)) return 1.0f;
  switch (curve) {
    case ToneCurve::Clamp:
      return std::min(x, 1.0f);
    case ToneCurve::AcesFitted:
      return acesFitted(x);
    case ToneCurve::Reinhard:
      return x / (1.0f + x);  // Reinhard et al. 2002, "Photographic Tone Reproduction", eq. 3
  }
  return 0.0f;
}

float srgbEncode(float linear) {
  // IEC 61966-2-1:1999, section 5.2: linear segment below 0.0031308, then a 1/2.4 power.
  const float x = linear > 0.0f ? std::min(linear, 1.0f) : 0.0f;
  return x <= kSrgbLinearLimit ? kSrgbSlope * x : kSrgbScale * std::pow(x, 1.0f / kSrgbGamma) - kSrgbOffset;
}

float srgbDecode(float encoded) {
  // The inverse of srgbEncode (IEC 61966-2-1:1999, section 5.2); 0.04045 = 12.92 * 0.0031308.
  const float v = encoded > 0.0f ? std::min(encoded, 1.0f) : 0.0f;
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

glm::vec3 toneMap(const glm::vec3& radiance, const ToneMapping& toneMapping) {
  const glm::vec3 exposed = radiance * std::exp2(toneMapping.exposure);
  glm::vec3 display;
  for (int c = 0; c < 3; ++c) display[c] = srgbEncode(applyToneCurve(exposed[c], toneMapping.curve));
  return display;
}

}  // namespace iblkit
