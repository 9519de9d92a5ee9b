#version 450 core
// World-space meshes with their baked per-vertex visibility (docs/baker.md). The locations are
// GpuMesh's (engine/gl/gpu_mesh_attribute.h, through the generated shared_constants.glsl).

#include "shared_constants.glsl"

layout(location = kAttributePosition) in vec3 inPosition;
layout(location = kAttributeNormal) in vec3 inNormal;
layout(location = kAttributeAo) in float inAo;
layout(location = kAttributeBentNormal) in vec3 inBentNormal;
layout(location = kAttributeTransfer012) in vec3 inTransfer012;
layout(location = kAttributeTransfer345) in vec3 inTransfer345;
layout(location = kAttributeTransfer678) in vec3 inTransfer678;
// Disabled when the mesh has none: (0, 0) uv and a zero tangent (gpu_mesh_attribute.h).
layout(location = kAttributeTexcoord0) in vec2 inTexcoord0;
layout(location = kAttributeTexcoord1) in vec2 inTexcoord1;
layout(location = kAttributeTangent) in vec4 inTangent;

uniform mat4 viewProjection;

// The shadow mask's surface pass (shadow_surface.vert) computes the same gl_Position: its
// fragments must be the lit pass's exactly.
invariant gl_Position;

out VertexData {
  vec3 position;
  vec3 normal;
  float ao;
  vec3 bentNormal;
  vec3 transfer012;
  vec3 transfer345;
  vec3 transfer678;
  vec2 texcoord0;
  vec2 texcoord1;
  vec4 tangent;
}
vertexOut;

void main() {
  vertexOut.position = inPosition;
  vertexOut.normal = inNormal;
  vertexOut.ao = inAo;
  vertexOut.bentNormal = inBentNormal;
  vertexOut.transfer012 = inTransfer012;
  vertexOut.transfer345 = inTransfer345;
  vertexOut.transfer678 = inTransfer678;
  vertexOut.texcoord0 = inTexcoord0;
  vertexOut.texcoord1 = inTexcoord1;
  vertexOut.tangent = inTangent;
  gl_Position = viewProjection * vec4(inPosition, 1.0);
}
