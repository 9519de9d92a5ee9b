#pragma once
// The constants of the tone curves of tone_curve.h, which tone_curve.cpp evaluates, shared with
// what re-implements the curves outside C++: the report page's exposure control emits them into
// its JavaScript (report/compare_view.cpp). (The GLSL twin in shaders/ is tested against the C++.)
//   ACES fitted (Narkowicz 2015): (x (a x + b)) / (x (c x + d) + e), clamped to 1;
//   sRGB OETF (IEC 61966-2-1): kSrgbSlope x below kSrgbLinearLimit, else kSrgbScale x^(1 / kSrgbGamma) - kSrgbOffset.

namespace iblkit {

struct AcesFitCoefficients {
  double a, b, c, d, e;
};
inline constexpr AcesFitCoefficients kAcesFitted{2.51, 0.03, 2.43, 0.59, 0.14};
inline constexpr float kSrgbLinearLimit = 0.0031308f, kSrgbSlope = 12.92f, kSrgbScale = 1.055f, kSrgbOffset = 0.055f,
                       kSrgbGamma = 2.4f;

}  // namespace iblkit
