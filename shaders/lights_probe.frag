#version 450 core
// Evaluates lights.glsl over a table, for tests (tests/gl/lights_test.cpp compares it with
// core/disk_irradiance.cpp and core/brdf.cpp): texel x of `materialA` holds (baseColor, metallic),
// of `materialB` (specularColor, specular), of `directionO` (wo, roughness), of `directionI` (wi or
// the light's direction, angular radius); the normal is +Z. `quantity` selects the output:
// 0 (uniformDiskIrradiance(wi.z, radius)), 1 evalBrdf(n, wo, wi), 2 diskLightRadiance of radiance 1,
// 3 sunDiskIrradiance(wi.z, sin(radius)).

#include "shared_constants.glsl"
#include "environment.glsl"
#include "brdf.glsl"
#include "lights.glsl"

in vec2 ndc;

uniform sampler2D materialA;
uniform sampler2D materialB;
uniform sampler2D directionO;
uniform sampler2D directionI;
uniform int quantity;

layout(location = 0) out vec4 fragColor;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 a = texelFetch(materialA, texel, 0);
  vec4 b = texelFetch(materialB, texel, 0);
  vec4 o = texelFetch(directionO, texel, 0);
  vec4 i = texelFetch(directionI, texel, 0);
  BrdfLobes lobes = brdfLobes(a.rgb, a.w, o.w, b.w, b.rgb);
  vec3 n = vec3(0.0, 0.0, 1.0);
  if (quantity == 0) fragColor = vec4(uniformDiskIrradiance(i.z, i.w));
  else if (quantity == 3) fragColor = vec4(sunDiskIrradiance(i.z, sin(i.w)));
  else if (quantity == 1) fragColor = vec4(evalBrdf(lobes, n, o.xyz, i.xyz), 1.0);
  else fragColor = vec4(diskLightRadiance(lobes, n, o.xyz, i.xyz, vec3(1.0), vec2(cos(i.w), sin(i.w)),
                                             vec2(cos(1.1 * i.w), cos(0.9 * i.w))), 1.0);
}
