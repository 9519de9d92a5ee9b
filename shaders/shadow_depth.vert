#version 450 core
// The depth pass of a light's shadow map (engine/gl/shadow_maps.cpp): world positions through the
// light's orthographic frame, (u, v, depth) in [0, 1] mapped to clip space.

#include "shared_constants.glsl"

layout(location = kAttributePosition) in vec3 inPosition;

uniform mat4 shadowFromWorld;

void main() {
  vec3 s = (shadowFromWorld * vec4(inPosition, 1.0)).xyz;
  gl_Position = vec4(2.0 * s - 1.0, 1.0);
}
