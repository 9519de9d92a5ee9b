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

// Irradiance on a surface of normal n from a uniform disk (spherical cap) of radiance 1 and angular
// radius sigma whose centre is at angle theta from n (cosTheta = n.l), partly below the horizon
// too: Snyder 1996, "Area Light Sources for Real-Time Graphics" (the sphere light's form factor), as
// Lagarde and de Rousiers 2014 write it ("Moving Frostbite to PBR", section 4.7.2, listing 7):
//   cos^2 theta > sin^2 sigma:  pi sin^2 sigma cos theta          (the whole disk above the horizon)
//   else:  (cos theta acos(y) - x sin theta sqrt(1 - y^2)) sin^2 sigma + atan(sin theta sqrt(1 - y^2) / x)
//          with x = sqrt(1 / sin^2 sigma - 1), y = -x cot theta.
float diskIrradianceSnyder(float cosTheta, float sinSigma2) {
  if (cosTheta * cosTheta > sinSigma2) return kPi * sinSigma2 * max(cosTheta, 0.0);
  float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
  float x = sqrt(max(1.0 / sinSigma2 - 1.0, 0.0));
  float y = clamp(-x * cosTheta / max(sinTheta, 1e-7), -1.0, 1.0);
  float sinThetaSqrtY = sinTheta * sqrt(1.0 - y * y);
  float e = (cosTheta * acos(y) - x * sinThetaSqrtY) * sinSigma2 + atan(sinThetaSqrtY, x);
  return max(e, 0.0);
}

// The disk's direction closest to the mirror direction r: r itself inside the disk, else the point
// of its rim towards r (the representative point of Karis 2013, "Real Shading in Unreal Engine 4",
// "Sphere lights", for a distant disk as Filament's sun does; cosSin = cos, sin of the radius).
vec3 diskRepresentativeDirection(vec3 l, vec3 r, vec2 cosSin) {
  float LoR = dot(l, r);
  if (LoR >= cosSin.x) return r;
  vec3 s = r - LoR * l;
  float length2 = dot(s, s);
  return length2 > 1e-12 ? normalize(cosSin.x * l + cosSin.y * s * inversesqrt(length2)) : l;
}

// One disk light of radiance `radiance`, direction l, angular radius with cos, sin = cosSin, on the
// material `lobes` at (n, v), without visibility: the core's BRDF times the disk's irradiance E.
//   diffuse  = brdfDiffuse(v, l) E(n.l)
//   specular = F D V (alpha) at the representative direction l', times Karis 2013's energy
//              normalisation (alpha / alpha')^2 with alpha' = min(alpha + tan(sigma) / 2, 1), times E(n.l)
// For a rough lobe (alpha >> sigma) this is f(v, l) E: the disk's exact irradiance times the BRDF at
// its centre. For a smooth one the representative point keeps the highlight the disk's size, and
// the normalisation its energy: a mirror facing the disk head-on reflects F L (D = 1 / (pi alpha'^2),
// V = 1/4, E = pi sin^2(sigma) L, alpha' = tan(sigma) / 2), the exact answer; the constant 2 in
// alpha' is chosen for that.
vec3 diskLightRadiance(BrdfLobes lobes, vec3 n, vec3 v, vec3 l, vec3 radiance, vec2 cosSin) {
  float irradiance = diskIrradianceSnyder(dot(n, l), cosSin.y * cosSin.y);
  if (irradiance <= 0.0 || dot(n, v) <= 0.0) return vec3(0.0);
  vec3 result = brdfDiffuse(lobes, v, l);
  if (maxComponent(lobes.f90) > 0.0) {
    vec3 lr = diskRepresentativeDirection(l, reflect(-v, n), cosSin);
    float alpha = max(lobes.alpha, 1e-4);
    float widened = min(alpha + 0.5 * cosSin.y / max(cosSin.x, 1e-4), 1.0);
    float normalisation = (alpha / widened) * (alpha / widened);
    result += brdfSpecular(lobes, n, v, lr, alpha) * normalisation;
  }
  return result * radiance * irradiance;
}
