// VERTEX_LIGHTS 1 (renderer.cpp): a program of the lights modes for a mesh whose vertices share one
// normal and whose triangles face along it (a plane such as the ground; hasConstantNormal), with a
// material without a specular layer and without a normal texture. Its lights' terms are then the
// Lambert diffuse, (1 - metallic) baseColor / pi L sunDiskIrradiance(n.l, r), and n.l is one value
// over the mesh: mesh.vert evaluates the irradiance per vertex (lightIrradianceAt) and the pixel
// needs no shading normal for it. The same frame (bunny_esplanade's ground: relMSE 3e-15 against
// the per-pixel terms), except within 0.57 degrees of the plane's horizon, where the pixel's
// normal would be turned towards the viewer (shadingNormalFacingViewer). Curved meshes keep the
// per-pixel terms: interpolating the irradiance there moved the bunny's terminators (FLIP 0.014,
// docs/benchmarks.md).
#ifndef VERTEX_LIGHTS
#define VERTEX_LIGHTS 0
#endif

// Disk lights with the core's BRDF (core/brdf.h: glTF 2.0 Appendix B with KHR_materials_specular):
// the engine's dominant lights (docs/dominant-lights.md, engine section; docs/engine.md "Lights").
// Needs environment.glsl (kPi) and brdf.glsl (BrdfLobes, diffuseWeight, maxComponent).

// Schlick 1994: F = f0 + (f90 - f0)(1 - cos)^5, the weights (1 - (1 - cos)^5, (1 - cos)^5) of
// splitSumKaris; schlickFresnel of core/brdf.cpp.
vec2 schlickWeights(float cosTheta) {
  float m = clamp(1.0 - cosTheta, 0.0, 1.0);
  float m5 = m * m * m * m * m;
  return vec2(1.0 - m5, m5);
}

// ggxD of core/microfacet.h, with cosH = n.h: alpha^2 / (pi (sin^2 + alpha^2 cos^2)^2).
float ggxD(float cosH, float alpha) {
  if (cosH <= 0.0) return 0.0;
  float alpha2 = alpha * alpha;
  float t = (1.0 - cosH * cosH) + alpha2 * cosH * cosH;
  return alpha2 / (kPi * t * t);
}

// ggxSmithVisibility of core/microfacet.h (height-correlated Smith, Heitz 2014; glTF 2.0 B.3.2).
float ggxSmithVisibility(float cosThetaI, float cosThetaO, float alpha) {
  float alpha2 = alpha * alpha;
  float viewTerm = cosThetaI * sqrt(cosThetaO * cosThetaO * (1.0 - alpha2) + alpha2);
  float lightTerm = cosThetaO * sqrt(cosThetaI * cosThetaI * (1.0 - alpha2) + alpha2);
  return 0.5 / (viewTerm + lightTerm);
}

// The diffuse base of evalBrdf (core/brdf.cpp): diffuseWeight(cos v.h) baseColor / pi.
vec3 brdfDiffuse(BrdfLobes lobes, vec3 v, vec3 l) {
  float VoH = clamp(dot(v, normalize(v + l)), 0.0, 1.0);
  return diffuseWeight(lobes, schlickWeights(VoH)) * lobes.baseColor / kPi;
}

// The specular layer of evalBrdf: F(v.h) D(h) V(l, v) at `alpha` (the lobe's, or widened).
vec3 brdfSpecular(BrdfLobes lobes, vec3 n, vec3 v, vec3 l, float alpha) {
  float NoL = dot(n, l), NoV = dot(n, v);
  if (NoL <= 0.0 || NoV <= 0.0) return vec3(0.0);
  vec3 h = normalize(v + l);
  float VoH = clamp(dot(v, h), 0.0, 1.0);
  vec3 fresnel = splitSumKaris(lobes.f0, lobes.f90, schlickWeights(VoH));
  return fresnel * (ggxD(dot(n, h), alpha) * ggxSmithVisibility(NoL, NoV, alpha));
}

// evalBrdf of core/brdf.h (the non-delta part: a mirror's lobe is a delta the C++ leaves out too).
vec3 evalBrdf(BrdfLobes lobes, vec3 n, vec3 v, vec3 l) {
  if (dot(n, l) <= 0.0 || dot(n, v) <= 0.0) return vec3(0.0);
  vec3 f = brdfDiffuse(lobes, v, l);
  if (lobes.alpha >= kDeltaAlpha) f += brdfSpecular(lobes, n, v, l, lobes.alpha);
  return f;
}

