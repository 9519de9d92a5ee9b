#include "baker/vertex_visibility.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <limits>
#include <string>

#include "engine/core/error.h"
#include "engine/core/frame.h"
#include "engine/core/low_discrepancy.h"
#include "engine/core/sampling.h"
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

// The unit normals of the triangles around each vertex, in compressed rows: the normals of
// vertex v are normals[start[v] .. start[v + 1]). Zero-area triangles have no plane and are left
// out.
struct OneRings {
  std::vector<std::size_t> start;
  std::vector<glm::vec3> normals;
};

OneRings oneRings(const Mesh& mesh) {
  OneRings rings;
  const std::size_t triangles = mesh.triangleCount();
  std::vector<glm::vec3> faceNormals(triangles);
  std::vector<bool> flat(triangles);
  for (std::size_t t = 0; t < triangles; ++t) {
    const glm::vec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
                    c = mesh.positions[mesh.indices[3 * t + 2]];
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float length = glm::length(n);
    flat[t] = !(length > 0.0f) || !std::isfinite(length);
    faceNormals[t] = flat[t] ? glm::vec3(0.0f) : n / length;
  }
  rings.start.assign(mesh.vertexCount() + 1, 0);
  for (std::size_t i = 0; i < mesh.indices.size(); ++i)
    if (!flat[i / 3]) ++rings.start[mesh.indices[i] + 1];
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) rings.start[v + 1] += rings.start[v];
  rings.normals.resize(rings.start.back());
  std::vector<std::size_t> fill(rings.start.begin(), rings.start.end() - 1);
  for (std::size_t i = 0; i < mesh.indices.size(); ++i)
    if (!flat[i / 3]) rings.normals[fill[mesh.indices[i]]++] = faceNormals[i / 3];
  return rings;
}

bool aboveOneRing(const glm::vec3& direction, const glm::vec3* normals, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i)
    if (!(glm::dot(direction, normals[i]) > 0.0f)) return false;
  return true;
}

struct VertexResult {
  float ambientOcclusion;
  glm::vec3 bentNormal;
  float bentNormalLength;
  ShBasis9 transfer;
  std::size_t rays, rejected;
};

VertexResult vertexVisibility(const RayScene& scene, const glm::vec3& position, const glm::vec3& normal,
                              const glm::vec3* ringNormals, std::size_t ringSize, std::uint32_t seed,
                              const VisibilitySettings& settings) {
  const float tmax =
      settings.maxDistance > 0.0f ? settings.maxDistance : std::numeric_limits<float>::infinity();
  const auto count = static_cast<std::uint32_t>(settings.rayCount);
  const Frame frame = Frame::fromZ(normal);
  const glm::vec3 origin = offsetRayOrigin(position, normal);

  VertexResult result{};
  glm::vec3 escapedSum(0.0f);
  std::uint32_t escaped = 0;
  for (std::uint32_t i = 0; i < count; ++i) {
    glm::vec3 direction(0.0f);
    bool valid = false;
    for (std::uint32_t draw = 0; draw <= kMaxRedraws && !valid; ++draw) {
      direction = frame.toWorld(
          sampleCosineHemisphere(owenScrambledSobol02(i, draw == 0 ? seed : redrawSeed(seed, draw))));
      valid = aboveOneRing(direction, ringNormals, ringSize);
      result.rejected += valid ? 0 : 1;
    }
    if (!valid) continue;
    ++result.rays;
    if (scene.occluded(origin, direction, 0.0f, tmax)) continue;
    ++escaped;
    escapedSum += direction;
    const ShBasis9 basis = shBasis9(direction);
    for (int k = 0; k < kShCoefficients; ++k) result.transfer[k] += basis[k];
  }
  result.ambientOcclusion = float(escaped) / float(count);
  const float transferWeight = glm::pi<float>() / float(count);
  for (float& t : result.transfer) t *= transferWeight;
  const float sumLength = glm::length(escapedSum);
  result.bentNormal = sumLength > 0.0f ? escapedSum / sumLength : normal;
  result.bentNormalLength = escaped > 0 ? sumLength / float(escaped) : 0.0f;
  return result;
}

void checkInput(const std::vector<Mesh>& meshes, const VisibilitySettings& settings) {
  if (settings.rayCount < 1 || settings.rayCount > kMaxRayCount)
    fail("vertex visibility",
         "ray count " + std::to_string(settings.rayCount) + " is not in 1.." + std::to_string(kMaxRayCount));
  if (!(settings.maxDistance >= 0.0f) || !std::isfinite(settings.maxDistance))
    fail("vertex visibility", "maximum distance must be finite and >= 0 (0 = infinite)");
  for (std::size_t m = 0; m < meshes.size(); ++m)
    if (meshes[m].normals.size() != meshes[m].positions.size())
      fail("vertex visibility", "mesh " + std::to_string(m) + " has " +
                                    std::to_string(meshes[m].normals.size()) + " normals for " +
                                    std::to_string(meshes[m].positions.size()) + " vertices");
}

}  // namespace

std::vector<MeshVisibility> bakeVertexVisibility(const std::vector<Mesh>& meshes,
                                                 const VisibilitySettings& settings,
                                                 VisibilityStatistics* statistics) {
  checkInput(meshes, settings);
  RayScene scene;
  for (const Mesh& mesh : meshes) scene.addTriangleMesh(mesh.positions, mesh.indices);
  scene.commit();

  std::size_t totalVertices = 0;
  for (const Mesh& mesh : meshes) totalVertices += mesh.vertexCount();
  std::vector<MeshVisibility> results(meshes.size());
  std::atomic<std::size_t> done{0}, rays{0}, rejected{0};

  tbb::parallel_for(std::size_t(0), meshes.size(), [&](std::size_t m) {
    const Mesh& mesh = meshes[m];
    const OneRings rings = oneRings(mesh);
    MeshVisibility& out = results[m];
    out.ambientOcclusion.resize(mesh.vertexCount());
    out.bentNormals.resize(mesh.vertexCount());
    out.bentNormalLengths.resize(mesh.vertexCount());
    out.transfer.resize(mesh.vertexCount());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.vertexCount(), kVertexGrain),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        std::size_t rangeRays = 0, rangeRejected = 0;
                        for (std::size_t v = range.begin(); v != range.end(); ++v) {
                          const VertexResult r = vertexVisibility(scene, mesh.positions[v], mesh.normals[v],
                                                                  rings.normals.data() + rings.start[v],
                                                                  rings.start[v + 1] - rings.start[v],
                                                                  vertexSeed(settings.seed, m, v), settings);
                          out.ambientOcclusion[v] = r.ambientOcclusion;
                          out.bentNormals[v] = r.bentNormal;
                          out.bentNormalLengths[v] = r.bentNormalLength;
                          out.transfer[v] = r.transfer;
                          rangeRays += r.rays;
                          rangeRejected += r.rejected;
                        }
                        rays += rangeRays;
                        rejected += rangeRejected;
                        const std::size_t finished = done += range.size();
                        if (settings.progress) settings.progress(finished, totalVertices);
                      });
  });

  if (statistics) *statistics = {totalVertices, rays.load(), rejected.load()};
  return results;
}

}  // namespace iblkit
