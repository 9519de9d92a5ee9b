#version 450 core
// Shading of the meshes in every mode (engine/gl/shading_mode.h, docs/engine.md). Output: linear
// radiance (or the normal / depth layer); alpha 1 on objects, 0 on the ground.

#include "shared_constants.glsl"
#include "environment.glsl"
#include "sh9.glsl"
#include "brdf.glsl"

in VertexData {
  vec3 position;
  vec3 normal;
  float ao;
  vec3 bentNormal;
  vec3 transfer012;
  vec3 transfer345;
  vec3 transfer678;
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
const int mode = SHADING_MODE;
const int layer = FRAME_LAYER;
uniform vec3 cameraPosition;
uniform bool isGround;
// Material (core/material.h), clamped to the glTF ranges on the CPU (clampedToGltfRanges).
uniform vec3 baseColor;
uniform float metallic;
uniform float roughness;
uniform float specularWeight;
uniform vec3 specularColor;
uniform vec3 emissive;
// Environment: SH9 radiance (rotated on the CPU), the lat-long map with its total rotation and
// intensity, the specular chain with the extra rotation only (the scene's is baked into it).
uniform vec3 shRadiance[9];
layout(binding = kTextureUnitLatLong) uniform sampler2D latLongMap;
uniform vec2 latLongRotation;  // cos, sin of -(scene + extra rotation)
uniform float latLongIntensity;
layout(binding = kTextureUnitSpecular) uniform samplerCube specularCube;
uniform vec2 specularRotation;  // cos, sin of -(extra rotation)
uniform float specularLevels;   // number of levels n; level i has roughness i / (n - 1)
layout(binding = kTextureUnitBrdfLut) uniform sampler2D brdfLut;

layout(location = 0) out vec4 fragColor;

// The shading normal on the viewer's side, as iblkit-trace chooses it (docs/reference-tracer.md):
// the interpolated normal turned towards the viewer, or the geometric normal where it still faces
// away (silhouettes of coarse meshes).
vec3 shadingNormal(vec3 v) {
  vec3 geometric = normalize(cross(dFdx(vertexIn.position), dFdy(vertexIn.position)));
  if (dot(geometric, v) < 0.0) geometric = -geometric;
  vec3 n = normalize(vertexIn.normal);
  if (dot(n, geometric) < 0.0) n = -n;
  return dot(n, v) > 0.0 ? n : geometric;
}

// `ao` is the occlusion the heuristics use (the multi-bounce fit and the specular cone of aperture
// AO about `bent`); `irradiance` the diffuse irradiance with that visibility already in it.
vec3 fullMaterialModel(vec3 n, vec3 v, vec3 albedo, float ao, vec3 bent, vec3 irradiance) {
  float NoV = clamp(dot(n, v), 1e-4, 1.0);
  vec3 r = reflect(-v, n);
  BrdfLobes lobes = brdfLobes(baseColor, metallic, roughness, specularWeight, specularColor);
  vec3 dfg = texture(brdfLut, vec2(NoV, roughness)).rgb;
  vec3 specularAlbedo = splitSumKaris(lobes.f0, lobes.f90, dfg.xy) * energyCompensationFdezAguera(lobes.f0, dfg.z);
  float lod = roughness * (specularLevels - 1.0);
  vec3 prefiltered = textureLod(specularCube, rotateAboutY(r, specularRotation), lod).rgb;
  float specularOcclusion = specularOcclusionCone(bent, ao, r, lobes.alpha);
  vec3 specular = prefiltered * specularAlbedo * multiBounceAoJimenez(specularOcclusion, lobes.f0);
  // The baked transfer already holds the visibility (one bounce of shadowing); the multi-bounce
  // fit adds the light interreflected inside the occluded region, as a ratio to plain AO.
  vec3 bounce = multiBounceAoJimenez(ao, albedo) / max(ao, 1e-3);
  // The diffuse base is weighted by what the dielectric layer leaves, with Fd's directional
  // average dielectricF0 A + B in place of the per-direction Schlick term (brdf.glsl).
  vec3 diffuse = diffuseWeight(lobes, dfg.xy) * albedo / kPi * irradiance * bounce;
  return diffuse + specular;
}

// The axis of the visibility cone: the baked bent normal, turned towards n as the AO nears 1. An
// unoccluded vertex sees its whole hemisphere, a 90-degree cone about n; its bent normal is n only
// on average, and with few bake rays a tilted one would cut off part of that hemisphere. A fully
// occluded vertex (no bent normal, zero length) keeps n.
vec3 visibilityConeAxis(vec3 n, float ao) {
  float length2 = dot(vertexIn.bentNormal, vertexIn.bentNormal);
  vec3 bent = length2 > 1e-8 ? vertexIn.bentNormal * inversesqrt(length2) : n;
  return normalize(mix(bent, n, ao));
}

void main() {
  vec3 v = normalize(cameraPosition - vertexIn.position);
  vec3 n = shadingNormal(v);
  float coverage = isGround ? 0.0 : 1.0;
  if (layer == kFrameLayerNormal) {
    fragColor = vec4(n, coverage);
    return;
  }
  if (layer == kFrameLayerDepth) {
    fragColor = vec4(vec3(distance(cameraPosition, vertexIn.position)), coverage);
    return;
  }
  vec3 albedo = baseColor;
  float ao = clamp(vertexIn.ao, 0.0, 1.0);
  // The material's glTF occlusion (occlusionTexture R, 1 + strength (R - 1)); 1 without one.
  float gltfOcclusion = 1.0;
  vec3 radiance;
  if (mode == kShadingModeUnlit) {
    radiance = baseColor;
  } else if (mode == kShadingModeMirror) {
    radiance = latLongIntensity * sampleLatLongBilinear(latLongMap, latLongUv(rotateAboutY(reflect(-v, n), latLongRotation)));
  } else if (mode == kShadingModeSh) {
    radiance = albedo / kPi * sphericalHarmonics9Irradiance(shRadiance, n);
  } else if (mode == kShadingModeShAo) {
    radiance = albedo / kPi * sphericalHarmonics9Irradiance(shRadiance, n) * ao;
  } else if (mode == kShadingModeShAoBent) {
    vec3 bent = normalize(vertexIn.bentNormal);
    radiance = albedo / kPi * sphericalHarmonics9Irradiance(shRadiance, bent) * ao;
  } else if (mode == kShadingModeFullGltfAo) {
    // The asset's AO in place of the baked visibility: unshadowed SH9 irradiance times it, the
    // specular cone about n (glTF's occlusion has no direction).
    vec3 irradiance = sphericalHarmonics9Irradiance(shRadiance, n) * gltfOcclusion;
    radiance = fullMaterialModel(n, v, albedo, gltfOcclusion, n, irradiance);
  } else {
    vec3 irradiance = irradiancePrtSloan(vertexIn.transfer012, vertexIn.transfer345, vertexIn.transfer678, shRadiance);
    if (mode == kShadingModePrt) {
      radiance = albedo / kPi * irradiance;
    } else if (mode == kShadingModeFullBothAo) {
      // Both: the baked visibility (in the transfer and the cone's axis) times the asset's AO.
      radiance = fullMaterialModel(n, v, albedo, ao * gltfOcclusion, visibilityConeAxis(n, ao), irradiance * gltfOcclusion);
    } else {
      radiance = fullMaterialModel(n, v, albedo, ao, visibilityConeAxis(n, ao), irradiance);
    }
  }
  if (mode != kShadingModeUnlit) radiance += emissive;
  fragColor = vec4(radiance, coverage);
}
