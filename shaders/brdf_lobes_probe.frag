#version 450 core
// Evaluates the lobe weights fullMaterialModel (mesh.frag) derives from the material, brdfLobes and
// diffuseWeight of brdf.glsl, over a table, for tests (tests/gl/brdf_lobes_test.cpp): texel x of
// `materialA` holds (baseColor, metallic), of `materialB` (specularColor, specular), of `angle`
// (roughness, cos(theta_d)). Schlick's (1 - cos)^5 weights stand in for the DFG table's (A, B), so
// that the split-sum terms are the per-direction ones of core/brdf.cpp. `quantity` selects the
// output: 0 (f0, alpha), 1 (f90, diffuseWeight), 2 (Fresnel F, specular), 3 (dielectricF0, metallic).

#include "environment.glsl"
#include "brdf.glsl"

in vec2 ndc;

uniform sampler2D materialA;
uniform sampler2D materialB;
uniform sampler2D angle;
uniform int quantity;

layout(location = 0) out vec4 fragColor;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 a = texelFetch(materialA, texel, 0);
  vec4 b = texelFetch(materialB, texel, 0);
  vec4 c = texelFetch(angle, texel, 0);
  BrdfLobes lobes = brdfLobes(a.rgb, a.w, c.x, b.w, b.rgb);
  float m = clamp(1.0 - c.y, 0.0, 1.0);
  float m5 = m * m * m * m * m;
  vec2 schlick = vec2(1.0 - m5, m5);
  if (quantity == 0) fragColor = vec4(lobes.f0, lobes.alpha);
  else if (quantity == 1) fragColor = vec4(lobes.f90, diffuseWeight(lobes, schlick));
  else if (quantity == 2) fragColor = vec4(splitSumKaris(lobes.f0, lobes.f90, schlick), lobes.specular);
  else fragColor = vec4(lobes.dielectricF0, lobes.metallic);
}
