#include "reference/integrator.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <stdexcept>

#include "core/brdf.h"
#include "core/error.h"
#include "core/frame.h"
#include "core/sampling.h"
#include "raytrace/ray_offset.h"
#include "reference/ambient_occlusion.h"

namespace iblkit {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Veach's power heuristic with beta = 2 for one sample of each of two strategies (Veach 1997,
// eq. 9.13): the weight of the strategy whose density is pdfA.
float powerHeuristic(float pdfA, float pdfB) {
  const float a = pdfA * pdfA, b = pdfB * pdfB;
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
  if (settings.envSampling == EnvSampling::MedianCut && !medianCut.sampler)
    throw std::invalid_argument("Integrator: mediancut needs a MedianCutSampler");
  if (settings.envSampling == EnvSampling::Lights && !medianCut.pointLights)
    throw std::invalid_argument("Integrator: lights needs EnvironmentPointLights");
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

bool Integrator::occluded(const glm::vec3& origin, const glm::vec3& direction, float tmax,
                          const RayQuery& query) const {
  if (recorder_) [[unlikely]]
    recorder_->record({origin, 0.0f, direction, tmax, true, query});
  return scene_.rays().occluded(origin, direction, 0.0f, tmax, query);
}

CameraSample Integrator::trace(const Ray& cameraRay, PixelSampler& sampler, const RayCone& cone) const {
  CameraSample result;
  if (settings_.kind == IntegratorKind::AmbientOcclusion)
    traceOcclusion(cameraRay, sampler, cone, result);
  else
    traceRadiance(cameraRay, sampler, cone, result);
  return result;
}

Integrator::LightSample Integrator::sampleLight(const glm::vec3& n, glm::vec2 u) const {
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
      const EnvironmentSampler::Sample s = environmentSampler_.sample(u);
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

void Integrator::traceRadiance(Ray ray, PixelSampler& sampler, RayCone cone, CameraSample& result) const {
  const EnvSampling strategy = settings_.envSampling;
  const bool sampleLights = strategy != EnvSampling::Brdf;
  const bool combine = strategy == EnvSampling::Mis || strategy == EnvSampling::MedianCut;
  const int maxDepth = settings_.kind == IntegratorKind::Direct ? 1 : settings_.maxDepth;

  glm::vec3 throughput(1.0f);
  float previousPdf = 0.0f;   // BRDF pdf of the ray being traced
  bool previousDelta = true;  // the camera ray, like a mirror ray, sees the environment directly
  for (int depth = 0;; ++depth) {
    const Hit hit = intersect(ray, RayQuery{depth == 0 ? RayKind::Camera : RayKind::Secondary, cone});
    ++result.rays;
    if (!hit.hit) {
      // The environment seen by a BRDF-sampled ray counts when BRDF sampling is a strategy of
      // its own (brdf), MIS-weighted against the light strategy (mis, mediancut), or fully after a
      // delta bounce, which no light strategy can reach. With lights the point lights stand for it
      // at every other vertex.
      if (previousDelta || strategy == EnvSampling::Brdf) {
        result.radiance += throughput * environment_.radiance(ray.direction);
      } else if (combine) {
        const EnvironmentSampler::Lookup seen = lookupLight(ray.direction);
        result.radiance += throughput * powerHeuristic(previousPdf, seen.pdf) * seen.radiance;
      }
      return;
    }

    const glm::vec3 wo = -ray.direction;
    const SurfacePoint point = scene_.surfacePoint(hit, wo, cone);
    if (depth == 0) recordFirstHit(point, hit.t, result);
    result.radiance += throughput * point.emissive;
    // The path's next rays (shadow and bounce) start their cone at its width here.
    cone.width = cone.widthAt(hit.t);
    cone.pixel = {};  // the camera's differentials end at the first hit
    if (depth == maxDepth) return;

    // Every vertex draws the same numbers in the same order, used or not, so the dimensions of
    // the sampler line up between samples (and the Sobol pairs go to the first vertex).
    const glm::vec2 uLight = sampler.next2D();
    const glm::vec2 uBrdf = sampler.next2D();
    const float uLobe = sampler.next1D();
    const float uRoulette = sampler.next1D();
    const glm::vec3 n = point.shadingNormal, ng = point.geometricNormal;
    // The glTF BRDF at this vertex, prepared once for its eval, pdf and sample calls (none with --phong).
    std::optional<BrdfAtPoint> gltfBrdf;
    if (!settings_.phong) gltfBrdf.emplace(point.lobes, n, wo);
    const BrdfAtPoint* brdf = gltfBrdf ? &*gltfBrdf : nullptr;

    if (sampleLights) {
      const LightSample light = sampleLight(n, uLight);
      const float cosTheta = glm::dot(n, light.direction);
      // Directions below the triangle's plane are blocked by the surface itself.
      if (light.pdf > 0.0f && cosTheta > 0.0f && glm::dot(light.direction, ng) > 0.0f &&
          maxComponent(light.radiance) > 0.0f) {
        const glm::vec3 f = evalReflection(brdf, point.baseColor, n, wo, light.direction);
        if (maxComponent(f) > 0.0f) {
          ++result.rays;
          if (!occluded(offsetRayOrigin(point.position, ng), light.direction, kInfinity,
                        RayQuery{RayKind::Secondary, cone})) {
            const float weight =
                combine ? powerHeuristic(light.pdf, pdfReflection(brdf, n, wo, light.direction)) : 1.0f;
            result.radiance += throughput * f * light.radiance * (cosTheta * weight / light.pdf);
          }
        }
      }
    }

    const BrdfSample scattered = sampleReflection(brdf, point.baseColor, n, wo, uBrdf, uLobe);
    if (!scattered.valid()) return;
    throughput *= scattered.weight;
    // The cone widens by the sampled lobe's angular width, the half-angle of a cone whose solid
    // angle is 1 / pdf (pi theta^2 = 1 / pdf), at most 1 radian (a Lambert lobe); a mirror keeps
    // it (docs/reference-tracer.md "Texture filtering").
    if (!scattered.delta) cone.spread += std::min(1.0f, 1.0f / std::sqrt(glm::pi<float>() * scattered.pdf));
    previousPdf = scattered.pdf;
    previousDelta = scattered.delta;
    // Russian roulette (Arvo and Kirk 1990): continue with probability q, dividing by q.
    if (depth + 1 >= kRussianRouletteDepth) {
      const float q = std::min(0.95f, maxComponent(throughput));
      if (uRoulette >= q) return;
      throughput /= q;
    }
    ray = Ray{offsetRayOrigin(point.position, sideFacing(ng, scattered.wi)), scattered.wi};
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
