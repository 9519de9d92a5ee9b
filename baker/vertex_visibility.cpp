#include "baker/vertex_visibility.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <limits>
#include <string>

#include "core/error.h"
#include "core/frame.h"
#include "core/low_discrepancy.h"
#include "core/sampling.h"
#include "raytrace/alpha_filter.h"
#include "raytrace/ray_offset.h"
#include "raytrace/ray_scene.h"

namespace iblkit {

namespace {

// The largest ray count: the 24-bit sample coordinates keep nets of up to 2^24 points exact.
constexpr int kMaxRayCount = 1 << 24;
constexpr std::size_t kVertexGrain = 64;

// SplitMix64's finaliser (Steele, Lea and Flood 2014, "Fast Splittable Pseudorandom Number
// Generators"): every input bit affects every output bit, so neighbouring vertices get unrelated
// scrambles.
std::uint64_t mixBits(std::uint64_t x) {
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

std::uint32_t vertexSeed(std::uint32_t seed, std::size_t mesh, std::size_t vertex) {
  const std::uint64_t h = mixBits(mixBits((std::uint64_t(seed) << 32) | std::uint64_t(mesh)) ^ vertex);
  return static_cast<std::uint32_t>(h >> 32);
}

// The scramble of the draw-th re-draw: an independent copy of the point set. (Later points of the
// same sequence would not do: point i + k 2^m shares the leading m bits of point i's first
// coordinate, so a direction rejected near the horizon would be re-drawn near the horizon again.)
std::uint32_t redrawSeed(std::uint32_t seed, std::uint32_t draw) {
  return static_cast<std::uint32_t>(mixBits((std::uint64_t(draw) << 32) | seed) >> 32);
}

// The triangles around each vertex, in compressed rows: those of vertex v are entries
// start[v] .. start[v + 1]) of `triangles` (triangle index), `normals` (unit plane normal) and
// `areas`. Zero-area triangles have no plane and are left out.
struct OneRings {
  std::vector<std::size_t> start;
  std::vector<glm::vec3> normals;
  std::vector<std::uint32_t> triangles;
  std::vector<float> areas;
};

OneRings oneRings(const Mesh& mesh) {
  OneRings rings;
  const std::size_t triangles = mesh.triangleCount();
  std::vector<glm::vec3> faceNormals(triangles);
  std::vector<float> faceAreas(triangles);
  std::vector<bool> flat(triangles);
  for (std::size_t t = 0; t < triangles; ++t) {
    const glm::vec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
                    c = mesh.positions[mesh.indices[3 * t + 2]];
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float length = glm::length(n);
    flat[t] = !(length > 0.0f) || !std::isfinite(length);
    faceNormals[t] = flat[t] ? glm::vec3(0.0f) : n / length;
    faceAreas[t] = flat[t] ? 0.0f : 0.5f * length;
  }
  rings.start.assign(mesh.vertexCount() + 1, 0);
  for (std::size_t i = 0; i < mesh.indices.size(); ++i)
    if (!flat[i / 3]) ++rings.start[mesh.indices[i] + 1];
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) rings.start[v + 1] += rings.start[v];
  rings.normals.resize(rings.start.back());
  rings.triangles.resize(rings.start.back());
  rings.areas.resize(rings.start.back());
  std::vector<std::size_t> fill(rings.start.begin(), rings.start.end() - 1);
  for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
    if (flat[i / 3]) continue;
    const std::size_t slot = fill[mesh.indices[i]]++;
    rings.normals[slot] = faceNormals[i / 3];
    rings.triangles[slot] = static_cast<std::uint32_t>(i / 3);
    rings.areas[slot] = faceAreas[i / 3];
  }
  return rings;
}

// Where a vertex's rays start when they start at the vertex: the vertex moved towards its
// one-ring's centroid (the area-weighted mean of its triangles' centroids) by a sixteenth of
// the offset it then gets off the surface along its normal (offsetRayOrigin with
// surfaceErrorBound of the vertex and its one-ring's extent, ray_offset.h). Until
// 2026-12-07 both steps were fixed numbers of ulps of the vertex's own
// coordinates (16 and 256), which moved a bunny baked 3,000 units from the origin 0.06 units off
// its surface (its AO off by up to 0.14) and one shrunk to 1.8 mm by 1% of its size (AO off by
// up to 1: tests/baker/vertex_visibility_test, "...WhereTheMeshStandsOrItsSize"); the sixteenth
// is the ratio those two had. A vertex on a contact line (a flat-shaded box's bottom
// edge on the ground) lies on the other surface's plane too, and an upward ray from the vertex
// itself met that surface at t ~ 0: its AO and transfer were 0, and the engine's interpolation
// darkened the face (VisibilityPointSampling.AContactVertexSeesWhatItsFaceSees). The step takes
// the origin off that plane, into the surface the vertex stands for. It is that short because the
// centroid lies inside a convex surface: a step of 128 ulps of the largest coordinate put the
// origins of 93 of the bunny's vertices (ears, feet) under their neighbouring triangles (AO 0);
// at a sixteenth of the normal offset, per axis, no vertex of the bundled scenes changes its AO by
// more than 0.004. A vertex without a non-degenerate triangle starts at the vertex.
constexpr float kVertexOriginStep = 1.0f / 16.0f;

glm::vec3 vertexRayOrigin(const Mesh& mesh, const OneRings& rings, std::size_t vertex) {
  const glm::vec3& p = mesh.positions[vertex];
  glm::vec3 centroid(0.0f), lower = p, upper = p;
  float area = 0.0f;
  for (std::size_t k = rings.start[vertex]; k < rings.start[vertex + 1]; ++k) {
    const std::size_t t = rings.triangles[k];
    const glm::vec3 corners[3] = {mesh.positions[mesh.indices[3 * t]], mesh.positions[mesh.indices[3 * t + 1]],
                                  mesh.positions[mesh.indices[3 * t + 2]]};
    centroid += rings.areas[k] * ((corners[0] + corners[1] + corners[2]) / 3.0f);
    area += rings.areas[k];
    for (const glm::vec3& corner : corners) lower = glm::min(lower, corner), upper = glm::max(upper, corner);
  }
  const glm::vec3 error = surfaceErrorBound(p, upper - lower);
  const glm::vec3& normal = mesh.normals[vertex];
  const glm::vec3 towards = area > 0.0f && std::isfinite(area) ? centroid / area - p : glm::vec3(0.0f);
  const float length = glm::length(towards);
  const glm::vec3 stepped = length > 0.0f && std::isfinite(length)
                                ? p + (kVertexOriginStep * offsetDistance(error, normal) / length) * towards
                                : p;
  return offsetRayOrigin(stepped, error, normal);
}

bool aboveOneRing(const glm::vec3& direction, const glm::vec3* normals, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i)
    if (!(glm::dot(direction, normals[i]) > 0.0f)) return false;
  return true;
}

