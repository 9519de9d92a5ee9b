#version 450 core
// Evaluates material.glsl's evaluateSurfaceMaterial (the textured variant) over a table, for tests
// (tests/gl/material_test.cpp compares it with core/surface_material.cpp): texel x of `uvs` holds
// (TEXCOORD_0, TEXCOORD_1), of `normals` the normal, of `tangents` the tangent, of
// `colors` the vertex colour. The material's
// uniforms and textures are the renderer's (material.glsl). `quantity` selects the output:
// 0 (baseColor, alpha), 1 (metallic, roughness, occlusion), 2 emissive, 3 normal,
// 4 (slot 0's and slot 3's transformed uv: textureTransformApply), 5 the base colour texture's
// texel x of level 0 as the texture unit decodes it (texelFetch), 6 shadingNormalFacingViewer with
// n the normal, wo the tangent's xyz and the geometric normal the uvs' xyz.

#define TEXTURED 31  // every slot (kAllTextureSlots)
#include "shared_constants.glsl"
#include "material.glsl"

in vec2 ndc;

uniform sampler2D uvs;
uniform sampler2D normals;
uniform sampler2D tangents;
uniform sampler2D colors;
uniform int quantity;
uniform int probeSlots;

layout(location = 0) out vec4 fragColor;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 uv = texelFetch(uvs, texel, 0);
  SurfaceInputs inputs;
  inputs.texcoords[0] = uv.xy;
  inputs.texcoords[1] = uv.zw;
  inputs.normal = texelFetch(normals, texel, 0).xyz;
  inputs.tangent = texelFetch(tangents, texel, 0);
  inputs.slots = probeSlots;
  inputs.vertexColor = texelFetch(colors, texel, 0);
  SurfaceMaterial m = evaluateSurfaceMaterial(inputs);
  if (quantity == 0) fragColor = vec4(m.baseColor, m.alpha);
  else if (quantity == 1) fragColor = vec4(m.metallic, m.roughness, m.occlusion, 0.0);
  else if (quantity == 2) fragColor = vec4(m.emissive, 0.0);
  else if (quantity == 3) fragColor = vec4(m.normal, 0.0);
  else if (quantity == 4) fragColor = vec4(slotUv(inputs, 0), slotUv(inputs, 3));
  else if (quantity == 6) fragColor = vec4(shadingNormalFacingViewer(inputs.normal, inputs.tangent.xyz, uv.xyz), 0.0);
  else fragColor = texelFetch(baseColorTexture, ivec2(texel.x, 0), 0);
}
