#include "reference/integrator.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <stdexcept>
#include <vector>

#include "core/brdf.h"
#include "core/error.h"
#include "core/frame.h"
#include "core/sampling.h"
#include "raytrace/ray_offset.h"
#include "reference/ambient_occlusion.h"

namespace iblkit {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// The ground's vertices that ground occlusion takes: a geometric normal within 4.5e-4 radians of +Y
// (a plane's normals are +Y to the rounding), where the upper hemisphere of E_up is the surface's
// own; and for the Lambert case's shortcuts (exact) the shading normal too (a normal texture's is
// not).
constexpr float kUpCosine = 1.0f - 1e-7f;

// The shading normals of a horizontal ground (a normal texture's) that ground occlusion takes
// beyond those: within 20 degrees of +Y. There the control's a w_y L no longer matches f (n.w) L
// exactly, so it is the control variate's general case. Measured on `tiles` with a normal texture on
// its ground, relMSE off / on, within 20 degrees: sky 1.48x, esplanade 2.07x, studio 1.09x; every
// tilt: studio 0.98x (docs/benchmarks.md "Ground occlusion on specular grounds").
constexpr float kTiltedUpCosine = 0.94f;

// The least GGX alpha of a ground with a specular layer that ground occlusion takes (perceptual
// roughness 0.5). On a glossier one the control variate does worse than the plain estimate: the
// BRDF strategy picks the specular lobe with probability at least 0.1 whatever its share, and in
// the plain estimate f cos / pdf of the lobes' mixture stays near constant, but with the diffuse
// base's a taken out what is left, (f - a) cos / pdf, is about 0 on the diffuse lobe's draws and
// large on the specular lobe's. Measured on a lone ground, plain / control noise at roughness 0.2,
// 0.5, 0.7 and 0.9: 0.43, 0.84, 4.0 and 24 under a constant map, 0.85, 3.9, 28 and 57 under the
// spot sky (docs/reference-tracer.md "Ground occlusion").
constexpr float kGroundControlMinAlpha = 0.25f;

// Ground points whose visible fraction of E_up (ground_visibility.h) is below this take it as the
// control's coefficient; the others keep 1. The coefficient's gain is where the objects hide much
// of the light (the penumbrae and shadows), and elsewhere it costs the exact case's shortcuts:
// bunny under venice, coefficient wherever the fraction is below 1, CPU time 1.2x (11 alternated
// pairs, 1.06-1.33) for the same relMSE; below 0.5, 0.99x (0.96-1.02), and the same gain under studio
// (docs/benchmarks.md "Ground occlusion on specular grounds").
constexpr float kGroundCoefficientBelow = 0.5f;

// Veach's power heuristic (Veach 1997, eq. 9.13) with exponent beta = 1.5: the weight of the
// strategy whose density (times its sample count) is pdfA against one of density pdfB,
// pdfA^1.5 / (pdfA^1.5 + pdfB^1.5). The two weights of a direction add up to 1 for any beta, so
// every beta is unbiased. Veach recommends 2; with this tracer's stratified samples 1.5 gave a
// lower relMSE over 40 scene x map cases (2's over 1.5's: 0.997x to 1.19x, geometric mean 1.07x),
// where the balance heuristic (beta = 1) gained up to 1.4x on Lambert scenes and lost up to 1.2x
// under small bright sources (docs/benchmarks.md, "The MIS exponent").
float powerHeuristic(float pdfA, float pdfB) {
  const float a = pdfA * std::sqrt(pdfA), b = pdfB * std::sqrt(pdfB);
  return a / (a + b);
}

float maxComponent(const glm::vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }

// The side of the surface a ray in direction `direction` leaves into.
glm::vec3 sideFacing(const glm::vec3& geometricNormal, const glm::vec3& direction) {
  return glm::dot(direction, geometricNormal) > 0.0f ? geometricNormal : -geometricNormal;
}

void recordFirstHit(const SurfacePoint& point, float distance, CameraSample& result) {
  result.albedo = point.baseColor;
  result.normal = point.shadingNormal;
  result.distance = distance;
  result.objectCoverage = point.isGround ? 0.0f : 1.0f;
}

}  // namespace

