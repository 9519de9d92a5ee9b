#version 450 core
// The planar ground's visibility of every light (engine/gl/shadow_maps.h, GroundVisibilityFrame),
// per texel of a texture over the ground's plane: shadow.glsl's shadowVisibilities at the texel's
// point. Rendered with the maps, when the lights change; the lit pass reads it on the ground
// (groundShadowVisibilities) in place of the per-pixel lookups or the mask.

#include "shared_constants.glsl"
#include "shadow.glsl"

uniform vec3 groundOrigin;  // the plane's point at the texture's corner
uniform vec3 groundStepU;   // a texel's sides in world space
uniform vec3 groundStepV;
uniform vec3 groundNormal;

layout(location = 0) out vec4 visibility;

void main() {
  vec3 p = groundOrigin + gl_FragCoord.x * groundStepU + gl_FragCoord.y * groundStepV;
  // Beyond the texture the sampler repeats its edge texels: where the edge is the ground's, no
  // ground is there; elsewhere the edge runs along the maps' borders or outside them, which no
  // object shadows (fitShadowFrame's margin), so the edge texels are lit.
  visibility = shadowVisibilities(p, groundNormal);
}