// Everything needed to draw the rays of one vertex.
class VertexSampler {
 public:
  VertexSampler(const Mesh& mesh, const OneRings& rings, std::size_t vertex, std::uint32_t seed, bool area)
      : mesh_(mesh),
        vertex_(static_cast<std::uint32_t>(vertex)),
        begin_(rings.start[vertex]),
        size_(rings.start[vertex + 1] - rings.start[vertex]),
        rings_(rings),
        seed_(seed),
        frame_(Frame::fromZ(mesh.normals[vertex])),
        origin_(vertexRayOrigin(mesh, rings, vertex)) {
    for (std::size_t k = 0; k < size_; ++k) ringArea_ += rings.areas[begin_ + k];
    area_ = area && size_ > 0 && ringArea_ > 0.0f && std::isfinite(ringArea_);
  }

  // The i-th ray; false when every draw was rejected (it then counts as occluded). Adds the
  // rejected draws to `rejected`.
  bool ray(std::uint32_t i, Ray& ray, std::size_t& rejected) const {
    if (!area_) {
      ray.origin = origin_;
      return direction(i, frame_, rings_.normals.data() + begin_, size_, ray.direction, rejected);
    }
    // The origin: a point of the vertex's barycentric dual cell. A hash of (seed, i) gives its
    // random numbers (the Sobol points stay with the directions: index i of another scramble
    // would tie the origin's stratum to the direction's).
    const std::uint64_t h = mixBits((std::uint64_t(redrawSeed(seed_, kMaxRedraws + 1)) << 32) | i);
    float target = float(h >> 40) * 0x1p-24f * ringArea_;
    std::size_t k = 0;
    while (k + 1 < size_ && target >= rings_.areas[begin_ + k]) target -= rings_.areas[begin_ + k++];
    const float reuse = std::clamp(target / rings_.areas[begin_ + k], 0.0f, 0x1.fffffep-1f);
    const glm::vec2 b = sampleUniformTriangle({reuse, float((h >> 16) & 0xffffffu) * 0x1p-24f});
    float w[3] = {b.x, b.y, 1.0f - b.x - b.y};
    std::sort(w, w + 3);  // the vertex takes the largest coordinate, the other two either order
    const std::uint32_t t = rings_.triangles[begin_ + k];
    std::uint32_t corner[3] = {mesh_.indices[3 * std::size_t(t)], mesh_.indices[3 * std::size_t(t) + 1],
                               mesh_.indices[3 * std::size_t(t) + 2]};
    while (corner[0] != vertex_) std::rotate(corner, corner + 1, corner + 3);
    if (h & 1u) std::swap(corner[1], corner[2]);
    const glm::vec3 &p0 = mesh_.positions[corner[0]], &p1 = mesh_.positions[corner[1]],
                    &p2 = mesh_.positions[corner[2]];
    const glm::vec3 point = trianglePoint(p0, p1, p2, w[1], w[0]);
    const glm::vec3 faceNormal = rings_.normals[begin_ + k];
    glm::vec3 normal =
        w[2] * mesh_.normals[corner[0]] + w[1] * mesh_.normals[corner[1]] + w[0] * mesh_.normals[corner[2]];
    const float length = glm::length(normal);
    normal = length > 0.0f && std::isfinite(length) ? normal / length : faceNormal;
    ray.origin = offsetRayOrigin(point, surfaceErrorBound(point, triangleExtent(p0, p1, p2)), faceNormal);
    return direction(i, Frame::fromZ(normal), &faceNormal, 1, ray.direction, rejected);
  }