IntegratorKind parseIntegratorKind(const std::string& name) {
  return parseEnumName(kIntegratorNames, name, "--integrator", "integrator");
}

EnvSampling parseEnvSampling(const std::string& name) {
  return parseEnumName(kEnvSamplingNames, name, "--env-sampling", "strategy");
}

Integrator::Integrator(const RenderScene& scene, const EnvironmentMap& environment,
                       const EnvironmentSampler& environmentSampler, const IntegratorSettings& settings,
                       const MedianCutLighting& medianCut)
    : scene_(scene),
      environment_(environment),
      environmentSampler_(environmentSampler),
      settings_(settings),
      medianCut_(medianCut) {
  // Ground occlusion replaces the light and BRDF strategies of mis at the ground's vertices, so
  // it needs both (and the glTF BRDF, whose Lambert case it recognises).
  if (settings.groundOcclusion && settings.kind != IntegratorKind::AmbientOcclusion &&
      settings.envSampling == EnvSampling::Mis && !settings.phong)
    ground_ = GroundOcclusion::of(scene.scene(), environment);
  if (ground_) groundVisibility_ = GroundVisibility(*ground_, scene.rays(), environmentSampler);
  if (settings.envSampling == EnvSampling::MedianCut && !medianCut.sampler)
    throw std::invalid_argument("Integrator: mediancut needs a MedianCutSampler");
  if (settings.envSampling == EnvSampling::Lights && !medianCut.pointLights)
    throw std::invalid_argument("Integrator: lights needs EnvironmentPointLights");
  if (settings.cameraLightSamples < 1 || settings.cameraLightSamples > kMaxSplitLightDraws)
    throw std::invalid_argument("Integrator: camera light samples outside 1.." +
                                std::to_string(kMaxSplitLightDraws));
}

glm::vec3 Integrator::evalReflection(const BrdfAtPoint* brdf, const glm::vec3& baseColor, const glm::vec3& n,
                                     const glm::vec3& wo, const glm::vec3& wi) const {
  if (brdf) return brdf->eval(wi);
  return baseColor * evalPhongLobe(*settings_.phong, n, wo, wi);
}

float Integrator::pdfReflection(const BrdfAtPoint* brdf, const glm::vec3& n, const glm::vec3& wo,
                                const glm::vec3& wi) const {
  return brdf ? brdf->pdf(wi) : pdfPhongLobe(*settings_.phong, n, wo, wi);
}

BrdfSample Integrator::sampleReflection(const BrdfAtPoint* brdf, const glm::vec3& baseColor,
                                        const glm::vec3& n, const glm::vec3& wo, glm::vec2 u,
                                        float uLobe) const {
  if (brdf) return brdf->sample(u, uLobe);
  BrdfSample sample = samplePhongLobe(*settings_.phong, n, wo, u);
  sample.weight *= baseColor;
  return sample;
}

Hit Integrator::intersect(const Ray& ray, const RayQuery& query) const {
  if (recorder_) [[unlikely]]
    recorder_->record({ray.origin, 0.0f, ray.direction, kInfinity, false, query});
  return scene_.rays().intersect(ray, 0.0f, kInfinity, query);
}

void Integrator::occluded(std::span<const OcclusionQuery> rays, std::vector<std::uint8_t>& blocked) const {
  if (recorder_) [[unlikely]]
    for (const OcclusionQuery& r : rays) recorder_->record({r.origin, r.tmin, r.direction, r.tmax, true, r.query});
  blocked.resize(rays.size());
  scene_.rays().occluded(rays, blocked);
}

CameraSample Integrator::trace(const Ray& cameraRay, PixelSampler& sampler, const RayCone& cone) const {
  CameraSample result;
  traceBatch(std::span<const Ray>(&cameraRay, 1), std::span<PixelSampler>(&sampler, 1), cone,
             std::span<CameraSample>(&result, 1));
  return result;
}

