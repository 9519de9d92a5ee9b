#version 450 core
// World-space meshes with their baked per-vertex visibility (docs/baker.md).

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in float inAo;
layout(location = 3) in vec3 inBentNormal;
layout(location = 4) in vec3 inTransfer012;
layout(location = 5) in vec3 inTransfer345;
layout(location = 6) in vec3 inTransfer678;

uniform mat4 viewProjection;

out VertexData {
  vec3 position;
  vec3 normal;
  float ao;
  vec3 bentNormal;
  vec3 transfer012;
  vec3 transfer345;
  vec3 transfer678;
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
  gl_Position = viewProjection * vec4(inPosition, 1.0);
}