 private:
  // Direction i about `frame`, re-drawn while below one of the planes.
  bool direction(std::uint32_t i, const Frame& frame, const glm::vec3* planes, std::size_t planeCount,
                 glm::vec3& direction, std::size_t& rejected) const {
    for (std::uint32_t draw = 0; draw <= kMaxRedraws; ++draw) {
      direction = frame.toWorld(
          sampleCosineHemisphere(owenScrambledSobol02(i, draw == 0 ? seed_ : redrawSeed(seed_, draw))));
      if (aboveOneRing(direction, planes, planeCount)) return true;
      ++rejected;
    }
    return false;
  }

  const Mesh& mesh_;
  std::uint32_t vertex_;
  std::size_t begin_, size_;
  const OneRings& rings_;
  std::uint32_t seed_;
  bool area_ = false;
  float ringArea_ = 0.0f;
  Frame frame_;
  glm::vec3 origin_;
};

float rayLength(const VisibilitySettings& settings) {
  return settings.maxDistance > 0.0f ? settings.maxDistance : std::numeric_limits<float>::infinity();
}

// How much a ray is blocked, in [0, 1] (1 - visibility), and what it hit when `hit` is given.
// rtcOccluded1 alone when neither the hit nor the distance (falloff) is needed.
float rayOcclusion(const RayScene& scene, const Ray& ray, float tmax, float falloff, Hit* hit) {
  if (falloff <= 0.0f && !hit) return scene.occluded(ray.origin, ray.direction, 0.0f, tmax) ? 1.0f : 0.0f;
  const Hit h = scene.intersect(ray, 0.0f, tmax);
  if (hit) *hit = h;
  if (!h.hit) return 0.0f;
  if (falloff <= 0.0f) return 1.0f;
  return std::pow(std::clamp(1.0f - h.t / tmax, 0.0f, 1.0f), falloff);
}

