#version 450 core
// Shading of the meshes in every mode (engine/gl/shading_mode.h, docs/engine.md). Output: linear
// radiance (or the normal / depth layer); alpha 1 on objects, 0 on the ground.

#include "shared_constants.glsl"
#include "latlong_footprint.glsl"
#include "sh9.glsl"
#include "brdf.glsl"
#include "material.glsl"
#include "lights.glsl"
#include "shadow.glsl"
#include "visibility_cone.glsl"

in VertexData {
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
  vec4 color;
  // The lights modes' residual irradiance (mesh.vert) of the front and of the back face, and the
  // lights' bounce.
  vec3 residualIrradianceFront;
  vec3 residualIrradianceBack;
  vec3 lightsBounce;
#if VERTEX_LIGHTS
  vec4 lightIrradianceFront;
  vec4 lightIrradianceBack;
#endif
}
vertexIn;

// The mode (iblkit::ShadingMode) and the layer (iblkit::FrameLayer) are compile-time constants,
// one program per combination (renderer.cpp defines them): a software rasteriser like llvmpipe
// runs every side of a branch on a uniform, so a single program would cost the sum of all modes.
// The defaults serve glslangValidator.
#ifndef SHADING_MODE
#define SHADING_MODE kShadingModeFull
#endif
#ifndef FRAME_LAYER
#define FRAME_LAYER kFrameLayerRadiance
#endif
// The material's alpha mode (iblkit::AlphaMode as ALPHA_MODE_* macros), one program per mode too.
#ifndef ALPHA_MODE
#define ALPHA_MODE ALPHA_MODE_OPAQUE
#endif
const int mode = SHADING_MODE;
const int layer = FRAME_LAYER;
uniform vec3 cameraPosition;
uniform bool isGround;
// 1 where the baked SH transfer holds interreflection (iblkit-bake --bounces; renderer.cpp): the
// diffuse multi-bounce fit (fullMaterialModelWith) would count that light twice.
uniform int transferInterreflected;
// The material's other factors (material.glsl has those its textures multiply), clamped to the
// glTF ranges on the CPU (clampedToGltfRanges).
uniform float specularWeight;
// The lobes' specular factor: 0 in a program without a specular layer (brdf.glsl's SPECULAR_LAYER),
// a constant the compiler folds.
#if SPECULAR_LAYER
#define SPECULAR_WEIGHT specularWeight
#else
#define SPECULAR_WEIGHT 0.0
#endif
uniform vec3 specularColor;
// TextureSlot bits that are present and switched on (renderer.cpp), and whether the material is
// double-sided (the back face then shades with the normal and tangent negated).
uniform int textureSlots;
uniform bool doubleSided;
// GL_SAMPLES of the target (renderer.cpp; llvmpipe's gl_NumSamples reads 1 on a multisampled one).
uniform int framebufferSamples;
// Environment: SH9 radiance (rotated on the CPU), the lat-long map with its total rotation and
// intensity, the specular chain with the extra rotation only (the scene's is baked into it).
uniform vec3 shRadiance[9];
layout(binding = kTextureUnitLatLong) uniform sampler2D latLongMap;
uniform vec2 latLongRotation;  // cos, sin of -(scene + extra rotation)
uniform float latLongIntensity;
layout(binding = kTextureUnitSpecular) uniform samplerCube specularCube;
uniform vec2 specularRotation;  // cos, sin of -(extra rotation); the irradiance cube's too
uniform float specularLevels;   // number of levels n; level i has roughness i / (n - 1)
layout(binding = kTextureUnitBrdfLut) uniform sampler2D brdfLut;
// The brute-force irradiance cube (env/irradiance.exr), world space like the specular chain.
layout(binding = kTextureUnitIrradiance) uniform samplerCube irradianceCube;

layout(location = 0) out vec4 fragColor;

// Irradiance along the unit direction n from the cube, bilinear between its texel centres.
vec3 irradianceFromCube(vec3 n) { return textureLod(irradianceCube, rotateAboutY(n, specularRotation), 0.0).rgb; }

// The shading normal on the viewer's side, as iblkit-trace chooses it (docs/material-model.md
// "Shading normal"): `n` (the interpolated or normal-mapped normal) flipped to the viewer's side
// of the geometric normal, then turned towards the viewer where it still faces away or nearly
// (silhouettes of coarse meshes, normal maps at grazing angles). `geometric` faces the viewer.
vec3 shadingNormal(vec3 n, vec3 geometric, vec3 v) {
  if (dot(n, geometric) < 0.0) n = -n;
  return shadingNormalFacingViewer(n, v, geometric);
}

