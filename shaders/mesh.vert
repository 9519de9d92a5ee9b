#version 450 core
// World-space meshes with their baked per-vertex visibility (docs/baker.md). The locations are
// GpuMesh's (engine/gl/gpu_mesh_attribute.h, through the generated shared_constants.glsl).

#include "shared_constants.glsl"
#include "environment.glsl"
#include "sh9.glsl"
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
// The lights modes' radiance programs evaluate their residual diffuse and the lights' bounce here
// (residualIrradianceAt, lightsBounceAt); every other program leaves those outputs 0.
const bool lightsModeTerms = (SHADING_MODE == kShadingModeLights || SHADING_MODE == kShadingModeLightsShadowed) &&
                             FRAME_LAYER == kFrameLayerRadiance;
// The residual's truncation: what SH9 truncates of the residual's irradiance, its brute-force
// irradiance cube minus its own SH9 irradiance (without the suns not drawn, which
// residualShRadiance adds back), texel by texel (engine/gl/residual_truncation.h), world space like
// the specular chain and turned by specularRotation with it; residualCubeCorrection 0 without it.
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
  if (!lightsModeTerms || residualCubeCorrection == 0) return vec3(0.0);
  float ao = clamp(inAo, 0.0, 1.0);
  vec3 axis = visibilityConeAxis(inBentNormal, n, ao);
  return ao * textureLod(residualTruncationCube, rotateAboutY(axis, specularRotation), 0.0).rgb;
}

// The lights modes' residual diffuse irradiance at the vertex for the face of normal n (n or -n):
// the baked transfer dotted with the residual's SH9 (PRT), plus SH9's truncation, at least 0
// (dominant_lights.glsl). Per vertex, not per pixel: the PRT product is linear in the transfer, so
// interpolating it equals interpolating the transfer (up to the clamp at 0), and llvmpipe pays for
// every interpolated component of every pixel. Three components a face here against the transfer's
// nine and the truncation's three (and lightsBounceAt's three against the baked bounce's four):
// the lights modes' frames cost about 13 ms less at 1280 x 720 on llvmpipe (docs/benchmarks.md
// "The lights modes' per-vertex terms").
uniform vec3 residualShRadiance[9];
vec3 residualIrradianceAt(vec3 n) {
  if (!lightsModeTerms) return vec3(0.0);
  vec3 irradiance = irradiancePrtSloan(inTransfer012, inTransfer345, inTransfer678, residualShRadiance);
  if (residualCubeCorrection != 0) irradiance = max(irradiance + residualTruncationAt(n), vec3(0.0));
  return irradiance;
}

// A light's first bounce off what occludes the vertex (docs/dominant-lights.md, "Bounce light"),
// per vertex for the same reason, and for the sum of the drawn lights at once (it is linear in
// their irradiance). The reference's sunlit ground lights the object from below, and the object
// lights the ground beside it; `full` holds some of it through its SH9 sun and the multi-bounce AO
// fit, the lights' direct term not at all.
// Without SUN_BOUNCE the occluders are taken as diffuse surfaces of the vertex's own albedo (the
// assumption of Jimenez's multi-bounce fit) lit by the light unshadowed as an upward-facing
// surface: radiance albedo E_up / pi, E_up the light's irradiance on an upward normal. Below the
// vertex's horizon they count whole (the ground); above it by half (an object seen from beside or
// below shows about as much shadowed as sunlit surface; 0, 0.5 and 1 were measured, docs/
// dominant-lights.md). The vertex sees them over
//   O_below = pi (1 - n_y) / 2 - sum_k t_k H_k   (>= 0),
// the lower hemisphere's unoccluded irradiance weight (exact: a hemisphere's irradiance lies in
// SH bands 0 and 1) minus the part the baked transfer t sees, H the SH9 of the lower hemisphere's
// indicator (H_0 = 2 pi Y_0 = sqrt(pi), H_1 = -pi 0.488603, the others 0), and
//   O_all = pi - t_0 sqrt(4 pi)   (>= 0),
// the whole hemisphere's occluded weight (what the transfer sees of a constant radiance 1). This
// returns O E_up / pi; the pixel multiplies by its albedo (dominant_lights.glsl).
// With SUN_BOUNCE the bake's own estimate stands for the drawn lights: radiosity over the vertices
// (baker/vertex_visibility.h bakeSunBounce), the occluders its visibility rays hit, each lit as its
// normal, its sun shadow ray and its mesh's albedo say, with three bounces; E_i b_i for light i of
// irradiance E_i, the reflected irradiance itself.
// Each drawn light's irradiance on an upward normal, lightRadiance uniformDiskIrradiance(l.y, r)
// (the core's, computed once a frame), and at normal incidence (lights.json's `irradiance`).
uniform vec3 lightIrradianceUp[kMaxEngineLights];
uniform vec3 lightIrradiance[kMaxEngineLights];
const float kAboveHorizonBounce = 0.5;  // the weight of the occluders above the horizon (above)
vec3 lightsBounceAt(vec3 n) {
  if (!lightsModeTerms) return vec3(0.0);
#if SUN_BOUNCE
  vec3 bounced = vec3(0.0);
  for (int i = 0; i < lightCount; ++i) bounced += lightIrradiance[i] * inSunBounce[i];
  return bounced;
#else
  vec3 irradianceUp = vec3(0.0);
  for (int i = 0; i < lightCount; ++i) irradianceUp += lightIrradianceUp[i];
  float visibleBelow = inTransfer012.x * 1.7724539 - inTransfer012.y * 1.5349874;
  float occludedBelow = max(0.5 * kPi * (1.0 - n.y) - visibleBelow, 0.0);
  float occludedAll = max(kPi - inTransfer012.x * 3.5449077, 0.0);
  float occluded = occludedBelow + kAboveHorizonBounce * max(occludedAll - occludedBelow, 0.0);
  return occluded / kPi * irradianceUp;
#endif
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
  // The lights modes: residualIrradianceAt of the front face (the normal) and of a double-sided
  // material's back face (the normal negated, mesh.frag's `side`), and lightsBounceAt.
  vec3 residualIrradianceFront;
  vec3 residualIrradianceBack;
  vec3 lightsBounce;
  // VERTEX_LIGHTS (lights.glsl): each drawn light's sunDiskIrradiance at the vertex, light i in
  // component i, of the front face and of a double-sided material's back face. Only in those
  // programs: the other programs interpolate nothing more per pixel.
#if VERTEX_LIGHTS
  vec4 lightIrradianceFront;
  vec4 lightIrradianceBack;
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
  vec3 normal = normalize(inNormal);
  vertexOut.residualIrradianceFront = residualIrradianceAt(normal);
  // A single-sided material's back faces are culled: no second lookup.
  vertexOut.residualIrradianceBack = doubleSided ? residualIrradianceAt(-normal) : vertexOut.residualIrradianceFront;
  vertexOut.lightsBounce = lightsBounceAt(normal);
#if VERTEX_LIGHTS
  vertexOut.lightIrradianceFront = lightIrradianceAt(normal);
  vertexOut.lightIrradianceBack = doubleSided ? lightIrradianceAt(-normal) : vertexOut.lightIrradianceFront;
#endif
  gl_Position = viewProjection * vec4(inPosition, 1.0);
}
