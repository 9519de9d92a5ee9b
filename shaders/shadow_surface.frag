#version 450 core
// The shadow mask's first pass (engine/gl/shadow_mask.h): the visible receivers' world position
// and geometric normal, per pixel, for shadow_mask.frag. Drawn with shadow_surface.vert, whose
// fragments are the lit pass's (invariant gl_Position), with mesh.frag's derivatives: the same
// geometric normal.

in vec3 worldPosition;

// x, y, z: the position's float bits; w: the unit geometric normal, octahedral (Cigolle et al.
// 2014, "A Survey of Efficient Representations for Independent Unit Vectors") in two snorm16.
layout(location = 0) out uvec4 surface;

vec2 octahedralEncode(vec3 n) {
  vec2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
  return n.z >= 0.0 ? p : (1.0 - abs(p.yx)) * vec2(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
}

void main() {
  vec3 geometric = normalize(cross(dFdx(worldPosition), dFdy(worldPosition)));
  surface = uvec4(floatBitsToUint(worldPosition), packSnorm2x16(octahedralEncode(geometric)));
}
