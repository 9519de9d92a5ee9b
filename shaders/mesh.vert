#version 450 core
// World-space meshes with their baked per-vertex visibility (docs/baker.md). The locations are
// GpuMesh's (engine/gl/gpu_mesh_attribute.h, through the generated shared_constants.glsl).

#include "shared_constants.glsl"
#include "environment.glsl"
#include "visibility_cone.glsl"
#include "brdf.glsl"
#include "light_directions.glsl"
#include "lights.glsl"

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
// COLOR_0, or the generic (1, 1, 1, 1) GpuMesh::draw sets for a mesh without it.
layout(location = kAttributeColor) in vec4 inColor;
#if SUN_BOUNCE
// The baked suns' bounced light b_i (_SUNBOUNCE), sun i in component i; read only where the renderer
// says it stands for the drawn lights (dominant_lights.glsl's bakedSunBounce).
layout(location = kAttributeSunBounce) in vec4 inSunBounce;
#endif

uniform mat4 viewProjection;
uniform bool doubleSided;  // mesh.frag's: the material's back faces are drawn

#ifndef SHADING_MODE
#define SHADING_MODE kShadingModeFull
#endif
#ifndef FRAME_LAYER
#define FRAME_LAYER kFrameLayerRadiance
#endif
// The lights modes' residual diffuse (dominant_lights.glsl): what SH9 truncates of the residual's
// irradiance, its brute-force irradiance cube minus its own SH9 irradiance (without the suns not
// drawn, which residualShRadiance adds back), texel by texel (engine/gl/residual_truncation.h),
// world space like the specular chain and turned by specularRotation with it; residualCubeCorrection
// 0 without it.
const bool residualTruncationRead = (SHADING_MODE == kShadingModeLights || SHADING_MODE == kShadingModeLightsShadowed) &&
                                    FRAME_LAYER == kFrameLayerRadiance;
uniform int residualCubeCorrection;
uniform vec2 specularRotation;
layout(binding = kTextureUnitResidualIrradiance) uniform samplerCube residualTruncationCube;

// SH9's truncation at a vertex of normal n: AO times the residual cube along the visibility cone's
// axis (the sh-ao-bent approximation, for this high-frequency part only). Per vertex, like the
// baked transfer whose SH9 irradiance it corrects (the truncation is a smooth function of the
// direction and of the vertex's AO and bent normal, which are per vertex themselves): per pixel,
// the axis needs the shading normal, which a Lambert material with no light drawn does not
// otherwise compute (21 ms of a 1280 x 720 frame on llvmpipe, docs/benchmarks.md). A studio map's
// residual keeps the softboxes past the K drawn lights, which SH9 rings around: on a lone diffuse
// sphere this makes the residual's diffuse the cube's (axis n, AO 1), the `irradiance` mode's
// accuracy to the mesh's interpolation (docs/dominant-lights.md).
vec3 residualTruncationAt(vec3 n) {
  if (!residualTruncationRead || residualCubeCorrection == 0) return vec3(0.0);
  float ao = clamp(inAo, 0.0, 1.0);
  vec3 axis = visibilityConeAxis(inBentNormal, n, ao);
  return ao * textureLod(residualTruncationCube, rotateAboutY(axis, specularRotation), 0.0).rgb;
}

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
  vec4 color;
  // residualTruncationAt of the front face (the normal) and of a double-sided material's back face
  // (the normal negated, mesh.frag's `side`).
  vec3 residualTruncationFront;
  vec3 residualTruncationBack;
  // VERTEX_LIGHTS (lights.glsl): each drawn light's sunDiskIrradiance at the vertex, light i in
  // component i, of the front face and of a double-sided material's back face. Only in those
  // programs: the other programs interpolate nothing more per pixel.
#if VERTEX_LIGHTS
  vec4 lightIrradianceFront;
  vec4 lightIrradianceBack;
#endif
#if SUN_BOUNCE
  vec4 sunBounce;
#endif
}
vertexOut;

// The drawn lights' disk irradiance (per unit radiance) on the normal n, light i in component i.
vec4 lightIrradianceAt(vec3 n) {
  vec4 irradiance = vec4(0.0);
  for (int i = 0; i < lightCount; ++i) irradiance[i] = sunDiskIrradiance(dot(n, lightDirection[i]), lightCosSin[i].y);
  return irradiance;
}

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
  vertexOut.color = inColor;
#if SUN_BOUNCE
  vertexOut.sunBounce = inSunBounce;
#endif
  vec3 normal = normalize(inNormal);
  vertexOut.residualTruncationFront = residualTruncationAt(normal);
  // A single-sided material's back faces are culled: no second lookup.
  vertexOut.residualTruncationBack = doubleSided ? residualTruncationAt(-normal) : vertexOut.residualTruncationFront;
#if VERTEX_LIGHTS
  vertexOut.lightIrradianceFront = lightIrradianceAt(normal);
  vertexOut.lightIrradianceBack = doubleSided ? lightIrradianceAt(-normal) : vertexOut.lightIrradianceFront;
#endif
  gl_Position = viewProjection * vec4(inPosition, 1.0);
}