// The material model with the split-sum specular read from `prefilteredCube` (the map's chain, or
// the residual's in the lights modes).
vec3 fullMaterialModelWith(samplerCube prefilteredCube, SurfaceMaterial m, vec3 n, vec3 v, float ao, vec3 bent,
                           vec3 irradiance) {
  vec3 albedo = m.baseColor;
  float roughness = m.roughness;
  float NoV = clamp(dot(n, v), 1e-4, 1.0);
  vec3 r = reflect(-v, n);
  BrdfLobes lobes = brdfLobes(m.baseColor, m.metallic, roughness, SPECULAR_WEIGHT, specularColor);
#if SPECULAR_LAYER
  vec3 dfg = textureLod(brdfLut, vec2(NoV, roughness), 0.0).rgb;
  vec3 specularAlbedo = splitSumKaris(lobes.f0, lobes.f90, dfg.xy) * energyCompensationFdezAguera(lobes.f0, dfg.z);
  float lod = roughness * (specularLevels - 1.0);
  vec3 prefiltered = textureLod(prefilteredCube, rotateAboutY(r, specularRotation), lod).rgb;
  float specularOcclusion = specularOcclusionCone(bent, ao, r, lobes.alpha);
  vec3 specular = prefiltered * specularAlbedo * multiBounceAoJimenez(specularOcclusion, lobes.f0);
#else
  // f0 = f90 = 0: no specular, and diffuseWeight is 1 whatever the table's weights.
  vec3 dfg = vec3(0.0);
  vec3 specular = vec3(0.0);
#endif
  // The baked transfer already holds the visibility (one bounce of shadowing); the multi-bounce
  // fit adds the light interreflected inside the occluded region, as a ratio to plain AO. Not
  // where the transfer holds the interreflection itself (a bake with --bounces), except in
  // full-gltf-ao, whose irradiance is SH9 times the asset's occlusion, not the transfer.
  bool transferBounced = transferInterreflected != 0 && mode != kShadingModeFullGltfAo;
  vec3 bounce = transferBounced ? vec3(1.0) : multiBounceAoJimenez(ao, albedo) / max(ao, 1e-3);
  // The diffuse base is weighted by what the dielectric layer leaves, with Fd's directional
  // average dielectricF0 A + B in place of the per-direction Schlick term (brdf.glsl).
  vec3 diffuse = diffuseWeight(lobes, dfg.xy) * albedo / kPi * irradiance * bounce;
  return diffuse + specular;
}

vec3 fullMaterialModel(SurfaceMaterial m, vec3 n, vec3 v, float ao, vec3 bent, vec3 irradiance) {
  return fullMaterialModelWith(specularCube, m, n, v, ao, bent, irradiance);
}

// visibility_cone.glsl's axis from the pixel's interpolated bent normal.
vec3 visibilityConeAxis(vec3 n, float ao) { return visibilityConeAxis(vertexIn.bentNormal, n, ao); }

#include "dominant_lights.glsl"

