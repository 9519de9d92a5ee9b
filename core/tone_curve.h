#pragma once
// The one tone curve every program uses: the reference's PNG preview, the engine's display
// output and the scorer's LDR images all go through these functions (the GLSL twin in
// shaders/ is tested against them).
//   display = sRGB_OETF( curve( radiance * 2^exposure ) )

#include <glm/glm.hpp>

namespace iblkit {

enum class ToneCurve {
  Clamp,       // identity, clamped to [0,1]
  AcesFitted,  // Narkowicz 2015, "ACES Filmic Tone Mapping Curve" (the common ALU fit)
  Reinhard,    // x / (1 + x), per channel
};

struct ToneMapping {
  float exposure = 0.0f;  // stops
  ToneCurve curve = ToneCurve::AcesFitted;
};

// Maps one linear channel value (already exposed) to linear display light in [0,1]. Negative
// values and NaN give 0, +Inf gives 1, so the result is always finite.
float applyToneCurve(float x, ToneCurve curve);
float srgbEncode(float linear);   // IEC 61966-2-1 OETF, input clamped to [0,1]
float srgbDecode(float encoded);  // its inverse (the EOTF), input clamped to [0,1]
// Linear radiance -> display-referred sRGB in [0,1]: per channel, multiply by 2^exposure, apply
// the curve, sRGB-encode.
glm::vec3 toneMap(const glm::vec3& radiance, const ToneMapping& toneMapping);

}  // namespace iblkit
