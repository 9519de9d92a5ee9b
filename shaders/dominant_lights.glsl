// The `lights` and `lights-shadowed` modes (docs/engine.md "Lights"; docs/dominant-lights.md,
// engine section): the environment as K disk lights plus the residual map. Included by mesh.frag
// after fullMaterialModelWith and visibilityConeAxis, which it uses; lights.glsl and shadow.glsl
// have the terms.

// The first lightCount suns (renderer.cpp: the world direction towards each, its uniform radiance,
// its angular radius and that angle's cos and sin), and the residual: its SH9 radiance (with the suns not drawn
// added back) and its specular chain (the same levels and rotation as the map's).
uniform int lightCount;
uniform vec3 lightDirection[kMaxEngineLights];
uniform vec3 lightRadiance[kMaxEngineLights];
uniform float lightAngularRadius[kMaxEngineLights];
uniform vec2 lightCosSin[kMaxEngineLights];
uniform vec3 residualShRadiance[9];
layout(binding = kTextureUnitResidualSpecular) uniform samplerCube residualSpecularCube;

// residual  = fullMaterialModelWith(residual chain, AO, cone axis, E_PRT,residual)
// + sum_i diskLightRadiance(light i) V_i   (V_i = 1, or the PCSS visibility with `shadowed`)
// The residual's diffuse is `full`'s: the baked transfer dotted with the residual's SH9 (PRT, the
// visibility in the transfer), so that where the bake extracted no sun both modes are `full`
// exactly. (The residual's SH9 along the bent normal times AO, the sh-ao-bent formula, measured
// worse than `full` on the soft maps: bunny under forest, mean FLIP 0.043 against 0.034.)
vec3 dominantLightsModel(SurfaceMaterial m, vec3 n, vec3 v, float ao, vec3 position, vec3 geometric, bool shadowed) {
  vec3 irradiance = irradiancePrtSloan(vertexIn.transfer012, vertexIn.transfer345, vertexIn.transfer678, residualShRadiance);
  vec3 radiance = fullMaterialModelWith(residualSpecularCube, m, n, v, ao, visibilityConeAxis(n, ao), irradiance);
  BrdfLobes lobes = brdfLobes(m.baseColor, m.metallic, m.roughness, specularWeight, specularColor);
  mat2 rotation = shadowed ? shadowTapRotation() : mat2(1.0);
  for (int i = 0; i < lightCount; ++i) {
    vec3 l = lightDirection[i];
    vec3 lit = diskLightRadiance(lobes, n, v, l, lightRadiance[i], lightAngularRadius[i], lightCosSin[i]);
    if (shadowed && maxComponent(lit) > 0.0) {
      vec3 g = dot(geometric, l) < 0.0 ? -geometric : geometric;
      lit *= shadowVisibility(i, position, g, l, lightCosSin[i].y / max(lightCosSin[i].x, 1e-4), rotation);
    }
    radiance += lit;
  }
  return radiance;
}
