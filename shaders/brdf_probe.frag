#version 450 core
// Evaluates functions of brdf.glsl over a table, for tests (tests/gl/specular_occlusion_test.cpp): texel x
// of `inputA` holds (bent normal, ao), of `inputB` (reflection direction, alpha); the output's
// red channel is specularOcclusionCone of them.

#include "environment.glsl"
#include "brdf.glsl"

in vec2 ndc;

uniform sampler2D inputA;
uniform sampler2D inputB;

layout(location = 0) out vec4 fragColor;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 a = texelFetch(inputA, texel, 0);
  vec4 b = texelFetch(inputB, texel, 0);
  fragColor = vec4(specularOcclusionCone(normalize(a.xyz), a.w, normalize(b.xyz), b.w), 0.0, 0.0, 1.0);
}
