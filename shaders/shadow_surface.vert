#version 450 core
// The shadow mask's surface pass (engine/gl/shadow_mask.h): mesh.vert's position alone. Its
// gl_Position is mesh.vert's expression of the same inputs, invariant in both, so that the pass
// rasterises the lit pass's fragments exactly (GLSL 4.50 section 4.8.1).

#include "shared_constants.glsl"

layout(location = kAttributePosition) in vec3 inPosition;

uniform mat4 viewProjection;

out vec3 worldPosition;

invariant gl_Position;

void main() {
  worldPosition = inPosition;
  gl_Position = viewProjection * vec4(inPosition, 1.0);
}
