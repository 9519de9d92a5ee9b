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

// The ground's vertices that ground occlusion takes: a shading and a geometric normal within
// 4.5e-4 radians of +Y (a plane's interpolated normals are +Y to the rounding; a normal texture's
// are not), where the upper hemisphere of E_up is the surface's own.
constexpr float kUpCosine = 1.0f - 1e-7f;

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

void Integrator::sampleGroundOcclusion(const Path& p, std::size_t index, int lightSamples,
                                       const glm::vec2* splitDraws, CameraSample& result,
                                       ShadowBatch& shadows) const {
  const SurfacePoint& point = p.point;
  const glm::vec3 wo = -p.ray.direction, n = point.shadingNormal, ng = point.geometricNormal;
  const BrdfAtPoint* brdf = p.reflection();
  // The Lambert BRDF, the same for every pair of directions above the plane.
  const glm::vec3 f = evalReflection(brdf, point.baseColor, n, wo, n);
  const glm::vec3 lit = p.throughput * f;
  // f (E_up - O): E_up exact, O (the light the objects hide) by the light samples here and the
  // BRDF ray (groundOcclusionOfBounce), with the plain estimate's MIS weights.
  result.radiance += lit * ground_->unoccludedIrradiance();
  if (p.occluders.empty) return;
  const float samples = float(lightSamples);
  const glm::vec3 origin = offsetRayOrigin(point.position, ng);
  for (int j = 0; j < lightSamples; ++j) {
    // Outside the cone nothing is blocked: O's integrand is 0 there, and no ray is needed. (The
    // sampler stops early where its cell is outside the cone; mis is the strategy here.)
    const EnvironmentSampler::Sample light = environmentSampler_.sampleWithin(
        p.bucket, splitDraws ? splitDraws[j] : p.uLight, p.occluders.axis, p.occluders.cosRadius);
    const glm::vec3& w = light.direction;
    if (!(light.pdf > 0.0f && w.y > 0.0f && p.occluders.contains(w) && maxComponent(light.radiance) > 0.0f))
      continue;
    const float density = samples * light.pdf;
    const float weight = powerHeuristic(density, pdfReflection(brdf, n, wo, w));
    ++result.rays;
    shadows.rays.push_back({origin, w, 0.0f, kInfinity, RayQuery{RayKind::Secondary, p.cone}});
    shadows.light.push_back({index, glm::vec3(0.0f), -lit * light.radiance * (w.y * weight / density)});
  }
}

void Integrator::groundOcclusionOfBounce(const Path& p, CameraSample& result) const {
  // The ray left a covered vertex by BRDF sampling (its bucket is still previousBucket), and its
  // throughput is f cos / pdf already, and it was found blocked (the caller's test): it counts the
  // light it hides (an escape counts nothing).
  const glm::vec3& w = p.ray.direction;
  if (w.y <= 0.0f) return;
  const EnvironmentSampler::Lookup seen =
      environmentSampler_.lookupAt(p.previousBucket, environmentSampler_.mapUv(w));
  result.radiance -= p.throughput * seen.radiance * powerHeuristic(p.previousPdf, p.previousLightSamples * seen.pdf);
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
      return p.alive && !p.hit.hit && !p.previousDelta && !p.previousCovered && combine;
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
      } else if (p.previousCovered) {
        // Ground occlusion counted the unoccluded light whole (E_up).
      } else if (combine) {
        const EnvironmentSampler::Lookup seen = strategy == EnvSampling::Mis
                                                    ? environmentSampler_.lookupAt(p.previousBucket, p.escapeUv)
                                                    : lookupLight(p.ray.direction);
        out[i].radiance +=
            p.throughput * powerHeuristic(p.previousPdf, p.previousLightSamples * seen.pdf) * seen.radiance;
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
      p.covered = ground_ && p.point.isGround && p.brdf && groundLambert(p.point) &&
                  p.point.shadingNormal.y >= kUpCosine && p.point.geometricNormal.y >= kUpCosine;
      if (p.covered) p.occluders = ground_->coneAt(offsetRayOrigin(p.point.position, p.point.geometricNormal));
    }
    if (depth == 1) keepDirect();
    // The light samples' tables and texels, brought in for the whole batch stage by stage.
    const int lightSamples = depth == 0 ? split : 1;
    if (envSampler)
      for (int stage = 0; stage < EnvironmentSampler::kPrefetchStages; ++stage)
        for (std::size_t i = 0; i < count; ++i) {
          if (!paths[i].alive) continue;
          const int bucket = paths[i].bucket;
          if (lightSamples == 1)
            environmentSampler_.prefetchSample(bucket, paths[i].uLight, stage);
          else
            for (int j = 0; j < lightSamples; ++j) environmentSampler_.prefetchSample(bucket, splitDraw(i, j), stage);
        }

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
        sampleGroundOcclusion(p, i, lightSamples, split > 1 ? &splitDraws[i * std::size_t(split)] : nullptr,
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
            shadows.rays.push_back({offsetRayOrigin(point.position, ng), light.direction, 0.0f, kInfinity,
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
      // From a covered vertex a ray outside the objects' cone escapes (nothing else is above the
      // plane), and an escape adds nothing there (ground occlusion took the unoccluded light
      // whole): the path ends without tracing it.
      if (!scattered.valid() || (p.covered && !p.occluders.contains(scattered.wi))) {
        p.alive = false;
        continue;
      }
      p.throughput *= scattered.weight;
      // The cone widens by the sampled lobe's angular width, the half-angle of a cone whose solid
      // angle is 1 / pdf (pi theta^2 = 1 / pdf), at most 1 radian (a Lambert lobe); a mirror keeps
      // it (docs/reference-tracer.md "Texture filtering").
      if (!scattered.delta) p.cone.spread += std::min(1.0f, 1.0f / std::sqrt(glm::pi<float>() * scattered.pdf));
      p.previousPdf = scattered.pdf;
      p.previousDelta = scattered.delta;
      p.previousLightSamples = samples;
      p.previousBucket = p.bucket;
      p.previousCovered = p.covered;
      // Russian roulette (Arvo and Kirk 1990): continue with probability q, dividing by q.
      if (depth + 1 >= kRussianRouletteDepth) {
        const float q = std::min(0.95f, maxComponent(p.throughput));
        if (p.uRoulette >= q) {
          p.alive = false;
          continue;
        }
        p.throughput /= q;
      }
      p.ray = Ray{offsetRayOrigin(point.position, sideFacing(ng, scattered.wi)), scattered.wi};
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
      sampleAmbientOcclusion(scene_.rays(), point.position, point.geometricNormal, point.shadingNormal,
                             sampler.next2D(), settings_.aoDistance);
  if (!sample.escaped) return;
  result.radiance = glm::vec3(1.0f);
  result.unoccludedDirection = sample.direction;
}

}  // namespace iblkit