// One path of a batch: what the loop of a single path keeps between its vertices, and the current
// vertex's hit, surface and random numbers, which the batch's passes hand on to each other.
struct Integrator::Path {
  Ray ray;
  RayCone cone;
  glm::vec3 throughput{1.0f};
  float previousPdf = 0.0f;   // BRDF pdf of the ray being traced
  bool previousDelta = true;  // the camera ray, like a mirror ray, sees the environment directly
  // Light samples taken at the vertex the ray leaves (K at the first hit), for its MIS weight, and
  // the environment sampler's bucket of that vertex's normal (an oriented sampler's density there).
  float previousLightSamples = 1.0f;
  int previousBucket = EnvironmentSampler::kNoBucket;
  // Ground occlusion (ground_occlusion.h) takes the current vertex's direct light (covered), or
  // took the direct light of the vertex the ray leaves (previousCovered: the ray counts where it is
  // blocked); the cone of directions the objects can block from the current vertex.
  bool covered = false, previousCovered = false;
  GroundOcclusion::Cone occluders;
  // At a covered vertex: `control`, the constant BRDF a of the split f (E_up - O) + (f - a)
  // (groundControl), times the point's coefficient beta where it is below 1 (ground_visibility.h),
  // and whether it is f itself (exact: a Lambert ground with beta 1, where the light outside the
  // occluders' cone adds nothing). For the ray being traced from such a vertex: whether it was
  // exact, and the throughput the control's term carries, a w_y / pdf (previousControl; f cos / pdf
  // is `throughput`).
  bool exact = false, previousExact = false;
  glm::vec3 control{0.0f}, previousControl{0.0f};
  int bucket = EnvironmentSampler::kNoBucket;  // the current vertex's
  bool alive = true;
  Hit hit;
  glm::vec2 escapeUv{0.0f};  // where an escaping ray looks the environment sampler up (mis)
  SurfacePoint point;
  glm::vec2 uLight{0.0f}, uBrdf{0.0f};
  float uLobe = 0.0f, uRoulette = 0.0f;
  // The glTF BRDF at this vertex, prepared once for its eval, pdf and sample calls (none with --phong).
  std::optional<BrdfAtPoint> brdf;

  // The state a new camera ray starts with. Only what the loop reads before it writes is set: the
  // rest (hit, point, draws, brdf) is written at each vertex before it is read, so a path reused
  // from an earlier batch needs no clearing (clearing the whole batch was 1-2% of a render).
  const BrdfAtPoint* reflection() const { return brdf ? &*brdf : nullptr; }

  void start(const Ray& cameraRay, const RayCone& cameraCone) {
    ray = cameraRay;
    cone = cameraCone;
    throughput = glm::vec3(1.0f);
    previousPdf = 0.0f;
    previousDelta = true;
    previousLightSamples = 1.0f;
    previousBucket = bucket = EnvironmentSampler::kNoBucket;
    previousCovered = false;
    alive = true;
  }
};

void Integrator::intersectCameraRays(std::span<Path> paths) const {
  thread_local std::vector<Ray> rays;
  thread_local std::vector<Hit> hits;
  rays.resize(paths.size());
  hits.resize(paths.size());
  for (std::size_t i = 0; i < paths.size(); ++i) rays[i] = paths[i].ray;
  // The renderer gives a batch's camera rays one cone.
  const RayQuery query{RayKind::Camera, paths.empty() ? RayCone{} : paths.front().cone};
  if (recorder_) [[unlikely]]
    for (const Ray& ray : rays) recorder_->record({ray.origin, 0.0f, ray.direction, kInfinity, false, query});
  scene_.rays().intersectCoherent(rays, 0.0f, kInfinity, query, hits);
  for (std::size_t i = 0; i < paths.size(); ++i) paths[i].hit = hits[i];
}

void Integrator::traceBatch(std::span<const Ray> cameraRays, std::span<PixelSampler> samplers,
                            const RayCone& cone, std::span<CameraSample> out) const {
  if (cameraRays.size() != samplers.size() || cameraRays.size() != out.size())
    throw std::invalid_argument("Integrator::traceBatch: rays, samplers and results differ in number");
  for (CameraSample& result : out) result = CameraSample{};
  if (settings_.kind == IntegratorKind::AmbientOcclusion) {
    for (std::size_t i = 0; i < out.size(); ++i) {
      traceOcclusion(cameraRays[i], samplers[i], cone, out[i]);
      out[i].direct = out[i].radiance;
    }
    return;
  }
  // Each thread's paths, kept from batch to batch.
  thread_local std::vector<Path> scratch;
  if (scratch.size() < cameraRays.size()) scratch.resize(cameraRays.size());
  const std::span<Path> paths(scratch.data(), cameraRays.size());
  for (std::size_t i = 0; i < paths.size(); ++i) paths[i].start(cameraRays[i], cone);
  traceRadiance(paths, samplers, out);
}