struct VertexResult {
  float ambientOcclusion;
  glm::vec3 bentNormal;
  float bentNormalLength;
  ShBasis9 transfer;
  std::size_t rays, rejected;
};

VertexResult vertexVisibility(const RayScene& scene, const VertexSampler& sampler, const glm::vec3& normal,
                              const VisibilitySettings& settings) {
  const float tmax = rayLength(settings);
  const auto count = static_cast<std::uint32_t>(settings.rayCount);
  VertexResult result{};
  glm::vec3 escapedSum(0.0f);
  float escaped = 0.0f;
  Ray ray;
  for (std::uint32_t i = 0; i < count; ++i) {
    if (!sampler.ray(i, ray, result.rejected)) continue;
    ++result.rays;
    const float visible = 1.0f - rayOcclusion(scene, ray, tmax, settings.falloff, nullptr);
    if (visible <= 0.0f) continue;
    escaped += visible;
    escapedSum += visible * ray.direction;
    const ShBasis9 basis = shBasis9(ray.direction);
    for (int k = 0; k < kShCoefficients; ++k) result.transfer[k] += visible * basis[k];
  }
  result.ambientOcclusion = escaped / float(count);
  const float transferWeight = glm::pi<float>() / float(count);
  for (float& t : result.transfer) t *= transferWeight;
  const float sumLength = glm::length(escapedSum);
  result.bentNormal = sumLength > 0.0f ? escapedSum / sumLength : normal;
  result.bentNormalLength = escaped > 0.0f ? sumLength / escaped : 0.0f;
  return result;
}

// Calls gather(blocked, mesh, corner, w) for each of a vertex's rays that hits a front face
// (closest hit): how much the ray is blocked (below 1 with a falloff), the hit mesh's index, its
// triangle's three vertex indices and the hit's barycentric weights for them. Counts the rays.
template <class Gather>
void forEachFrontHit(const RayScene& scene, const VertexSampler& sampler, const std::vector<Mesh>& meshes,
                     const VisibilitySettings& settings, std::size_t& rays, const Gather& gather) {
  const float tmax = rayLength(settings);
  const auto count = static_cast<std::uint32_t>(settings.rayCount);
  Ray ray;
  std::size_t rejected = 0;
  for (std::uint32_t i = 0; i < count; ++i) {
    if (!sampler.ray(i, ray, rejected)) continue;
    ++rays;
    Hit hit;
    const float blocked = rayOcclusion(scene, ray, tmax, settings.falloff, &hit);
    if (blocked <= 0.0f || !(glm::dot(ray.direction, hit.geometricNormal) < 0.0f)) continue;
    const std::uint32_t* corner = &meshes[hit.geomId].indices[3 * std::size_t(hit.primId)];
    const float w[3] = {1.0f - hit.barycentrics.x - hit.barycentrics.y, hit.barycentrics.x,
                        hit.barycentrics.y};
    gather(blocked, hit.geomId, corner, w);
  }
}

// One bounce of interreflected transfer at a vertex (VisibilitySettings::bounces): 1 / N times the
// sum over its blocked rays of the hit mesh's albedo times the previous bounce's transfer at the
// front-face hit (weighted by how much the ray is blocked when there is a falloff). The transfer is
// of irradiance (the shader multiplies by the vertex's own albedo / pi), so what a hit sends back
// is its irradiance times its own albedo / pi, and the cosine-distributed rays' pi cancels that pi:
// the reflector's albedo, as the suns' bounce takes it (vertexSunBounce). Until 2026-12-07 the
// receiving vertex's albedo stood there: the same only where the two meshes' albedos are equal.
ShBasis9 vertexBounce(const RayScene& scene, const VertexSampler& sampler,
                      const std::vector<std::vector<ShBasis9>>& previous, const std::vector<Mesh>& meshes,
                      const VisibilitySettings& settings, std::size_t& rays) {
  ShBasis9 gathered{};
  forEachFrontHit(scene, sampler, meshes, settings, rays,
                  [&](float blocked, unsigned mesh, const std::uint32_t* corner, const float* w) {
                    const float reflected = blocked * settings.albedo[mesh];
                    for (int c = 0; c < 3; ++c) {
                      const ShBasis9& t = previous[mesh][corner[c]];
                      for (int k = 0; k < kShCoefficients; ++k) gathered[k] += reflected * w[c] * t[k];
                    }
                  });
  for (float& t : gathered) t /= float(settings.rayCount);
  return gathered;
}

