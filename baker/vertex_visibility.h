#pragma once
// Per-vertex visibility of the environment, baked with Embree rays (docs/baker.md): ambient
// occlusion, the bent normal and the order-3 spherical-harmonic shadowed diffuse transfer vector,
// all estimated from one set of cosine-distributed rays per vertex.
//
// Sampling: for each vertex, `rayCount` points of the Owen-scrambled Sobol (0,2)-sequence
// (low_discrepancy.h), scrambled by a hash of (seed, mesh, vertex), are warped to the
// cosine-weighted hemisphere about the vertex normal (Malley's method, sampling.h). Each ray
// starts at the vertex moved off the surface by offsetRayOrigin (ray_offset.h) along the vertex
// normal and is tested with rtcOccluded1 against every mesh (the ground included) up to
// `maxDistance`. The result depends only on the scene, the seed and the ray count, not on the
// number of threads.
//
// One-ring rejection: a direction below the plane of one of the triangles around the vertex
// points into the surface the vertex lies on, and from an origin just off the vertex it could
// slip past that triangle's edge. Such a direction is re-drawn as the same point of an
// independently scrambled copy of the point set, up to kMaxRedraws times; a direction still
// rejected then counts as occluded. Re-drawing (rather than counting as occluded) keeps a convex vertex at AO
// = 1: its real hemisphere is open, only the tessellated one-ring clips the horizon.
//
// Options (docs/baker.md): a distance falloff of the occlusion, area sampling of the ray origins
// over the vertex's one-ring, and interreflected transfer (bounces).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <memory>
#include <span>
#include <vector>

#include "core/material.h"
#include "core/mesh.h"
#include "core/ray.h"
#include "core/scene.h"
#include "core/spherical_harmonics.h"
#include "core/texture_sampling.h"

