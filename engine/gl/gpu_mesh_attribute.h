#pragma once
// The vertex attribute locations of a GpuMesh. shaders/mesh.vert declares its inputs with
// layout(location = kAttribute...) from the generated shared_constants.glsl
// (embed_shaders_tool.cpp), so these values are the one source of both sides. No GL header here:
// the build-time tool includes it.

namespace iblkit {

enum GpuMeshAttribute : unsigned {
  kAttributePosition = 0,
  kAttributeNormal = 1,
  kAttributeAo = 2,
  kAttributeBentNormal = 3,
  kAttributeTransfer012 = 4,
  kAttributeTransfer345 = 5,
  kAttributeTransfer678 = 6,
  // glTF TEXCOORD_0, TEXCOORD_1 and TANGENT (vec4, w the handedness). A mesh without one leaves
  // the attribute disabled: the shader reads the generic value (0, 0, 0, 1), i.e. uv (0, 0) and a
  // zero tangent, which surface_material.h treats as "no tangent".
  kAttributeTexcoord0 = 7,
  kAttributeTexcoord1 = 8,
  kAttributeTangent = 9,
  // glTF COLOR_0 (Mesh::colors, linear RGBA). A mesh without it leaves the attribute disabled and
  // GpuMesh::draw sets its generic value to (1, 1, 1, 1): white, opaque.
  kAttributeColor = 10,
  // The baked suns' bounced light (_SUNBOUNCE), read by the lights modes' programs only. A mesh
  // without it leaves the attribute disabled (the renderer then estimates the bounce).
  kAttributeSunBounce = 11,
};

}  // namespace iblkit