Integrator::LightSample Integrator::sampleLight(const glm::vec3& n, int bucket, glm::vec2 u) const {
  LightSample sample;
  switch (settings_.envSampling) {
    case EnvSampling::Uniform:
      sample.direction = sampleUniformSphere(u);
      sample.pdf = uniformSpherePdf();
      break;
    case EnvSampling::Cosine: {
      const glm::vec3 local = sampleCosineHemisphere(u);
      sample.direction = Frame::fromZ(n).toWorld(local);
      sample.pdf = cosineHemispherePdf(local.z);
      break;
    }
    case EnvSampling::Env:
    case EnvSampling::Mis: {
      const EnvironmentSampler::Sample s = environmentSampler_.sample(bucket, u);
      return {s.direction, s.radiance, s.pdf};
    }
    case EnvSampling::MedianCut: {
      const MedianCutSampler::Sample s = medianCut_.sampler->sample(u);
      return {s.direction, s.radiance, s.pdf};
    }
    case EnvSampling::Lights: {
      // A delta light: "radiance" E_i / p_i with "pdf" 1 gives the estimator's f E_i cos / p_i.
      const EnvironmentPointLights::Sample s = medianCut_.pointLights->sample(u.x);
      return {s.direction, s.irradiance, 1.0f};
    }
    case EnvSampling::Brdf:
      return sample;
  }
  sample.radiance = environment_.radiance(sample.direction);
  return sample;
}

EnvironmentSampler::Lookup Integrator::lookupLight(const glm::vec3& w) const {
  return settings_.envSampling == EnvSampling::MedianCut ? medianCut_.sampler->lookup(w)
                                                         : environmentSampler_.lookup(w);
}

// A depth's shadow rays, and what each brings: its light if unoccluded, and (ground occlusion's
// samples of the hidden light, negative) if occluded.
struct Integrator::ShadowBatch {
  struct Light {
    std::size_t path;
    glm::vec3 ifClear{0.0f}, ifBlocked{0.0f};
  };
  std::vector<OcclusionQuery> rays;
  std::vector<Light> light;
  std::vector<std::uint8_t> blocked;
};

bool Integrator::groundLambert(const SurfacePoint& point) {
  // evalLocal's f = diffuseWeight baseColor / pi, with diffuseWeight = (1 - metallic)(1 - specular
  // max Fd(v.h)): constant over the directions when the specular factor is 0 and there is no
  // specular layer.
  return point.lobes.hasDiffuse && !point.lobes.hasSpecular && point.lobes.specular == 0.0f;
}

bool Integrator::groundCoverable(const SurfacePoint& point) {
  const BrdfLobes& lobes = point.lobes;
  return lobes.hasDiffuse && (groundLambert(point) || (!lobes.delta && lobes.alpha >= kGroundControlMinAlpha));
}

glm::vec3 Integrator::groundControl(const SurfacePoint& point) {
  // The diffuse base where v.h = 1, (1 - metallic)(1 - specular max(F0)) baseColor / pi: the
  // diffuse base to within Schlick's (1 - v.h)^5 over most pairs of directions, and on a Lambert
  // ground f itself.
  return diffuseWeight(point.lobes, 1.0f) * point.baseColor / glm::pi<float>();
}

