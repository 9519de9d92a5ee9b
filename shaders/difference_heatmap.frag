#version 450 core
// The viewer's difference view (engine/view/reference_comparison.h): per pixel, the relative
// difference of the live frame from the path-traced reference, |live - ref| / (ref + 0.01) averaged
// over R, G and B (the relMSE's per-pixel term, unsquared), shown on a black-blue-green-yellow-red
// ramp where `scale` is red.

in vec2 ndc;

uniform sampler2D liveTexture;
uniform sampler2D referenceTexture;
uniform float scale;

layout(location = 0) out vec4 fragColor;

vec3 heatRamp(float t) {
  const vec3 stops[5] = vec3[5](vec3(0.0), vec3(0.0, 0.1, 0.9), vec3(0.0, 0.8, 0.2), vec3(1.0, 0.9, 0.0),
                                vec3(1.0, 0.0, 0.0));
  float x = clamp(t, 0.0, 1.0) * 4.0;
  int i = min(int(x), 3);
  return mix(stops[i], stops[i + 1], x - float(i));
}

void main() {
  vec2 uv = ndc * 0.5 + 0.5;
  vec3 live = texture(liveTexture, uv).rgb;
  vec3 reference = texture(referenceTexture, uv).rgb;
  vec3 relative = abs(live - reference) / (abs(reference) + 0.01);
  float difference = (relative.r + relative.g + relative.b) / 3.0;
  fragColor = vec4(heatRamp(difference / max(scale, 1e-6)), 1.0);
}
