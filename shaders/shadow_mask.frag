#version 450 core
// The shadow mask's second pass (engine/gl/shadow_mask.h): per receiver pixel (the stencil test
// keeps those shadow_surface.frag wrote), the visibility of each drawn light from the surface
// there, shadow.glsl's shadowVisibilities, in component i.

#include "shared_constants.glsl"
#include "shadow.glsl"

layout(binding = kTextureUnitShadowSurface) uniform usampler2D shadowSurface;

// MASK_BITS 16 (the mask at the frame's resolution): lights 0 and 1 in x, 2 and 3 in y, two unorm16
// each; 8 (a coarser mask): light i in byte i of x, so that one textureGather brings 4 pixels'
// visibilities of every light (shadow.glsl's upsampledShadowMask).
#if MASK_BITS == 16
layout(location = 0) out uvec2 visibility;
#else
layout(location = 0) out uint visibility;
#endif

vec3 octahedralDecode(vec2 p) {
  vec3 n = vec3(p, 1.0 - abs(p.x) - abs(p.y));
  float t = max(-n.z, 0.0);
  n.xy += vec2(n.x >= 0.0 ? -t : t, n.y >= 0.0 ? -t : t);
  return normalize(n);
}

void main() {
  uvec4 surface = texelFetch(shadowSurface, ivec2(gl_FragCoord.xy), 0);
  vec4 v = shadowVisibilities(uintBitsToFloat(surface.xyz), octahedralDecode(unpackSnorm2x16(surface.w)));
#if MASK_BITS == 16
  visibility = uvec2(packUnorm2x16(v.xy), packUnorm2x16(v.zw));
#else
  visibility = packUnorm4x8(v);
#endif
}
