#version 450 core
// A linear float texture shown tone-mapped (the core curve, tone_curve.glsl): display-referred
// sRGB values are written (no GL_FRAMEBUFFER_SRGB).

#include "shared_constants.glsl"
#include "tone_curve.glsl"

in vec2 ndc;

layout(binding = kTextureUnitPresent) uniform sampler2D radianceTexture;
uniform float exposure;
uniform int curve;  // iblkit::ToneCurve

layout(location = 0) out vec4 fragColor;

void main() {
  vec4 radiance = texture(radianceTexture, ndc * 0.5 + 0.5);
  fragColor = vec4(toneMap(radiance.rgb, exposure, curve), radiance.a);
}
