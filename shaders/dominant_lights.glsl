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
// lightIrradianceUp (each light's irradiance on an upward normal, lightRadiance
// uniformDiskIrradiance(l.y, r), the core's, computed once a frame), lightIrradiance (its
// irradiance at normal incidence, lights.json's `irradiance`), residualShRadiance (the residual's
// SH9, with the suns not drawn added back) and residualCubeCorrection (1 where SH9's truncation of
// the residual is added, 0 without the residual's cube) are mesh.vert's: the residual's diffuse
// irradiance and the lights' bounce are evaluated per vertex there (residualIrradianceAt,
// lightsBounceAt; SUN_BOUNCE: every mesh carries the suns' bounce baked for the drawn lights).
layout(binding = kTextureUnitResidualSpecular) uniform samplerCube residualSpecularCube;

// residual  = fullMaterialModelWith(residual chain, AO, cone axis, E_PRT,residual)
// + sum_i diskLightRadiance(light i) V_i   (V_i = 1, or the shadow map's visibility with `shadowed`)
// + the lights' bounce off what occludes the vertex.
// The residual's diffuse is `full`'s: the baked transfer dotted with the residual's SH9 (PRT, the
// visibility in the transfer), plus SH9's truncation of the residual from its cube, both per vertex
// (mesh.vert residualIrradianceAt). (The residual's SH9 along the bent normal times AO, the sh-ao-bent
// formula, measured worse than `full` on the soft maps: bunny under forest, mean FLIP 0.043 against
// 0.034.)
// `residualIrradiance`: that irradiance, of this pixel's face (front or back).
vec3 dominantLightsModel(SurfaceMaterial m, vec3 n, vec3 v, float ao, vec3 residualIrradiance,
                         vec4 vertexLightIrradiance, vec3 position, vec3 geometric, bool shadowed) {
  vec3 axis = visibilityConeAxis(n, ao);
  vec3 radiance = fullMaterialModelWith(residualSpecularCube, m, n, v, ao, axis, residualIrradiance);
  BrdfLobes lobes = brdfLobes(m.baseColor, m.metallic, m.roughness, SPECULAR_WEIGHT, specularColor);
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
  uvec2 packedVisibility = texelFetch(shadowMask, ivec2(gl_FragCoord.xy), 0).rg;
  vec4 visibility = shadowed ? vec4(unpackUnorm2x16(packedVisibility.x), unpackUnorm2x16(packedVisibility.y)) : vec4(1.0);
#elif SHADOW_MASK == 2
  vec2 depthGradient = vec2(dFdx(gl_FragCoord.z), dFdy(gl_FragCoord.z));
  vec4 visibility = shadowed ? upsampledShadowMask(depthGradient) : vec4(1.0);
#elif SHADOW_MASK == 3
  vec4 visibility = shadowed ? groundShadowVisibilities(position) : vec4(1.0);
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
  }
  // The lights' bounce off what occludes the vertex (mesh.vert lightsBounceAt: the reflected
  // irradiance, or without SUN_BOUNCE that per unit of the occluders' albedo, taken as this pixel's).
#if VERTEX_LIGHTS
  float bounceWeight = 1.0 - lobes.metallic;
#else
  float bounceWeight = diffuseWeight(lobes, schlickWeights(clamp(dot(n, v), 0.0, 1.0)));
#endif
#if SUN_BOUNCE
  vec3 bounceIrradiance = vertexIn.lightsBounce;
#else
  vec3 bounceIrradiance = m.baseColor * vertexIn.lightsBounce;
#endif
  radiance += bounceWeight * m.baseColor / kPi * bounceIrradiance;
  return radiance;
}
