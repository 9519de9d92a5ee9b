// The `lights` and `lights-shadowed` modes (docs/engine.md "Lights"; docs/dominant-lights.md,
// engine section): the environment as K disk lights plus the residual map. Included by mesh.frag
// after fullMaterialModelWith and visibilityConeAxis, which it uses; lights.glsl and shadow.glsl
// have the terms.

// The first lightCount suns (renderer.cpp: the world direction towards each, its uniform radiance,
// its angular radius' cos and sin), and the residual: its SH9 radiance (with the suns not drawn
// added back) and its specular chain (the same levels and rotation as the map's). lightCount,
// lightDirection and lightCosSin are light_directions.glsl's (through shadow.glsl).
uniform vec3 lightRadiance[kMaxEngineLights];
// cos(1.1 r), cos(0.9 r): the edge of a mirror's reflected disk (mirroredDiskRadiance).
uniform vec2 lightMirrorEdgeCos[kMaxEngineLights];
// cos(2 r + 1 deg), cos(1.5 r + 1 deg): the window of a mirror's reflected texels of the light
// (mirroredDiskRadiance of the texels), read where lightMirrorTexels is 1 (else 0: the uniform
// disk): where the residual has its own chain, so that the map's chain minus the residual's is
// the lights' texels, and the light is wider than a texel of the chain's level 0.
uniform vec2 lightTexelWindowCos[kMaxEngineLights];
uniform float lightMirrorTexels[kMaxEngineLights];
// The light's irradiance on an upward normal, lightRadiance uniformDiskIrradiance(l.y, r) (the
// core's, computed once a frame): what groundBounceIrradiance's ground receives.
uniform vec3 lightIrradianceUp[kMaxEngineLights];
// The light's irradiance at normal incidence (lights.json's `irradiance`, radiance x solid angle).
uniform vec3 lightIrradiance[kMaxEngineLights];
// SUN_BOUNCE (mesh.vert): 1 where every mesh carries the suns' bounce baked for the drawn lights
// (_SUNBOUNCE: the bake's suns, in the bake's orientation; renderer.cpp, bakedSunBounceFor).
// groundBounceIrradiance then reads it.
uniform vec3 residualShRadiance[9];
// 1 where mesh.vert reads SH9's truncation of the residual (residualTruncationAt), 0 without the
// residual's cube.
uniform int residualCubeCorrection;
layout(binding = kTextureUnitResidualSpecular) uniform samplerCube residualSpecularCube;

// residual  = fullMaterialModelWith(residual chain, AO, cone axis, E_PRT,residual)
// + sum_i diskLightRadiance(light i) V_i   (V_i = 1, or the shadow map's visibility with `shadowed`)
// The residual's diffuse is `full`'s: the baked transfer dotted with the residual's SH9 (PRT, the
// visibility in the transfer), plus SH9's truncation of the residual from its cube
// (mesh.vert residualTruncationAt). (The residual's SH9 along the bent normal times AO, the sh-ao-bent formula, measured
// worse than `full` on the soft maps: bunny under forest, mean FLIP 0.043 against 0.034.)
// A light's first bounce off what occludes the vertex (docs/dominant-lights.md, "Bounce light").
// The reference's sunlit ground lights the object from below, and the object lights the ground
// beside it; `full` holds some of it through its SH9 sun and the multi-bounce AO fit, the lights'
// direct term not at all. The occluders are taken as diffuse surfaces of the vertex's own albedo
// (the assumption of Jimenez's multi-bounce fit) lit by the light unshadowed as an upward-facing
// surface: radiance albedo E_up / pi, E_up the light's irradiance on an upward normal. Below the
// vertex's horizon they count whole (the ground); above it by half (an object seen from beside or
// below shows about as much shadowed as sunlit surface; 0, 0.5 and 1 were measured, docs/
// dominant-lights.md). The vertex sees them over
//   O_below = pi (1 - n_y) / 2 - sum_k t_k H_k   (>= 0),
// the lower hemisphere's unoccluded irradiance weight (exact: a hemisphere's irradiance lies in
// SH bands 0 and 1) minus the part the baked transfer t sees, H the SH9 of the lower hemisphere's
// indicator (H_0 = 2 pi Y_0 = sqrt(pi), H_1 = -pi 0.488603, the others 0), and
//   O_all = pi - t_0 sqrt(4 pi)   (>= 0),
// the whole hemisphere's occluded weight (what the transfer sees of a constant radiance 1).
// That estimate stands in where the bake's own is not for the drawn lights. The bake's (SUN_BOUNCE)
// is radiosity over the vertices (baker/vertex_visibility.h bakeSunBounce): the occluders its
// visibility rays hit, each lit as its normal, its sun shadow ray and its mesh's albedo say, with
// three bounces; E_i b_i for light i of irradiance E_i.
const float kAboveHorizonBounce = 0.5;  // the weight of the occluders above the horizon (above)
vec3 groundBounceIrradiance(vec3 albedo, vec3 irradianceUp) {
#if SUN_BOUNCE
  vec3 bounced = vec3(0.0);
  for (int i = 0; i < lightCount; ++i) bounced += lightIrradiance[i] * vertexIn.sunBounce[i];
  return bounced;
#else
  float visibleBelow = vertexIn.transfer012.x * 1.7724539 - vertexIn.transfer012.y * 1.5349874;
  float ny = normalize(vertexIn.normal).y;
  float occludedBelow = max(0.5 * kPi * (1.0 - ny) - visibleBelow, 0.0);
  float occludedAll = max(kPi - vertexIn.transfer012.x * 3.5449077, 0.0);
  float occluded = occludedBelow + kAboveHorizonBounce * max(occludedAll - occludedBelow, 0.0);
  return occluded * albedo / kPi * irradianceUp;
#endif
}