// One pass of the suns' bounce at a vertex (bakeSunBounce): 1/N times the sum over its rays that
// hit a front face of the hit mesh's albedo times `lit` interpolated at the hit (per sun: the
// direct sunlight and the last pass's bounce there, per unit of the sun's irradiance).
glm::vec4 vertexSunBounce(const RayScene& scene, const VertexSampler& sampler,
                          const std::vector<std::vector<glm::vec4>>& lit, const std::vector<Mesh>& meshes,
                          const VisibilitySettings& settings, std::size_t& rays) {
  glm::vec4 gathered(0.0f);
  forEachFrontHit(scene, sampler, meshes, settings, rays,
                  [&](float blocked, unsigned mesh, const std::uint32_t* corner, const float* w) {
                    const std::vector<glm::vec4>& values = lit[mesh];
                    gathered += blocked * settings.albedo[mesh] *
                                (w[0] * values[corner[0]] + w[1] * values[corner[1]] + w[2] * values[corner[2]]);
                  });
  return gathered / float(settings.rayCount);
}

// The direct sunlight at a vertex per unit of each sun's irradiance: max(0, n . l) where a shadow
// ray from the vertex (vertexRayOrigin: into its one-ring and off its surface) towards l escapes.
glm::vec4 vertexSunlight(const RayScene& scene, const Mesh& mesh, const OneRings& rings, std::size_t vertex,
                         std::span<const glm::vec3> suns, std::size_t& rays) {
  const glm::vec3& normal = mesh.normals[vertex];
  const glm::vec3 origin = vertexRayOrigin(mesh, rings, vertex);
  glm::vec4 lit(0.0f);
  for (std::size_t s = 0; s < suns.size(); ++s) {
    const float cosine = glm::dot(normal, suns[s]);
    if (!(cosine > 0.0f)) continue;
    ++rays;
    if (!scene.occluded(origin, suns[s], 0.0f, std::numeric_limits<float>::infinity())) lit[int(s)] = cosine;
  }
  return lit;
}

// settings.albedo: one per mesh, each in [0, 1]; `who` names what needs them in the message.
void checkAlbedo(const std::vector<Mesh>& meshes, const VisibilitySettings& settings, const std::string& who) {
  if (settings.albedo.size() != meshes.size())
    fail("vertex visibility", who + " one albedo per mesh: got " + std::to_string(settings.albedo.size()) + " for " +
                                  std::to_string(meshes.size()) + " meshes");
  for (float a : settings.albedo)
    if (!(a >= 0.0f && a <= 1.0f)) fail("vertex visibility", "albedo " + std::to_string(a) + " is not in [0, 1]");
}

void checkInput(const std::vector<Mesh>& meshes, const VisibilitySettings& settings) {
  if (settings.rayCount < 1 || settings.rayCount > kMaxRayCount)
    fail("vertex visibility",
         "ray count " + std::to_string(settings.rayCount) + " is not in 1.." + std::to_string(kMaxRayCount));
  if (!(settings.maxDistance >= 0.0f) || !std::isfinite(settings.maxDistance))
    fail("vertex visibility", "maximum distance must be finite and >= 0 (0 = infinite)");
  if (!(settings.falloff >= 0.0f) || !std::isfinite(settings.falloff))
    fail("vertex visibility", "falloff exponent must be finite and >= 0");
  if (settings.falloff > 0.0f && settings.maxDistance <= 0.0f)
    fail("vertex visibility", "a falloff needs a maximum distance (--ao-distance > 0)");
  if (settings.bounces < 0) fail("vertex visibility", "bounces must be >= 0");
  if (settings.bounces > 0) checkAlbedo(meshes, settings, "bounces need");
  for (std::size_t m = 0; m < meshes.size(); ++m)
    if (meshes[m].normals.size() != meshes[m].positions.size())
      fail("vertex visibility", "mesh " + std::to_string(m) + " has " +
                                    std::to_string(meshes[m].normals.size()) + " normals for " +
                                    std::to_string(meshes[m].positions.size()) + " vertices");
}

