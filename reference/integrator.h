#pragma once
// The integrators of the reference path tracer: what one camera ray sees.
//
//   path    unidirectional path tracing. At every non-delta vertex the environment is sampled
//           directly (next-event estimation: a shadow ray, RayScene::occluded) and by the BRDF
//           (sampleBrdf), the two combined with the power heuristic (Veach 1997, "Robust Monte
//           Carlo Methods for Light Transport Simulation", chapter 9.2.4, with beta = 1.5, not his
//           2: measured lower noise, integrator.cpp). A perfect
//           mirror (delta lobe) has no NEE: the environment its reflected ray sees counts fully.
//           Russian roulette on the throughput after kRussianRouletteDepth bounces; at most
//           maxDepth scattering events.
//   direct  the same estimator stopped after one scattering event: environment light reflected
//           once, with visibility (plus emission of what the BRDF ray hits).
//   ao      ambient occlusion: the fraction of cosine-weighted directions around the shading
//           normal that no geometry within aoDistance blocks, as grey; 1 for rays that miss.
//
// --env-sampling selects which strategies estimate the environment at a vertex (the sampling
// study): uniform (uniform sphere directions), cosine (cosine-weighted hemisphere about the
// shading normal), env (environment importance sampling), brdf (BRDF sampling alone) each on its
// own, mis (env + brdf, power heuristic, the default), or mediancut (median-cut sampling,
// median_cut_sampler.h, + brdf, power heuristic, like mis). Whatever the strategy the path is
// continued by BRDF sampling, so every one of these converges to the same image.
//
// Splitting (cameraLightSamples K): at the camera ray's first hit the light strategy takes K
// samples, each weighted 1/K, and the BRDF strategy one; MIS weighs them by Veach's power heuristic
// with sample counts (eq. 9.13: w_i = (n_i p_i)^1.5 / sum_k (n_k p_k)^1.5), so the estimator stays
// unbiased. Later vertices take one light sample. The K draws are stratified (PixelSampler::
// splitLight2D). K = 1 is the plain estimator, bit for bit.
//
// Ground occlusion (IntegratorSettings::groundOcclusion, ground_occlusion.h): with mis, at a vertex
// on a horizontal Lambert ground the direct light is f E_up (exact) minus the light the objects
// hide, estimated by the light samples (a shadow ray only for those inside the objects' cone) and
// the BRDF ray where it is blocked, with the plain estimate's MIS weights; the BRDF ray that
// escapes from such a vertex adds nothing. On a rough ground with a specular layer the same split
// is a control variate: a E_up (a, groundControl: the diffuse base at v.h = 1) plus the estimate of
// (f V cos - a w_y) L by the same strategies, whose light samples and BRDF rays outside the cone
// need no ray (they add their unblocked term); where the objects hide at least half of the light a
// coefficient beta < 1 weighs the control (ground_visibility.h). The vertex's indirect light (the BRDF ray's path) is
// as before, and so are the random numbers: with it off the image is the same as before, bit for bit.
//
// lights is the biased approximation (environment_point_lights.h): at every non-delta vertex one of
// the N median-cut point lights, picked by its power, with a shadow ray (next-event estimation,
// weighted by 1 / its probability: in expectation the sum over all N lights). BRDF-sampled rays
// that escape add nothing, except after a delta bounce: the camera ray and a perfect mirror's ray
// see the map itself. It converges to the image of the N point lights, not to the map's.

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/brdf.h"
#include "core/enum_names.h"
#include "core/environment_map.h"
#include "core/ray.h"
#include "reference/environment_point_lights.h"
#include "reference/environment_sampler.h"
#include "reference/ground_occlusion.h"
#include "reference/ground_visibility.h"
#include "reference/median_cut_sampler.h"
#include "reference/pixel_sampler.h"
#include "reference/ray_recorder.h"
#include "reference/render_scene.h"