// uniformDiskIrradiance of core/disk_irradiance.h: irradiance on a surface of normal n from a
// uniform disk (spherical cap) of radiance 1 and angular radius r whose centre is at angle theta
// from n (cosTheta = n.l), across the horizon too (Snyder 1996, "Area Light Sources for Real-Time
// Graphics", as Lagarde and de Rousiers 2014 write it, "Moving Frostbite to PBR", section 4.7):
//   cos^2 theta > sin^2 r:  pi sin^2 r max(cos theta, 0)
//   else:  (cos theta acos(y) - x sin theta sqrt(1 - y^2)) sin^2 r + atan(sin theta sqrt(1 - y^2) / x)
//          with x = cot r, y = -x cot theta.
// The same with the radius given by its cosine and sine (cosSin, r in [0, pi / 2]): a light's
// (lightCosSin), so that a pixel does not evaluate them.
float uniformDiskIrradiance(float cosTheta, vec2 cosSin) {
  float c = clamp(cosTheta, -1.0, 1.0);
  float sinRadius = cosSin.y;
  float sinSquared = sinRadius * sinRadius;
  if (sinSquared <= 0.0) return 0.0;
  if (c * c > sinSquared) return kPi * sinSquared * max(c, 0.0);
  float x = max(cosSin.x / sinRadius, 1e-7);
  float sinTheta = max(sqrt(max(0.0, 1.0 - c * c)), 1e-7);
  float y = clamp(-x * c / sinTheta, -1.0, 1.0);
  float sinThetaSqrtY = sinTheta * sqrt(max(0.0, 1.0 - y * y));
  float e = (c * acos(y) - x * sinThetaSqrtY) * sinSquared + atan(sinThetaSqrtY / x);
  return max(e, 0.0);
}

// The same for a sun (angular radius r <= kMaxSunAngularRadius, 10 degrees; core/environment_lights.h)
// without acos and atan: llvmpipe evaluates both sides of the horizon branch on every pixel, and
// those two were about 6 ms of a 1280 x 720 frame with 4 lights. In the horizon band |cos theta| <
// sin r it takes the small-disk limit: with h = cos theta / sin r, the disk seen as flat,
//   E = pi sin^3 r G(h),  G(h) = (h pi / 2 + h^2 sqrt(1 - h^2) + h asin h + 2/3 (1 - h^2)^(3/2)) / pi
// (the cosine-weighted area of the unit disk above a chord at -h; G(-1) = 0, G(1) = 1, G' the
// visible fraction), whose even part G(h) - h / 2 is fitted by a cubic in h^2 (least squares,
// largest error 7.4e-5 of pi sin^3 r). Against the exact formula: at most 8e-6 of the head-on
// irradiance pi sin^2 r at r = 3 degrees and 3.4e-4 at 10 (the limit's own error, the disk's
// curvature), measured by tests/gl/lights_test.cpp's SunDiskIrradianceMatchesTheCore.
float sunDiskIrradiance(float cosTheta, float sinRadius) {
  float c = clamp(cosTheta, -1.0, 1.0);
  float s = max(sinRadius, 1e-7);
  float h = clamp(c / s, -1.0, 1.0);
  float u = h * h;
  float g = 0.5 * h + (0.21224802 + u * (0.31755486 + u * (-0.02358804 + u * -0.00614100)));
  float e = c * c > s * s ? max(c, 0.0) : s * max(g, 0.0);
  return sinRadius > 0.0 ? kPi * sinRadius * sinRadius * e : 0.0;
}

float uniformDiskIrradiance(float cosTheta, float angularRadius) {
  float r = clamp(angularRadius, 0.0, 0.5 * kPi);
  return uniformDiskIrradiance(cosTheta, vec2(cos(r), sin(r)));
}