// Calls visit(m, v, sampler, rays) for every vertex v of every mesh m, in parallel, with the
// vertex's ray sampler; adds the rays the visits count to `rays` and calls done(vertices) after
// each range of vertices.
template <class Visit, class Done>
void forEachVertexSampler(const std::vector<Mesh>& meshes, const std::vector<OneRings>& rings,
                          const VisibilitySettings& settings, std::atomic<std::size_t>& rays, const Visit& visit,
                          const Done& done) {
  tbb::parallel_for(std::size_t(0), meshes.size(), [&](std::size_t m) {
    const Mesh& mesh = meshes[m];
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.vertexCount(), kVertexGrain),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        std::size_t rangeRays = 0;
                        for (std::size_t v = range.begin(); v != range.end(); ++v) {
                          const VertexSampler sampler(mesh, rings[m], v, vertexSeed(settings.seed, m, v),
                                                      settings.areaSampling);
                          visit(m, v, sampler, rangeRays);
                        }
                        rays += rangeRays;
                        done(range.size());
                      });
  });
}

// The visibility bake's Embree scene: every mesh, with the materials' alpha filter when some
// material can drop a point.
void buildScene(RayScene& scene, const std::vector<Mesh>& meshes, const VisibilitySettings& settings) {
  for (const Mesh& mesh : meshes) scene.addTriangleMesh(mesh.positions, mesh.indices);
  if (!settings.materials.empty()) {
    std::vector<const Mesh*> geometryMeshes;
    for (const Mesh& mesh : meshes) geometryMeshes.push_back(&mesh);
    auto filter = std::make_shared<AlphaFilter>(std::move(geometryMeshes), settings.materials, settings.textures,
                                                kAllTextureSlots, /*cameraRays=*/false);
    bool anyTest = false;
    for (unsigned g = 0; g < filter->geometryCount(); ++g) anyTest = anyTest || filter->needs(g) != 0;
    if (anyTest) scene.setAlphaFilter(std::move(filter));
  }
  scene.commit();
}

// The mean linear RGB of a texture's image (sRGB decoded), or 1 when there is none to read.
glm::vec3 meanTextureColor(const Scene& scene, const TextureRef& ref) {
  if (!ref.present() || std::size_t(ref.texture) >= scene.textures.size()) return glm::vec3(1.0f);
  const int image = scene.textures[std::size_t(ref.texture)].image;
  if (image < 0 || std::size_t(image) >= scene.images.size()) return glm::vec3(1.0f);
  const std::vector<std::uint8_t>& rgba = scene.images[std::size_t(image)].rgba;
  const std::size_t texels = rgba.size() / 4;
  if (texels == 0) return glm::vec3(1.0f);
  glm::dvec3 sum(0.0);
  for (std::size_t i = 0; i < texels; ++i)
    for (int c = 0; c < 3; ++c) sum[c] += srgbToLinear(rgba[4 * i + std::size_t(c)]);
  return glm::vec3(sum / double(texels));
}

double secondsSince(std::chrono::steady_clock::time_point& last) {
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - last).count();
  last = now;
  return seconds;
}

}  // namespace