namespace iblkit {

enum class IntegratorKind { Path, Direct, AmbientOcclusion };
enum class EnvSampling { Uniform, Cosine, Brdf, Env, Mis, MedianCut, Lights };

inline constexpr EnumName<IntegratorKind> kIntegratorNames[] = {{IntegratorKind::Path, "path"},
                                                                {IntegratorKind::Direct, "direct"},
                                                                {IntegratorKind::AmbientOcclusion, "ao"}};
inline constexpr EnumName<EnvSampling> kEnvSamplingNames[] = {
    {EnvSampling::Uniform, "uniform"}, {EnvSampling::Cosine, "cosine"}, {EnvSampling::Brdf, "brdf"},
    {EnvSampling::Env, "env"},         {EnvSampling::Mis, "mis"},       {EnvSampling::MedianCut, "mediancut"},
    {EnvSampling::Lights, "lights"}};

// Parse a name of the tables above; anything else throws Error("--integrator: unknown integrator
// 'x' (expected one of path, direct, ao)") and the like.
IntegratorKind parseIntegratorKind(const std::string& name);
EnvSampling parseEnvSampling(const std::string& name);

// Camera rays the renderer traces together (Integrator::traceBatch): enough paths for their
// environment lookups' cache misses to overlap, few enough for their state to stay in L1/L2.
inline constexpr int kTraceBatch = 32;

// Bounces after which Russian roulette may end a path. Six, not three: in the open scenes the
// report traces most paths escape to the map within a few bounces, so roulette at the third saved
// 2-5% of the time and cost 9-27% more noise (bunny, suzi and pmndrs under studio, venice and
// sky; docs/benchmarks.md, "Russian roulette from the sixth bounce").
inline constexpr int kRussianRouletteDepth = 6;

struct IntegratorSettings {
  IntegratorKind kind = IntegratorKind::Path;
  EnvSampling envSampling = EnvSampling::Mis;
  int maxDepth = 16;  // scattering events of a path (path only; direct uses 1)
  float aoDistance = std::numeric_limits<float>::infinity();  // occluders farther away do not count
  // Set: every surface reflects with the modified Phong lobe (brdf.h, Lafortune and Willems 1994)
  // of this exponent, tinted by its base colour, instead of the glTF BRDF: the second material
  // model of the sampling study (a lobe whose shape is known exactly).
  std::optional<PhongLobe> phong;
  // Light samples at the camera ray's first hit (splitting, above), 1..kMaxSplitLightDraws; path
  // and direct with a light strategy (not brdf).
  int cameraLightSamples = 1;
  // mis at a horizontal ground's vertices (Lambert, or rough under a specular layer): the direct
  // light as the exact unoccluded irradiance minus the part the objects hide (ground_occlusion.h;
  // iblkit-trace --ground-occlusion). No effect where it does not apply.
  bool groundOcclusion = true;
};

// Everything one camera sample produces; the renderer averages these per pixel.
struct CameraSample {
  glm::vec3 radiance{0.0f};  // the estimate (ao: the visibility, grey)
  // The part of `radiance` that reached the camera after at most one scattering event: the map
  // seen directly, emission at the first two vertices, the first vertex's next-event estimate and
  // its BRDF ray's escape. Bit for bit the direct integrator's estimate with the same numbers;
  // radiance - direct is the indirect light (the noise split by depth). ao: the visibility.
  glm::vec3 direct{0.0f};
  // First-hit features (zero where the camera ray escapes): base colour, world shading normal,
  // distance along the unit camera ray, and 1 for a non-ground object (the object mask).
  glm::vec3 albedo{0.0f};
  glm::vec3 normal{0.0f};
  float distance = 0.0f;
  float objectCoverage = 0.0f;
  // ao only: the sampled direction if unoccluded, else zero (their mean is the bent normal).
  glm::vec3 unoccludedDirection{0.0f};
  std::uint32_t rays = 0;  // rays traced (closest-hit and shadow)
};

// The light samplers of the median-cut strategies, both of `environment`: the median-cut sampler
// (mediancut) and the point lights (lights). Only the chosen strategy's need be set.
struct MedianCutLighting {
  const MedianCutSampler* sampler = nullptr;
  const EnvironmentPointLights* pointLights = nullptr;
};

class Integrator {
 public:
  // `scene`, `environment`, `environmentSampler` and what `medianCut` points to must outlive the
  // integrator. `environmentSampler` samples `environment` (used by the env and mis strategies).
  // Throws std::invalid_argument when settings.envSampling is mediancut or lights and `medianCut`
  // lacks its sampler, or when settings.cameraLightSamples is outside 1..kMaxSplitLightDraws.
  Integrator(const RenderScene& scene, const EnvironmentMap& environment,
             const EnvironmentSampler& environmentSampler, const IntegratorSettings& settings,
             const MedianCutLighting& medianCut = {});

  const IntegratorSettings& settings() const { return settings_; }

  // Logs every ray traced from now on into `recorder` (nullptr: stop; the default). The recorder
  // must outlive the integrator's use of it. For the ray-replay benchmark only.
  void recordRays(RayRecorder* recorder) { recorder_ = recorder; }

  // What the camera ray (unit direction) sees, with random numbers from `sampler`. `cone` is the
  // camera ray's footprint (texture levels; the renderer's is a fraction of the pixel, zero reads
  // the finest level); the path's later rays continue it (docs/reference-tracer.md "Texture
  // filtering"). The camera ray is a RayKind::Camera query: it passes through the back faces of
  // single-sided materials.
  CameraSample trace(const Ray& cameraRay, PixelSampler& sampler, const RayCone& cone = {}) const;