void main() {
  vec3 v = normalize(cameraPosition - vertexIn.position);
  // Screen derivatives (and every texture read) before any discard: the quad is still whole.
  vec3 geometric = normalize(cross(dFdx(vertexIn.position), dFdy(vertexIn.position)));
  if (dot(geometric, v) < 0.0) geometric = -geometric;
  // The side being shaded (surface_material.h): a double-sided material's back face negates the
  // normal and the tangent's xyz, w kept. Single-sided back faces are culled (renderer.cpp).
  float side = (doubleSided && !gl_FrontFacing) ? -1.0 : 1.0;
  SurfaceInputs inputs;
  inputs.texcoords[0] = vertexIn.texcoord0;
  inputs.texcoords[1] = vertexIn.texcoord1;
  inputs.normal = side * normalize(vertexIn.normal);
  float tangentLength2 = dot(vertexIn.tangent.xyz, vertexIn.tangent.xyz);
  inputs.tangent = tangentLength2 > 0.0 ? vec4(side * vertexIn.tangent.xyz * inversesqrt(tangentLength2), vertexIn.tangent.w < 0.0 ? -1.0 : 1.0) : vec4(0.0);
  inputs.slots = textureSlots;
  inputs.vertexColor = vertexIn.color;
  SurfaceMaterial m = evaluateSurfaceMaterial(inputs);
#if !SPECULAR_LAYER
  m.metallic = 0.0;  // the factor is 0 (hasSpecularLayer), so the texture's product is too
#endif
  vec3 n = shadingNormal(m.normal, geometric, v);
  // The mirror's lookup takes screen derivatives of its direction (sampleLatLongFootprint): here,
  // before any discard, in a branch on a uniform.
  vec3 mirrorRadiance = vec3(0.0);
  if (mode == kShadingModeMirror)
    mirrorRadiance = latLongIntensity * sampleLatLongFootprint(latLongMap, rotateAboutY(reflect(-v, n), latLongRotation));
  // Alpha (docs/engine.md "Alpha"), in every layer: MASK exact, BLEND as coverage of the samples.
  // Compiled in for those modes only (ALPHA_MODE, renderer.cpp): a shader that may discard or
  // write gl_SampleMask loses the early depth test, which opaque meshes keep.
#if ALPHA_MODE == ALPHA_MODE_MASK
  if (!surfacePresent(m.alpha, 0.0)) discard;
#elif ALPHA_MODE == ALPHA_MODE_BLEND
  // A single-sample target ignores gl_SampleMask (no multisample fragment operations): there the
  // one sample's bit decides through discard.
  int sampleMask = coverageMask(m.alpha, uvec2(gl_FragCoord.xy), max(framebufferSamples, 1));
  if (sampleMask == 0) discard;
  gl_SampleMask[0] = sampleMask;
#endif
  float coverage = isGround ? 0.0 : 1.0;
  if (layer == kFrameLayerNormal) {
    fragColor = vec4(n, coverage);
    return;
  }
  if (layer == kFrameLayerDepth) {
    fragColor = vec4(vec3(distance(cameraPosition, vertexIn.position)), coverage);
    return;
  }
  vec3 albedo = m.baseColor;
  float ao = clamp(vertexIn.ao, 0.0, 1.0);
  // The material's glTF occlusion (occlusionTexture R, 1 + strength (R - 1)); 1 without one.
  float gltfOcclusion = m.occlusion;
  vec3 radiance;
  if (mode == kShadingModeUnlit) {
    radiance = albedo;
  } else if (mode == kShadingModeMirror) {
    radiance = mirrorRadiance;
  } else if (mode == kShadingModeSh) {
    radiance = albedo / kPi * sphericalHarmonics9Irradiance(shRadiance, n);
  } else if (mode == kShadingModeIrradiance) {
    radiance = albedo / kPi * irradianceFromCube(n);
  } else if (mode == kShadingModeIrradianceAoBent) {
    radiance = albedo / kPi * irradianceFromCube(normalize(vertexIn.bentNormal)) * ao;
  } else if (mode == kShadingModeShAo) {
    radiance = albedo / kPi * sphericalHarmonics9Irradiance(shRadiance, n) * ao;
  } else if (mode == kShadingModeShAoBent) {
    vec3 bent = normalize(vertexIn.bentNormal);
    radiance = albedo / kPi * sphericalHarmonics9Irradiance(shRadiance, bent) * ao;
  } else if (mode == kShadingModeLights || mode == kShadingModeLightsShadowed) {
    vec3 residualIrradiance = side < 0.0 ? vertexIn.residualIrradianceBack : vertexIn.residualIrradianceFront;
#if VERTEX_LIGHTS
    vec4 lightIrradiance = side < 0.0 ? vertexIn.lightIrradianceBack : vertexIn.lightIrradianceFront;
#else
    vec4 lightIrradiance = vec4(0.0);  // not read: the lights' terms are the pixel's
#endif
    radiance = dominantLightsModel(m, n, v, ao, residualIrradiance, lightIrradiance, vertexIn.position, geometric,
                                   mode == kShadingModeLightsShadowed);
  } else if (mode == kShadingModeFullGltfAo) {
    // The asset's AO in place of the baked visibility: unshadowed SH9 irradiance times it, the
    // specular cone about n (glTF's occlusion has no direction).
    vec3 irradiance = sphericalHarmonics9Irradiance(shRadiance, n) * gltfOcclusion;
    radiance = fullMaterialModel(m, n, v, gltfOcclusion, n, irradiance);
  } else {
    vec3 irradiance = irradiancePrtSloan(vertexIn.transfer012, vertexIn.transfer345, vertexIn.transfer678, shRadiance);
    if (mode == kShadingModePrt) {
      radiance = albedo / kPi * irradiance;
    } else if (mode == kShadingModeFullBothAo) {
      // Both: the baked visibility (in the transfer and the cone's axis) times the asset's AO.
      radiance = fullMaterialModel(m, n, v, ao * gltfOcclusion, visibilityConeAxis(n, ao), irradiance * gltfOcclusion);
    } else {
      radiance = fullMaterialModel(m, n, v, ao, visibilityConeAxis(n, ao), irradiance);
    }
  }
  if (mode != kShadingModeUnlit) radiance += m.emissive;
  fragColor = vec4(radiance, coverage);
}