std::vector<MeshVisibility> bakeVertexVisibility(const std::vector<Mesh>& meshes,
                                                 const VisibilitySettings& settings,
                                                 VisibilityStatistics* statistics) {
  checkInput(meshes, settings);
  auto clock = std::chrono::steady_clock::now();
  VisibilityStatistics counts;
  RayScene scene;
  buildScene(scene, meshes, settings);
  counts.buildSeconds = secondsSince(clock);

  std::size_t totalVertices = 0;
  for (const Mesh& mesh : meshes) totalVertices += mesh.vertexCount();
  const std::size_t totalWork = totalVertices * std::size_t(1 + settings.bounces);
  std::vector<MeshVisibility> results(meshes.size());
  std::vector<OneRings> rings(meshes.size());
  std::atomic<std::size_t> done{0}, rays{0}, rejected{0}, bounceRays{0};
  const auto report = [&](std::size_t vertices) {
    const std::size_t finished = done += vertices;
    if (settings.progress) settings.progress(finished, totalWork);
  };

  tbb::parallel_for(std::size_t(0), meshes.size(), [&](std::size_t m) {
    const Mesh& mesh = meshes[m];
    rings[m] = oneRings(mesh);
    MeshVisibility& out = results[m];
    out.ambientOcclusion.resize(mesh.vertexCount());
    out.bentNormals.resize(mesh.vertexCount());
    out.bentNormalLengths.resize(mesh.vertexCount());
    out.transfer.resize(mesh.vertexCount());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.vertexCount(), kVertexGrain),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        std::size_t rangeRays = 0, rangeRejected = 0;
                        for (std::size_t v = range.begin(); v != range.end(); ++v) {
                          const VertexSampler sampler(mesh, rings[m], v, vertexSeed(settings.seed, m, v),
                                                      settings.areaSampling);
                          const VertexResult r = vertexVisibility(scene, sampler, mesh.normals[v], settings);
                          out.ambientOcclusion[v] = r.ambientOcclusion;
                          out.bentNormals[v] = r.bentNormal;
                          out.bentNormalLengths[v] = r.bentNormalLength;
                          out.transfer[v] = r.transfer;
                          rangeRays += r.rays;
                          rangeRejected += r.rejected;
                        }
                        rays += rangeRays;
                        rejected += rangeRejected;
                        report(range.size());
                      });
  });
  counts.raySeconds = secondsSince(clock);

  // Interreflected transfer: `previous` holds bounce b - 1 (the shadowed transfer for b = 1).
  std::vector<std::vector<ShBasis9>> previous;
  if (settings.bounces > 0)
    for (const MeshVisibility& r : results) previous.push_back(r.transfer);
  for (int bounce = 1; bounce <= settings.bounces; ++bounce) {
    std::vector<std::vector<ShBasis9>> next(meshes.size());
    for (std::size_t m = 0; m < meshes.size(); ++m) next[m].resize(meshes[m].vertexCount());
    forEachVertexSampler(
        meshes, rings, settings, bounceRays,
        [&](std::size_t m, std::size_t v, const VertexSampler& sampler, std::size_t& vertexRays) {
          next[m][v] = vertexBounce(scene, sampler, previous, meshes, settings, vertexRays);
        },
        report);
    for (std::size_t m = 0; m < meshes.size(); ++m)
      for (std::size_t v = 0; v < next[m].size(); ++v)
        for (int k = 0; k < kShCoefficients; ++k) results[m].transfer[v][k] += next[m][v][k];
    previous = std::move(next);
  }
  counts.bounceSeconds = secondsSince(clock);

  counts.vertices = totalVertices;
  counts.rays = rays.load();
  counts.rejected = rejected.load();
  counts.bounceRays = bounceRays.load();
  if (statistics) *statistics = counts;
  return results;
}

