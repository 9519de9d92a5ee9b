#version 450 core
// The viewer's difference view (engine/view/difference_heat_map.h): per pixel, the scorer's relMSE
// term of the live frame against the path-traced reference, the mean over R, G and B of
// relativeSquaredError (relativeSquaredErrorMap, score/image_metrics.h), through the scorer's magma
// colour map from 0 to `maxValue` (heatMapImage, score/heat_map.h); display-referred sRGB written.

#include "shared_constants.glsl"
#include "tone_curve.glsl"

in vec2 ndc;

layout(binding = kTextureUnitLive) uniform sampler2D liveTexture;
layout(binding = kTextureUnitReference) uniform sampler2D referenceTexture;
// magma (core/color_map.h) in linear RGB, n x 1: texel i holds magma(i / (n - 1)).
layout(binding = kTextureUnitColorMap) uniform sampler2D colorMap;
uniform float maxValue;
// The reference's rectangle in the live frame's texture coordinates (imageViewport,
// engine/view/reference_comparison.h): live uv = offset + uv * scale.
uniform vec2 liveUvOffset;
uniform vec2 liveUvScale;

layout(location = 0) out vec4 fragColor;

// relativeSquaredError of core/relative_squared_error.h, with its epsilon.
float relativeSquaredError(float reference, float test) {
  return (test - reference) * (test - reference) / (reference * reference + kRelMseEpsilon);
}

// magma(t) from the table: the texel centres are t = i / (n - 1), bilinear between them.
vec3 magma(float t) {
  float n = float(textureSize(colorMap, 0).x);
  return textureLod(colorMap, vec2((clamp(t, 0.0, 1.0) * (n - 1.0) + 0.5) / n, 0.5), 0.0).rgb;
}

void main() {
  vec2 uv = ndc * 0.5 + 0.5;
  vec3 live = texture(liveTexture, liveUvOffset + uv * liveUvScale).rgb;
  vec3 reference = texture(referenceTexture, uv).rgb;
  float error = (relativeSquaredError(reference.r, live.r) + relativeSquaredError(reference.g, live.g) +
                 relativeSquaredError(reference.b, live.b)) / 3.0;
  vec3 color = magma(error / maxValue);
  fragColor = vec4(srgbEncode(color.r), srgbEncode(color.g), srgbEncode(color.b), 1.0);
}