  // trace() for a batch of camera rays, each with its own sampler: out[i] is
  // trace(cameraRays[i], samplers[i], cone) (each path draws the same numbers in the same order
  // and does the same arithmetic), but the paths advance together, vertex by vertex: all
  // closest-hit queries of a depth (the camera rays in Embree's coherent packets, RayScene::
  // intersectCoherent, the bounce rays one by one), then all escapes, then all vertices, then all light
  // samples (the escapes' environment lookups are prefetched for the whole batch before any is read,
  // EnvironmentSampler::prefetchLookup),
  // whose shadow rays go to Embree in packets (the batch RayScene::occluded), then all bounces.
  // The three spans have the same size (any; the renderer passes kTraceBatch).
  void traceBatch(std::span<const Ray> cameraRays, std::span<PixelSampler> samplers, const RayCone& cone,
                  std::span<CameraSample> out) const;

 private:
  struct LightSample {
    glm::vec3 direction{0.0f};
    glm::vec3 radiance{0.0f};
    // Per steradian; 0: no sample. A point light (lights) has 1, its radiance being its
    // irradiance over its probability.
    float pdf = 0.0f;
  };
  // The environment strategy's direction at a point with shading normal n (not for brdf or lights);
  // `bucket` is the environment sampler's bucket of n (env, mis: EnvironmentSampler::bucketOf).
  LightSample sampleLight(const glm::vec3& n, int bucket, glm::vec2 u) const;
  // The density with which the light strategy of mis or mediancut samples world direction w, and
  // the environment's radiance there.
  EnvironmentSampler::Lookup lookupLight(const glm::vec3& w) const;
  // The surface reflection model: the glTF BRDF prepared at the vertex (`brdf`), or, when it is
  // null (settings_.phong set), the Phong lobe.
  glm::vec3 evalReflection(const BrdfAtPoint* brdf, const glm::vec3& baseColor, const glm::vec3& n,
                           const glm::vec3& wo, const glm::vec3& wi) const;
  float pdfReflection(const BrdfAtPoint* brdf, const glm::vec3& n, const glm::vec3& wo,
                      const glm::vec3& wi) const;
  BrdfSample sampleReflection(const BrdfAtPoint* brdf, const glm::vec3& baseColor, const glm::vec3& n,
                              const glm::vec3& wo, glm::vec2 u, float uLobe) const;
  // RayScene::intersect, logged when a recorder is set.
  Hit intersect(const Ray& ray, const RayQuery& query) const;
  // RayScene::occluded for each of `rays` into blocked[k] (resized), logged when a recorder is set.
  void occluded(std::span<const OcclusionQuery> rays, std::vector<std::uint8_t>& blocked) const;
  struct Path;
  struct ShadowBatch;
  // Whether ground occlusion may take a vertex's direct light: a Lambert BRDF (constant f).
  static bool groundLambert(const SurfacePoint& point);
  // Whether ground occlusion takes a ground vertex of this material (with its normals up): a Lambert
  // BRDF, or a diffuse base under a specular layer of GGX alpha at least kGroundControlMinAlpha.
  static bool groundCoverable(const SurfacePoint& point);
  // Ground occlusion's constant BRDF a at a ground vertex with a diffuse base (Path::control).
  static glm::vec3 groundControl(const SurfacePoint& point);
  // Ground occlusion's estimate at p's vertex (p.covered): f E_up into `result`, and the shadow rays
  // of the light samples (p.uLight, or the K splitDraws) that fall in p.occluders into `shadows`,
  // each with minus its MIS-weighted light if blocked.
  void sampleGroundOcclusion(const Path& p, std::size_t index, int lightSamples, const glm::vec2* splitDraws,
                             CameraSample& result, ShadowBatch& shadows) const;
  // Ground occlusion's BRDF strategy for p's ray, BRDF-sampled at a covered vertex
  // (p.previousCovered) and just found blocked (p.hit): minus the MIS-weighted light it hides.
  void groundOcclusionOfBounce(const Path& p, CameraSample& result) const;
  // The camera rays of a batch (all alive, one cone) into their paths' hits: RayScene::
  // intersectCoherent, logged when a recorder is set.
  void intersectCameraRays(std::span<Path> paths) const;
  // The paths of a batch of the radiance integrators (path, direct), advanced together.
  void traceRadiance(std::span<Path> paths, std::span<PixelSampler> samplers, std::span<CameraSample> out) const;
  void traceOcclusion(const Ray& ray, PixelSampler& sampler, const RayCone& cone, CameraSample& result) const;

  const RenderScene& scene_;
  const EnvironmentMap& environment_;
  const EnvironmentSampler& environmentSampler_;
  IntegratorSettings settings_;
  MedianCutLighting medianCut_;
  std::optional<GroundOcclusion> ground_;  // when settings_.groundOcclusion applies to the scene
  GroundVisibility groundVisibility_;      // its coefficient per point (1 everywhere without ground_)
  RayRecorder* recorder_ = nullptr;
};

}  // namespace iblkit