std::vector<std::vector<glm::vec4>> bakeSunBounce(const std::vector<Mesh>& meshes,
                                                  std::span<const glm::vec3> sunDirections,
                                                  const VisibilitySettings& settings,
                                                  VisibilityStatistics* statistics) {
  checkInput(meshes, settings);
  if (sunDirections.size() > std::size_t(kMaxSunBounceLights))
    fail("vertex visibility", std::to_string(sunDirections.size()) + " suns for the bounce, at most " +
                                  std::to_string(kMaxSunBounceLights));
  for (const glm::vec3& l : sunDirections)
    if (!(std::abs(glm::length(l) - 1.0f) < 1e-3f))
      fail("vertex visibility", "a sun direction for the bounce is not unit length");
  checkAlbedo(meshes, settings, "the sun bounce needs");
  auto clock = std::chrono::steady_clock::now();
  std::vector<std::vector<glm::vec4>> results(meshes.size()), lit(meshes.size());
  for (std::size_t m = 0; m < meshes.size(); ++m) results[m].assign(meshes[m].vertexCount(), glm::vec4(0.0f));
  std::atomic<std::size_t> rays{0};
  if (!sunDirections.empty()) {
    RayScene scene;
    buildScene(scene, meshes, settings);
    std::vector<OneRings> rings(meshes.size());
    // Each vertex's direct sunlight, then the bounces pass by pass: pass k gathers what the hits
    // reflect of the sunlight and of pass k - 1's bounce there.
    tbb::parallel_for(std::size_t(0), meshes.size(), [&](std::size_t m) {
      rings[m] = oneRings(meshes[m]);
      lit[m].resize(meshes[m].vertexCount());
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, meshes[m].vertexCount(), kVertexGrain),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          std::size_t rangeRays = 0;
                          for (std::size_t v = range.begin(); v != range.end(); ++v)
                            lit[m][v] = vertexSunlight(scene, meshes[m], rings[m], v, sunDirections, rangeRays);
                          rays += rangeRays;
                        });
    });
    for (int pass = 0; pass < kSunBouncePasses; ++pass) {
      std::vector<std::vector<glm::vec4>> next(meshes.size());
      for (std::size_t m = 0; m < meshes.size(); ++m) next[m].resize(meshes[m].vertexCount());
      forEachVertexSampler(
          meshes, rings, settings, rays,
          [&](std::size_t m, std::size_t v, const VertexSampler& sampler, std::size_t& vertexRays) {
            next[m][v] = vertexSunBounce(scene, sampler, lit, meshes, settings, vertexRays);
          },
          [](std::size_t) {});
      // The sources of the next pass: sunlight plus this pass's bounce.
      for (std::size_t m = 0; m < meshes.size(); ++m)
        for (std::size_t v = 0; v < next[m].size(); ++v) {
          lit[m][v] += next[m][v] - results[m][v];
          results[m][v] = next[m][v];
        }
    }
  }
  if (statistics) {
    statistics->bounceRays = rays.load();
    statistics->bounceSeconds = secondsSince(clock);
  }
  return results;
}


float meshDiffuseAlbedo(const Scene& scene, const Mesh& mesh) {
  if (mesh.material < 0 || std::size_t(mesh.material) >= scene.materials.size()) return 0.0f;
  const Material& material = scene.materials[std::size_t(mesh.material)];
  const glm::vec3 diffuse =
      material.baseColor * meanTextureColor(scene, material.baseColorTexture) * (1.0f - material.metallic);
  return std::clamp(glm::dot(diffuse, glm::vec3(0.2126f, 0.7152f, 0.0722f)), 0.0f, 1.0f);
}

std::vector<float> meshDiffuseAlbedos(const Scene& scene) {
  std::vector<float> albedo;
  for (const Mesh& mesh : scene.meshes) albedo.push_back(meshDiffuseAlbedo(scene, mesh));
  return albedo;
}

void useSceneMaterials(VisibilitySettings& settings, const Scene& scene) {
  settings.materials = scene.materials;
  settings.textures = std::make_shared<SceneTextures>(scene.textures, scene.images, scene.materials);
}

std::vector<Ray> vertexVisibilityRays(const std::vector<Mesh>& meshes, const VisibilitySettings& settings) {
  checkInput(meshes, settings);
  std::vector<Ray> rays;
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const OneRings rings = oneRings(meshes[m]);
    for (std::size_t v = 0; v < meshes[m].vertexCount(); ++v) {
      const VertexSampler sampler(meshes[m], rings, v, vertexSeed(settings.seed, m, v),
                                  settings.areaSampling);
      std::size_t rejected = 0;
      Ray ray;
      for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(settings.rayCount); ++i)
        if (sampler.ray(i, ray, rejected)) rays.push_back(ray);
    }
  }
  return rays;
}

}  // namespace iblkit
