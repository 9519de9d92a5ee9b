#version 450 core
// One triangle covering the viewport (no vertex buffer): ndc in [-1, 1]^2 over the screen, at the
// far plane so that it lies behind every mesh.

out vec2 ndc;

void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  ndc = corner * 2.0 - 1.0;
  gl_Position = vec4(ndc, 1.0, 1.0);
}