void Integrator::sampleGroundOcclusion(const Path& p, std::size_t index, int lightSamples,
                                       const glm::vec2* splitDraws, CameraSample& result,
                                       ShadowBatch& shadows) const {
  const SurfacePoint& point = p.point;
  const glm::vec3 wo = -p.ray.direction, n = point.shadingNormal, ng = point.geometricNormal;
  const BrdfAtPoint* brdf = p.reflection();
  // a E_up exact; then, by the light samples here and the BRDF ray (groundOcclusionOfBounce and the
  // escapes), with the plain estimate's MIS weights, the rest: -a O, and (f - a) L V cos where f
  // is not a (a specular layer). A Lambert ground (exact) has only -a O.
  const glm::vec3 lit = p.throughput * p.control;
  result.radiance += lit * ground_->unoccludedIrradiance();
  if (p.exact && p.occluders.empty) return;
  const float samples = float(lightSamples);
  const glm::vec3 origin = offsetRayOrigin(point.position, point.positionError, ng);
  for (int j = 0; j < lightSamples; ++j) {
    const glm::vec2 u = splitDraws ? splitDraws[j] : p.uLight;
    // Exact: outside the cone nothing is blocked and O's integrand is 0 there, so no ray is needed
    // (the sampler stops early where its cell is outside the cone; mis is the strategy here).
    const EnvironmentSampler::Sample light =
        p.exact ? environmentSampler_.sampleWithin(p.bucket, u, p.occluders.axis, p.occluders.cosRadius)
                : environmentSampler_.sample(p.bucket, u);
    const glm::vec3& w = light.direction;
    if (!(light.pdf > 0.0f && w.y > 0.0f && maxComponent(light.radiance) > 0.0f)) continue;
    const bool occludable = p.occluders.contains(w);
    if (p.exact && !occludable) continue;
    const float density = samples * light.pdf;
    const float weight = powerHeuristic(density, pdfReflection(brdf, n, wo, w));
    const glm::vec3 ifBlocked = -lit * light.radiance * (w.y * weight / density);
    // Unblocked, f L cos - a L w_y: 0 on a Lambert ground.
    const glm::vec3 ifClear =
        p.exact ? glm::vec3(0.0f)
                : p.throughput * light.radiance *
                      (evalReflection(brdf, point.baseColor, n, wo, w) * std::max(0.0f, glm::dot(n, w)) -
                       p.control * w.y) *
                      (weight / density);
    if (!occludable) {
      result.radiance += ifClear;  // nothing above the plane outside the cone: no ray
      continue;
    }
    ++result.rays;
    shadows.rays.push_back({origin, w, 0.0f, kInfinity, RayQuery{RayKind::Secondary, p.cone}});
    shadows.light.push_back({index, ifClear, ifBlocked});
  }
}

void Integrator::groundOcclusionOfBounce(const Path& p, CameraSample& result) const {
  // The ray left a covered vertex by BRDF sampling (its bucket is still previousBucket) and was found
  // blocked (the caller's test): it counts minus the control's share of the light it hides,
  // a L w_y / pdf (previousControl; on a Lambert ground the throughput f cos / pdf is that).
  const glm::vec3& w = p.ray.direction;
  if (w.y <= 0.0f) return;
  const EnvironmentSampler::Lookup seen =
      environmentSampler_.lookupAt(p.previousBucket, environmentSampler_.mapUv(w));
  const glm::vec3& control = p.previousExact ? p.throughput : p.previousControl;
  result.radiance -= control * seen.radiance * powerHeuristic(p.previousPdf, p.previousLightSamples * seen.pdf);
}

