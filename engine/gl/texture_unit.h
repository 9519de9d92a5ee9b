#pragma once
// The texture units the embedded shaders' samplers are bound to. The shaders declare each sampler
// with layout(binding = kTextureUnit...) from the generated shared_constants.glsl
// (embed_shaders_tool.cpp), so C++ binds textures to the units the samplers read without setting
// sampler uniforms, and these values are the one source of both sides. No GL header here: the
// build-time tool includes it.

namespace iblkit {

enum TextureUnit : unsigned {
  kTextureUnitLatLong = 0,    // mesh.frag, sky.frag: the lat-long environment
  kTextureUnitSpecular = 1,   // mesh.frag: the prefiltered specular cube
  kTextureUnitBrdfLut = 2,    // mesh.frag: the DFG table
  kTextureUnitPresent = 3,    // present.frag: the linear frame to tone-map
  kTextureUnitLive = 4,       // difference_heatmap.frag: the live frame
  kTextureUnitReference = 5,  // difference_heatmap.frag: the path-traced reference
  kTextureUnitColorMap = 6,   // difference_heatmap.frag: the heat map's colour map (core/color_map.h)
  // material.glsl: the five glTF material slots (core/material.h), in TextureSlot bit order.
  kTextureUnitBaseColor = 7,
  kTextureUnitMetallicRoughness = 8,
  kTextureUnitNormal = 9,
  kTextureUnitOcclusion = 10,
  kTextureUnitEmissive = 11,
  kTextureUnitIrradiance = 12,  // mesh.frag: the brute-force irradiance cube (the irradiance modes)
  // mesh.frag's lights modes: the residual's specular chain, and the shadow maps (the depths'
  // exponential moments, one mip-mapped texture array, shadow_maps.h).
  kTextureUnitResidualSpecular = 13,
  kTextureUnitShadowDepth = 14,
  kTextureUnitResidualIrradiance = 15,  // mesh.frag's lights modes: the residual's irradiance cube
  // The shadow mask (shadow_mask.h): mesh.frag's lights-shadowed mode reads the mask,
  // shadow_mask.frag the surfaces it is computed from.
  kTextureUnitShadowMask = 16,
  kTextureUnitShadowSurface = 17,
  // The mask's depths (window z of its pixels' surfaces), which mesh.frag's lights-shadowed mode
  // reads to upsample a mask coarser than the frame (shadow.glsl's upsampledShadowMask).
  kTextureUnitShadowMaskDepth = 18,
  // The planar ground's visibility of each light, precomputed in the light's map (shadow_maps.h):
  // mesh.frag's lights-shadowed mode reads it on the ground.
  kTextureUnitShadowGround = 19,
};

}  // namespace iblkit