// `truncation`: SH9's truncation of the residual's irradiance at this point, AO times the residual
// cube along the visibility cone's axis, which mesh.vert evaluates per vertex (residualTruncationAt).
vec3 dominantLightsModel(SurfaceMaterial m, vec3 n, vec3 v, float ao, vec3 truncation, vec4 vertexLightIrradiance,
                         vec3 position, vec3 geometric, bool shadowed) {
  vec3 irradiance = irradiancePrtSloan(vertexIn.transfer012, vertexIn.transfer345, vertexIn.transfer678, residualShRadiance);
  vec3 axis = visibilityConeAxis(n, ao);
  if (residualCubeCorrection != 0) irradiance = max(irradiance + truncation, vec3(0.0));
  vec3 radiance = fullMaterialModelWith(residualSpecularCube, m, n, v, ao, axis, irradiance);
  BrdfLobes lobes = brdfLobes(m.baseColor, m.metallic, m.roughness, SPECULAR_WEIGHT, specularColor);
  vec3 irradianceUp = vec3(0.0);
#if SPECULAR_LAYER && !VERTEX_LIGHTS
  // The lights' texels in the mirror direction (lights.glsl, mirroredDiskRadiance), the same for
  // every light.
  vec3 mirrorDirection = rotateAboutY(reflect(-v, n), specularRotation);
  vec3 texels = max(textureLod(specularCube, mirrorDirection, 0.0).rgb - textureLod(residualSpecularCube, mirrorDirection, 0.0).rgb,
                    vec3(0.0));
#endif
  // The lights' shadows: this pixel's texel of the frame's shadow mask (SHADOW_MASK 1, shadow.glsl),
  // the coarser mask upsampled (SHADOW_MASK 2), or the maps read here where the light's term is
  // not 0.
#if SHADOW_MASK == 1
  vec4 visibility = shadowed ? texelFetch(shadowMask, ivec2(gl_FragCoord.xy), 0) : vec4(1.0);
#elif SHADOW_MASK == 2
  vec2 depthGradient = vec2(dFdx(gl_FragCoord.z), dFdy(gl_FragCoord.z));
  vec4 visibility = shadowed ? upsampledShadowMask(depthGradient) : vec4(1.0);
#endif
  for (int i = 0; i < lightCount; ++i) {
    vec3 l = lightDirection[i];
#if VERTEX_LIGHTS
    vec3 lit = (1.0 - lobes.metallic) * lobes.baseColor / kPi * lightRadiance[i] * vertexLightIrradiance[i];
#else
#if SPECULAR_LAYER
    // lightMirrorTexels is 0 or 1: the disk's radiance and edge, or the texels and their window.
    vec3 mirrored = mirroredDiskRadiance(lobes, n, v, l, mix(lightRadiance[i], texels, lightMirrorTexels[i]),
                                         mix(lightMirrorEdgeCos[i], lightTexelWindowCos[i], lightMirrorTexels[i]));
#else
    vec3 mirrored = vec3(0.0);
#endif
    vec3 lit = diskLightRadianceMirroring(lobes, n, v, l, lightRadiance[i], lightCosSin[i], mirrored);
#endif
#if SHADOW_MASK
    lit *= visibility[i];
#else
    if (shadowed && maxComponent(lit) > 0.0) lit *= lightVisibility(i, position, geometric);
#endif
    radiance += lit;
    irradianceUp += lightIrradianceUp[i];
  }
  // The lights' bounce off what occludes the vertex (groundBounceIrradiance,
  // linear in the irradiance: the lights' sum at once).
#if VERTEX_LIGHTS
  float bounceWeight = 1.0 - lobes.metallic;
#else
  float bounceWeight = diffuseWeight(lobes, schlickWeights(clamp(dot(n, v), 0.0, 1.0)));
#endif
  radiance += bounceWeight * m.baseColor / kPi * groundBounceIrradiance(m.baseColor, irradianceUp);
  return radiance;
}