namespace iblkit {

// How often a rejected direction is re-drawn before it counts as occluded.
inline constexpr int kMaxRedraws = 8;

struct VisibilitySettings {
  int rayCount = 256;        // rays per vertex, >= 1 (a power of two keeps the Sobol points a net)
  float maxDistance = 0.0f;  // an occluder farther than this (world units) is ignored; 0 = infinite
  std::uint32_t seed = 0;    // scrambling seed: the same seed gives bit-identical results
  // Distance falloff exponent p >= 0 (needs maxDistance > 0 when p > 0): a ray blocked at
  // distance t occludes by (1 - t / maxDistance)^p, so near occluders count fully and those near
  // maxDistance hardly at all. 0 = off: every occluder within maxDistance occludes fully.
  float falloff = 0.0f;
  // Area sampling: ray i starts at a point of the vertex's barycentric dual cell (the part of each
  // one-ring triangle where the vertex's barycentric coordinate is the largest, a third of the
  // triangle, chosen in proportion to area), about the interpolated normal there, and directions
  // below that triangle's plane are re-drawn. The result is the mean visibility of the surface
  // the vertex stands for instead of the visibility at the vertex itself: smoother for large
  // triangles whose vertices sit in creases. A vertex without a one-ring triangle is sampled at
  // the vertex.
  bool areaSampling = false;
  // Interreflected transfer (Sloan, Kautz and Snyder 2002, section 5, "interreflected diffuse
  // transfer"): each bounce b adds, for every occluded ray of a vertex, the transfer of bounce
  // b - 1 interpolated at the point the ray hits (front faces only), times the hit mesh's albedo
  // / pi, integrated with the same rays (1 / N times the sum over the N rays of the hit's albedo
  // times its transfer). The transfer is of irradiance (the shader multiplies by the vertex's own
  // albedo), so the albedo that reflects is the hit's. 0 = shadowed transfer only.
  // The ambient occlusion and bent normals are not changed.
  int bounces = 0;
  // Diffuse albedo of each mesh, in [0, 1] (one grey value per mesh: the transfer vector is one
  // scalar per SH coefficient). Required (one per mesh) when bounces > 0.
  std::vector<float> albedo;
  // The meshes' materials (Mesh::material indexes them) and the scene's textures, for alpha: the
  // rays (visibility and bounces) pass through what a MASK or BLEND material says is not there,
  // through the very AlphaFilter the tracer's shadow rays use (raytrace/alpha_filter.h, finest
  // texture level; the baker traces no camera rays, so doubleSided changes nothing). Empty
  // materials: every mesh is opaque. useSceneMaterials fills both from a scene.
  std::vector<Material> materials;
  std::shared_ptr<const SceneTextures> textures;
  // Called with (vertices done, total) from the worker threads while the bake runs, possibly
  // concurrently: it must be thread-safe. May be empty. Each bounce pass visits every vertex
  // again, so total = vertices * (1 + bounces).
  std::function<void(std::size_t, std::size_t)> progress;
};

// The visibility of every vertex of one mesh, in the mesh's vertex order.
struct MeshVisibility {
  // Ambient occlusion: the fraction of cosine-weighted rays that escape, in [0, 1]; 1 = open sky.
  // With a falloff, each ray counts by its visibility 1 - (1 - t / maxDistance)^p instead of 0 or 1
  // (and so it does in the bent normal and the transfer).
  std::vector<float> ambientOcclusion;
  // Bent normal: the normalised mean of the escaping directions (the vertex normal when none
  // escapes). Unit length, world space.
  std::vector<glm::vec3> bentNormals;
  // Length of that mean (sum of escaping directions / number of escaping rays), in [0, 1]: 2/3
  // for an open cosine-weighted hemisphere, larger for a narrower visibility cone; 0 when no ray
  // escapes.
  std::vector<float> bentNormalLengths;
  // Shadowed diffuse transfer (Sloan, Kautz and Snyder 2002, "Precomputed Radiance Transfer",
  // section 5, eq. 7): t_k = integral of Y_k(w) V(w) max(0, n.w) dw, estimated with the cosine
  // pdf cos/pi as (pi / N) * sum over escaping rays of Y_k(w) (shBasis9's basis and order).
  // Lambert radiance under an environment with radiance coefficients L_k is
  // rho / pi * sum_k t_k L_k; unshadowed, t_k = A_l Y_k(n) (Ramamoorthi and Hanrahan 2001).
  std::vector<ShBasis9> transfer;
};

struct VisibilityStatistics {
  std::size_t vertices = 0;
  std::size_t rays = 0;        // occlusion rays traced
  std::size_t rejected = 0;    // directions below the one-ring that were re-drawn or dropped
  std::size_t bounceRays = 0;  // closest-hit rays traced for the bounces
  // Wall-clock seconds of the stages: building Embree's scene, the visibility rays, the bounces.
  double buildSeconds = 0.0, raySeconds = 0.0, bounceSeconds = 0.0;
};

// Bakes every vertex of every mesh, all meshes occluding each other. Runs in parallel over the
// vertices with TBB (the caller's task arena decides the thread count). Meshes must have one
// unit normal per position (Scene loading guarantees it). Throws Error("vertex visibility: ...")
// for a ray count below 1, a negative or non-finite maxDistance, a falloff without a maximum
// distance, negative bounces, a missing or out-of-range albedo, or missing normals, and the
// RayScene errors for bad geometry (no triangles, non-finite positions).
std::vector<MeshVisibility> bakeVertexVisibility(const std::vector<Mesh>& meshes,
                                                 const VisibilitySettings& settings,
                                                 VisibilityStatistics* statistics = nullptr);

// The suns' light bounced onto every vertex (docs/dominant-lights.md, "Bounce light of the suns"),
// for the engine's lights modes, per unit of each sun's irradiance E_i (at normal incidence), as
// the vertex's Lambert irradiance b_i: the bounced irradiance from sun i is E_i b_i.
// Radiosity over the vertices, gathered with the vertex's rays of bakeVertexVisibility (the same
// directions, origins, maximum distance, falloff and alpha): each vertex's direct sunlight
// s_i = max(0, n . l_i) V_i (n its normal, l_i the world direction towards sun i, V_i 1 where a
// shadow ray towards l_i escapes); then kSunBouncePasses passes of
//   b_i(v) = 1/N sum over the rays that hit a front face of rho (s_i + b_i) at the hit,
// the hit's values interpolated from its triangle's vertices, rho the hit mesh's grey albedo
// (settings.albedo, required: one per mesh), b_i on the right the last pass's (0 in the first).
// The hits reflect rho / pi (s_i + b_i) E_i, and the cosine-distributed rays' pdf cos / pi makes
// pi / N times the sum of that the estimate of the irradiance they give: one bounce per pass. Components
// past the suns given are 0. Throws like bakeVertexVisibility, and Error("vertex visibility: ...")
// for more than kMaxSunBounceLights suns, a direction that is not unit length, or a missing albedo.
// `statistics`, when given, gets the rays traced (closest-hit and shadow) in bounceRays and the
// seconds in bounceSeconds.
inline constexpr int kMaxSunBounceLights = 4;
inline constexpr int kSunBouncePasses = 3;
std::vector<std::vector<glm::vec4>> bakeSunBounce(const std::vector<Mesh>& meshes,
                                                  std::span<const glm::vec3> sunDirections,
                                                  const VisibilitySettings& settings,
                                                  VisibilityStatistics* statistics = nullptr);

// The grey diffuse albedo of a mesh (VisibilitySettings::albedo): the Rec. 709 luminance of the
// Lambert lobe's colour, baseColor * (1 - metallic) (material.h), clamped to [0, 1]; 0 without a
// material. A base colour texture counts as its image's mean (sRGB decoded); vertex colours, the
// metallic texture and the specular layer's share are not read.
float meshDiffuseAlbedo(const Scene& scene, const Mesh& mesh);
// meshDiffuseAlbedo of every mesh of `scene`, in order.
std::vector<float> meshDiffuseAlbedos(const Scene& scene);

// Sets settings.materials and settings.textures to the scene's (its materials, SceneTextures of
// its textures), so masked texels let the bake's rays through.
void useSceneMaterials(VisibilitySettings& settings, const Scene& scene);

// The visibility rays bakeVertexVisibility traces (after one-ring rejection: the directions
// dropped after kMaxRedraws are left out), vertex by vertex in the bake's order, for benchmarks
// that replay them through Embree directly (to settings.maxDistance, or infinity when it is 0).
std::vector<Ray> vertexVisibilityRays(const std::vector<Mesh>& meshes, const VisibilitySettings& settings);

}  // namespace iblkit