void Integrator::traceRadiance(std::span<Path> paths, std::span<PixelSampler> samplers,
                               std::span<CameraSample> out) const {
  const EnvSampling strategy = settings_.envSampling;
  const bool sampleLights = strategy != EnvSampling::Brdf;
  const bool combine = strategy == EnvSampling::Mis || strategy == EnvSampling::MedianCut;
  // The strategies whose light samples and MIS lookups are the environment sampler's (prefetched).
  const bool envSampler = strategy == EnvSampling::Env || strategy == EnvSampling::Mis;
  const int maxDepth = settings_.kind == IntegratorKind::Direct ? 1 : settings_.maxDepth;
  const std::size_t count = paths.size();
  // The first vertex's split light draws, K per path (none for K = 1, which uses uLight).
  const int split = sampleLights ? settings_.cameraLightSamples : 1;
  std::vector<glm::vec2> splitDraws(split > 1 ? count * std::size_t(split) : 0);
  // A depth's shadow rays and their light (kept by the thread from batch to batch).
  thread_local ShadowBatch shadows;
  const auto splitDraw = [&](std::size_t i, int j) {
    return splitDraws[i * std::size_t(split) + std::size_t(j)];
  };

  // What has arrived after at most one scattering event: everything so far, taken once the first
  // vertex's escapes and the second vertex's emission are in (or when every path ended before).
  const auto keepDirect = [&] {
    for (CameraSample& result : out) result.direct = result.radiance;
  };
  for (int depth = 0;; ++depth) {
    bool any = false;
    if (depth == 0) {
      // The camera rays, all alive, leave the camera together: Embree's packet traversal.
      intersectCameraRays(paths);
      for (CameraSample& result : out) ++result.rays;
      any = count > 0;
    } else {
      // Bounce rays go their own ways: one at a time (packets of them were no faster).
      for (std::size_t i = 0; i < count; ++i) {
        Path& p = paths[i];
        if (!p.alive) continue;
        any = true;
        p.hit = intersect(p.ray, RayQuery{RayKind::Secondary, p.cone});
        ++out[i].rays;
        if (p.previousCovered && p.hit.hit) groundOcclusionOfBounce(p, out[i]);
      }
    }
    if (!any) {
      if (depth <= 1) keepDirect();
      return;
    }

    // Rays that escape. The environment seen by a BRDF-sampled ray counts when BRDF sampling is a
    // strategy of its own (brdf), MIS-weighted against the light strategy (mis, mediancut), or
    // fully after a delta bounce, which no light strategy can reach. With lights the point lights
    // stand for it at every other vertex.
    const auto weighted = [&](const Path& p) {
      return p.alive && !p.hit.hit && !p.previousDelta && !(p.previousCovered && p.previousExact) && combine;
    };
    if (strategy == EnvSampling::Mis)
      for (Path& p : paths)
        if (weighted(p)) {
          p.escapeUv = environmentSampler_.mapUv(p.ray.direction);
          environmentSampler_.prefetchLookup(p.previousBucket, p.escapeUv);
        }
    for (std::size_t i = 0; i < count; ++i) {
      Path& p = paths[i];
      if (!p.alive || p.hit.hit) continue;
      p.alive = false;
      if (p.previousDelta || strategy == EnvSampling::Brdf) {
        out[i].radiance += p.throughput * environment_.radiance(p.ray.direction);
      } else if (p.previousCovered && p.previousExact) {
        // Ground occlusion counted the unoccluded light whole (E_up).
      } else if (combine) {
        const EnvironmentSampler::Lookup seen = strategy == EnvSampling::Mis
                                                    ? environmentSampler_.lookupAt(p.previousBucket, p.escapeUv)
                                                    : lookupLight(p.ray.direction);
        // From a covered vertex the control's share, a L w_y / pdf, is in E_up already.
        const glm::vec3 throughput = p.previousCovered ? p.throughput - p.previousControl : p.throughput;
        out[i].radiance +=
            throughput * powerHeuristic(p.previousPdf, p.previousLightSamples * seen.pdf) * seen.radiance;
      }
    }

    // The surfaces hit, and the vertices' random numbers.
    for (std::size_t i = 0; i < count; ++i) {
      Path& p = paths[i];
      if (!p.alive) continue;
      const glm::vec3 wo = -p.ray.direction;
      p.point = scene_.surfacePoint(p.hit, wo, p.cone);
      if (depth == 0) recordFirstHit(p.point, p.hit.t, out[i]);
      out[i].radiance += p.throughput * p.point.emissive;
      // The path's next rays (shadow and bounce) start their cone at its width here.
      p.cone.width = p.cone.widthAt(p.hit.t);
      p.cone.pixel = {};  // the camera's differentials end at the first hit
      if (depth == maxDepth) {
        p.alive = false;
        continue;
      }
      // Every vertex draws the same numbers in the same order, used or not, so the dimensions of
      // the sampler line up between samples (and the Sobol pairs go to the first vertex).
      PixelSampler& sampler = samplers[i];
      p.uLight = sampler.next2D();
      p.uBrdf = sampler.next2D();
      p.uLobe = sampler.next1D();
      p.uRoulette = sampler.next1D();
      if (depth == 0 && split > 1)
        for (int j = 0; j < split; ++j)
          splitDraws[i * std::size_t(split) + std::size_t(j)] = sampler.splitLight2D(j, split);
      p.brdf.reset();
      if (!settings_.phong) p.brdf.emplace(p.point.lobes, p.point.shadingNormal, wo);
      p.bucket = envSampler ? environmentSampler_.bucketOf(p.point.shadingNormal) : EnvironmentSampler::kNoBucket;
      p.covered = ground_ && p.point.isGround && p.brdf && groundCoverable(p.point) &&
                  p.point.shadingNormal.y >= kTiltedUpCosine && p.point.geometricNormal.y >= kUpCosine;
      if (p.covered) {
        p.occluders = ground_->coneAt(offsetRayOrigin(p.point.position, p.point.positionError, p.point.geometricNormal));
        p.exact = groundLambert(p.point) && p.point.shadingNormal.y >= kUpCosine;
        p.control = p.exact ? evalReflection(&*p.brdf, p.point.baseColor, p.point.shadingNormal, wo,
                                             p.point.shadingNormal)
                            : groundControl(p.point);
        // The coefficient beta of the control (ground_visibility.h): where the objects hide at least
        // half of the light, beta a E_up exact and the rest estimated, f = a no longer cancelling.
        const float beta = groundVisibility_.at(p.point.position);
        if (beta < kGroundCoefficientBelow) {
          p.exact = false;
          p.control *= beta;
        }
      }
    }
    if (depth == 1) keepDirect();
    // (The light samples' tables were once prefetched here for the whole batch, in three stages:
    // each stage searched the cell tables again, and the render was 4-13% faster without them on
    // a 2 vCPU AMD EPYC, docs/benchmarks.md "The sampler's prefetch stages, removed".)
    const int lightSamples = depth == 0 ? split : 1;

    // Next-event estimation: every light sample of the batch, then their shadow rays in packets,
    // then the unoccluded ones' light. A path's samples keep their order, and nothing else adds to
    // its radiance in between, so each sum is the same as one path at a time.
    const float samples = float(lightSamples);
    shadows.rays.clear();
    shadows.light.clear();
    for (std::size_t i = 0; i < count && sampleLights; ++i) {
      Path& p = paths[i];
      if (!p.alive) continue;
      const SurfacePoint& point = p.point;
      const glm::vec3 wo = -p.ray.direction, n = point.shadingNormal, ng = point.geometricNormal;
      const BrdfAtPoint* brdf = p.reflection();
      if (p.covered) {
        sampleGroundOcclusion(p, i, lightSamples, lightSamples > 1 ? &splitDraws[i * std::size_t(split)] : nullptr,
                              out[i], shadows);
        continue;
      }
      // n light samples, each weighted 1/n: their density is n times the one sample's in the
      // power heuristic (Veach 1997, eq. 9.13).
      for (int j = 0; j < lightSamples; ++j) {
        const LightSample light = sampleLight(n, p.bucket, lightSamples == 1 ? p.uLight : splitDraw(i, j));
        const float cosTheta = glm::dot(n, light.direction);
        // Directions below the triangle's plane are blocked by the surface itself.
        if (light.pdf > 0.0f && cosTheta > 0.0f && glm::dot(light.direction, ng) > 0.0f &&
            maxComponent(light.radiance) > 0.0f) {
          const glm::vec3 f = evalReflection(brdf, point.baseColor, n, wo, light.direction);
          if (maxComponent(f) > 0.0f) {
            ++out[i].rays;
            const float density = samples * light.pdf;
            const float weight =
                combine ? powerHeuristic(density, pdfReflection(brdf, n, wo, light.direction)) : 1.0f;
            shadows.rays.push_back({offsetRayOrigin(point.position, point.positionError, ng), light.direction, 0.0f, kInfinity,
                                    RayQuery{RayKind::Secondary, p.cone}});
            shadows.light.push_back({i, p.throughput * f * light.radiance * (cosTheta * weight / density), glm::vec3(0.0f)});
          }
        }
      }
    }
    occluded(shadows.rays, shadows.blocked);
    for (std::size_t k = 0; k < shadows.light.size(); ++k)
      out[shadows.light[k].path].radiance += shadows.blocked[k] ? shadows.light[k].ifBlocked : shadows.light[k].ifClear;

    // The bounce.
    for (std::size_t i = 0; i < count; ++i) {
      Path& p = paths[i];
      if (!p.alive) continue;
      const SurfacePoint& point = p.point;
      const glm::vec3 wo = -p.ray.direction, n = point.shadingNormal, ng = point.geometricNormal;
      const BrdfAtPoint* brdf = p.reflection();
      const BrdfSample scattered = sampleReflection(brdf, point.baseColor, n, wo, p.uBrdf, p.uLobe);
      if (!scattered.valid()) {
        p.alive = false;
        continue;
      }
      // The control's throughput, a w_y / pdf (w_y > 0: the ray leaves the plane upwards).
      const glm::vec3 control =
          p.covered && !p.exact ? p.throughput * p.control * (std::max(0.0f, scattered.wi.y) / scattered.pdf)
                                : glm::vec3(0.0f);
      // From a covered vertex a ray upwards outside the objects' cone escapes (nothing else is above
      // the plane): the path ends without tracing it. On a Lambert ground such an escape adds nothing
      // (ground occlusion took the unoccluded light whole); otherwise it adds (f cos - a w_y) L / pdf
      // with the BRDF strategy's weight, as the escapes below. A ray below the plane (a tilted
      // shading normal's) is traced as in the plain estimate, its control 0.
      if (p.covered && scattered.wi.y > 0.0f && !p.occluders.contains(scattered.wi)) {
        if (!p.exact) {
          const EnvironmentSampler::Lookup seen =
              environmentSampler_.lookupAt(p.bucket, environmentSampler_.mapUv(scattered.wi));
          out[i].radiance += (p.throughput * scattered.weight - control) * seen.radiance *
                             powerHeuristic(scattered.pdf, samples * seen.pdf);
        }
        p.alive = false;
        continue;
      }
      p.throughput *= scattered.weight;
      p.previousControl = control;
      // The cone keeps the camera's spread whatever the lobe, as through a mirror: a bounce ray reads
      // the texture levels a shadow ray from this vertex reads, about the camera's resolution at the
      // path's length (docs/reference-tracer.md "Texture filtering"). Widening it by the sampled
      // lobe's width (about 1 radian for Lambert) read coarse levels that a point's own texels do
      // not average to: an alpha-tested grate went opaque for BRDF rays and stayed open for light
      // samples, and filtered normal maps went flat (0.5-0.8% on the bundled grounds).
      p.previousPdf = scattered.pdf;
      p.previousDelta = scattered.delta;
      p.previousLightSamples = samples;
      p.previousBucket = p.bucket;
      p.previousCovered = p.covered;
      p.previousExact = p.exact;
      // Russian roulette (Arvo and Kirk 1990): continue with probability q, dividing by q.
      if (depth + 1 >= kRussianRouletteDepth) {
        const float q = std::min(0.95f, maxComponent(p.throughput));
        if (p.uRoulette >= q) {
          p.alive = false;
          continue;
        }
        p.throughput /= q;
        p.previousControl /= q;
      }
      p.ray = Ray{offsetRayOrigin(point.position, point.positionError, sideFacing(ng, scattered.wi)), scattered.wi};
    }
  }
}

void Integrator::traceOcclusion(const Ray& ray, PixelSampler& sampler, const RayCone& cone,
                                CameraSample& result) const {
  const Hit hit = intersect(ray, RayQuery{RayKind::Camera, cone});
  ++result.rays;
  if (!hit.hit) {
    result.radiance = glm::vec3(1.0f);
    return;
  }
  const SurfacePoint point = scene_.surfacePoint(hit, -ray.direction, cone);
  recordFirstHit(point, hit.t, result);
  ++result.rays;
  const OcclusionSample sample =
      sampleAmbientOcclusion(scene_.rays(), point.position, &point.positionError, point.geometricNormal,
                             point.shadingNormal, sampler.next2D(), settings_.aoDistance);
  if (!sample.escaped) return;
  result.radiance = glm::vec3(1.0f);
  result.unoccludedDirection = sample.direction;
}

}  // namespace iblkit
