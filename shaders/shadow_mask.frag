#version 450 core
// The shadow mask's second pass (engine/gl/shadow_mask.h): per receiver pixel (the stencil test
// keeps those shadow_surface.frag wrote), the visibility of each drawn light from the surface
// there, shadow.glsl's shadowVisibilities, in component i.

#include "shared_constants.glsl"
#include "shadow.glsl"

layout(binding = kTextureUnitShadowSurface) uniform usampler2D shadowSurface;

layout(location = 0) out vec4 visibility;

vec3 octahedralDecode(vec2 p) {
  vec3 n = vec3(p, 1.0 - abs(p.x) - abs(p.y));
  float t = max(-n.z, 0.0);
  n.xy += vec2(n.x >= 0.0 ? -t : t, n.y >= 0.0 ? -t : t);
  return normalize(n);
}

void main() {
  uvec4 surface = texelFetch(shadowSurface, ivec2(gl_FragCoord.xy), 0);
  visibility = shadowVisibilities(uintBitsToFloat(surface.xyz), octahedralDecode(unpackSnorm2x16(surface.w)));
}