// One disk light of radiance `radiance`, direction l, angular radius r (cos, sin = cosSin), on the
// material `lobes` at (n, v), without visibility: the core's BRDF times the disk's irradiance
// E = radiance uniformDiskIrradiance(n.l, r) (sunIrradiance of core/environment_lights.h),
//   diffuse  = brdfDiffuse(v, l) E
//   specular = F D V (v, l; alpha') E,   alpha' = min(sqrt(alpha^2 + (tan(r) / 2)^2), 1)
// The specular lobe is widened by the disk (roughness widening, as in Karis 2013, "Real Shading in
// Unreal Engine 4", "Area lights", where alpha' grows with the source's angular size): a lobe
// convolved with the disk, whose widths add in quadrature. D stays normalised, so no energy is
// gained; for alpha >> r this is f(v, l) E, the disk's exact irradiance times the BRDF at its centre,
// and a mirror facing the disk head-on reflects F L cos^2(r) (D = 1 / (pi alpha'^2), V = 1/4,
// E = pi sin^2(r) L, alpha' = tan(r) / 2), the exact answer F L to 0.3% at r = 3 degrees: the
// factor 1/2 in alpha' is chosen for that. tests/gl/lights_test.cpp measures it against quadrature.
//
// Below the disk's own width (alpha < tan(r) / 2) the widened lobe's GGX tails, heavy (D falls
// only as alpha'^2 / tan^4 of the half-vector angle), spread a bright sun over the whole lit half
// of a near-mirror, up to its n.l = 0 terminator (mirror sphere under studio: FLIP 0.43 against
// full's 0.027). There the disk is reflected as a disk: F(n.v) L times the part of the reflected
// direction's neighbourhood inside it (an edge a fifth of the radius wide), blended towards the
// widened lobe as alpha grows to tan(r) / 2. Above that, as before.
// edgeCos: cos(1.1 r) and cos(0.9 r), the edge (a light's lightMirrorEdgeCos, per light).
//
// The lights modes may pass the light's own texels as `radiance` instead of the uniform disk
// (dominant_lights.glsl, where the map's chain and the residual's both exist): the map's level 0
// minus the residual's in the reflected direction, which is what the extracted lights carry there,
// texel by texel (residual + lights = the map), so a near-mirror reflects the lamp's real shape,
// not a disk of its spread (mirror sphere under studio). The edge is then a window around light
// i, edgeCos = (cos(2 r + 1 deg), cos(1.5 r + 1 deg)) (lightTexelWindowCos), which holds its
// region's texels (the region, ringing included, spreads beyond the disk of the same spread) and
// not another light's.
vec3 mirroredDiskRadiance(BrdfLobes lobes, vec3 n, vec3 v, vec3 l, vec3 radiance, vec2 edgeCos) {
  float NoV = dot(n, v);
  vec3 r = reflect(-v, n);
  float inside = smoothstep(edgeCos.x, edgeCos.y, dot(r, l));
  return splitSumKaris(lobes.f0, lobes.f90, schlickWeights(NoV)) * radiance * inside;
}

// diskLightRadiance (below) with the near-mirror's reflection `mirrored` given (mirroredDiskRadiance
// of the disk's radiance or of the light's texels).
vec3 diskLightRadianceMirroring(BrdfLobes lobes, vec3 n, vec3 v, vec3 l, vec3 radiance, vec2 cosSin, vec3 mirrored) {
  if (dot(n, v) <= 0.0) return vec3(0.0);
  float irradiance = sunDiskIrradiance(dot(n, l), cosSin.y);
  vec3 result = irradiance > 0.0 ? brdfDiffuse(lobes, v, l) * radiance * irradiance : vec3(0.0);
#if SPECULAR_LAYER
  if (maxComponent(lobes.f90) > 0.0) {
    float spread = 0.5 * cosSin.y / max(cosSin.x, 1e-4);
    float widened = min(sqrt(lobes.alpha * lobes.alpha + spread * spread), 1.0);
    vec3 lobe = irradiance > 0.0 ? brdfSpecular(lobes, n, v, l, widened) * radiance * irradiance : vec3(0.0);
    float towardsLobe = clamp(lobes.alpha / max(spread, 1e-6), 0.0, 1.0);
    result += towardsLobe >= 1.0 ? lobe : mix(mirrored, lobe, towardsLobe);
  }
#endif
  return result;
}

// cosSin: cos r and sin r; edgeCos: cos(1.1 r) and cos(0.9 r) (uniforms of the light, so that a
// pixel evaluates no trigonometry of r).
vec3 diskLightRadiance(BrdfLobes lobes, vec3 n, vec3 v, vec3 l, vec3 radiance, vec2 cosSin, vec2 edgeCos) {
  return diskLightRadianceMirroring(lobes, n, v, l, radiance, cosSin,
                                    mirroredDiskRadiance(lobes, n, v, l, radiance, edgeCos));
}
