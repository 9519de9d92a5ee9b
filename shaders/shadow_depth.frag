#version 450 core
// The depth pass of a light's shadow map (engine/gl/shadow_maps.cpp): the depth test's depth d in
// [0, 1] (0 towards the light), and its exponential moments (d, exp(kShadowExponent (d - 1))) for
// shadow.glsl's prefiltered lookups (the mip chain averages them).

#include "shared_constants.glsl"

layout(location = 0) out vec2 moments;

void main() {
  float d = gl_FragCoord.z;
  moments = vec2(d, exp(kShadowExponent * (d - 1.0)));
}
