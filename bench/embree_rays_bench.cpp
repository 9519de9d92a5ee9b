// Raw Embree throughput: rays per second of rtcOccluded1 and rtcIntersect1 on a fixed scene, the
// rate the reference path tracer and the baker compare their own ray rates against
// (docs/benchmarks.md, "Raw Embree throughput").
//
// Scene: a UV sphere of about 100k triangles resting on a ground plane. Two ray loads of 2^16 rays
// each, generated once with a fixed seed:
//   ao      incoherent: origins on the sphere and the ground near it (offset with
//           offsetRayOrigin), cosine-distributed directions about the geometric normal, unbounded
//           length: the ambient-occlusion / environment-visibility rays of a bake;
//   camera  coherent: one ray per pixel of a 256 x 256 pinhole camera, in scanline order.
// Each load is traced through Embree's C API directly ("raw") on 1 and 2 threads (TBB
// parallel_reduce in a task_arena of that size), and through RayScene on 1 thread to show the
// wrapper's overhead. items_per_second is rays per second.

#include <benchmark/benchmark.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include "bench/raw_embree.h"
#include "core/procedural_mesh.h"
#include "raytrace/ray_offset.h"
#include "raytrace/ray_scene.h"

namespace iblkit {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr int kCameraResolution = 256;
constexpr std::size_t kRayCount = kCameraResolution * kCameraResolution;

struct BenchScene {
  ProceduralMesh sphere = uvSphere(glm::vec3(0.0f, 1.0f, 0.0f), 1.0f, 160, 320);  // 101,760 triangles
  ProceduralMesh ground = plane(glm::vec3(0.0f), 20.0f);
  RayScene scene;
  std::vector<Ray> aoRays, cameraRays;
};

// A direction cosine-distributed about the unit normal n: n plus a uniform point on the unit
// sphere, normalised (directions to uniform points on the unit sphere tangent to the surface at
// the origin have the cosine density; Shirley, "Ray Tracing in One Weekend", "True Lambertian
// Reflection").
glm::vec3 cosineDirection(glm::vec3 n, std::mt19937& rng) {
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  const float z = 2.0f * uniform(rng) - 1.0f, phi = 6.2831853f * uniform(rng);
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const glm::vec3 d = n + glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
  const float length = glm::length(d);
  return length > 1e-6f ? d / length : n;
}

std::vector<Ray> ambientOcclusionRays(const ProceduralMesh& sphere, std::mt19937& rng) {
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  std::uniform_int_distribution<std::size_t> triangle(0, sphere.indices.size() / 3 - 1);
  std::vector<Ray> rays(kRayCount);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    glm::vec3 p, n;
    if (i % 2 == 0) {  // a uniform point in a random sphere triangle
      const std::size_t t = triangle(rng);
      const glm::vec3 a = sphere.positions[sphere.indices[3 * t]],
                      b = sphere.positions[sphere.indices[3 * t + 1]],
                      c = sphere.positions[sphere.indices[3 * t + 2]];
      const float s = std::sqrt(uniform(rng)), u = uniform(rng);
      p = (1.0f - s) * a + s * (1.0f - u) * b + s * u * c;
      n = glm::normalize(glm::cross(b - a, c - a));
    } else {  // the ground within 2 radii of the sphere's contact point, where the sphere occludes
      p = glm::vec3(4.0f * uniform(rng) - 2.0f, 0.0f, 4.0f * uniform(rng) - 2.0f);
      n = glm::vec3(0.0f, 1.0f, 0.0f);
    }
    rays[i] = {offsetRayOrigin(p, n), cosineDirection(n, rng)};
  }
  return rays;
}

std::vector<Ray> cameraRays() {
  const glm::vec3 eye(0.0f, 1.5f, 4.0f), target(0.0f, 0.8f, 0.0f);
  const glm::vec3 forward = glm::normalize(target - eye);
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
  const glm::vec3 up = glm::cross(right, forward);
  const float halfHeight = std::tan(0.5f * 0.7854f);  // 45 degree vertical field of view
  std::vector<Ray> rays;
  rays.reserve(kRayCount);
  for (int y = 0; y < kCameraResolution; ++y)
    for (int x = 0; x < kCameraResolution; ++x) {
      const float sx = (2.0f * (float(x) + 0.5f) / kCameraResolution - 1.0f) * halfHeight;
      const float sy = (1.0f - 2.0f * (float(y) + 0.5f) / kCameraResolution) * halfHeight;
      rays.push_back({eye, glm::normalize(forward + sx * right + sy * up)});
    }
  return rays;
}

const BenchScene& benchScene() {
  static const BenchScene scene = [] {
    BenchScene s;
    s.scene.addTriangleMesh(s.sphere.positions, s.sphere.indices);
    s.scene.addTriangleMesh(s.ground.positions, s.ground.indices);
    s.scene.commit();
    std::mt19937 rng(20240611);
    s.aoRays = ambientOcclusionRays(s.sphere, rng);
    s.cameraRays = cameraRays();
    return s;
  }();
  return scene;
}

enum class Load { kAmbientOcclusion, kCamera };
enum class Query { kRawOccluded, kRawIntersect, kRaySceneOccluded, kRaySceneIntersect };

// Traces every ray of the load once per iteration on state.range(0) threads; counts hits so the
// work cannot be optimised away and reports the hit fraction as a sanity check of the load.
template <class Trace>
void traceLoad(benchmark::State& state, const std::vector<Ray>& rays, Trace trace) {
  tbb::task_arena arena(static_cast<int>(state.range(0)));
  std::size_t hits = 0;
  for (auto _ : state) {
    hits = arena.execute([&] {
      return tbb::parallel_reduce(
          tbb::blocked_range<std::size_t>(0, rays.size(), 1024), std::size_t(0),
          [&](const tbb::blocked_range<std::size_t>& range, std::size_t count) {
            for (std::size_t i = range.begin(); i != range.end(); ++i) count += trace(rays[i]) ? 1 : 0;
            return count;
          },
          std::plus<>());
    });
    benchmark::DoNotOptimize(hits);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * rays.size()));
  state.counters["hit_fraction"] = double(hits) / double(rays.size());
}

void BM_Rays(benchmark::State& state, Load load, Query query) {
  const BenchScene& s = benchScene();
  const std::vector<Ray>& rays = load == Load::kAmbientOcclusion ? s.aoRays : s.cameraRays;
  const RTCScene embree = s.scene.embreeScene();
  switch (query) {
    case Query::kRawOccluded:
      return traceLoad(state, rays, [&](const Ray& r) { return rawOccluded(embree, r); });
    case Query::kRawIntersect:
      return traceLoad(state, rays, [&](const Ray& r) { return rawIntersect(embree, r); });
    case Query::kRaySceneOccluded:
      return traceLoad(state, rays, [&](const Ray& r) {
        return s.scene.occluded(r.origin, r.direction, 0.0f, kInfinity);
      });
    case Query::kRaySceneIntersect:
      return traceLoad(state, rays, [&](const Ray& r) { return s.scene.intersect(r, 0.0f, kInfinity).hit; });
  }
}

BENCHMARK_CAPTURE(BM_Rays, ao_rtcOccluded1, Load::kAmbientOcclusion, Query::kRawOccluded)
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_Rays, ao_rtcIntersect1, Load::kAmbientOcclusion, Query::kRawIntersect)
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_Rays, camera_rtcOccluded1, Load::kCamera, Query::kRawOccluded)
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_Rays, camera_rtcIntersect1, Load::kCamera, Query::kRawIntersect)
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_Rays, ao_RayScene_occluded, Load::kAmbientOcclusion, Query::kRaySceneOccluded)
    ->Arg(1)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_Rays, ao_RayScene_intersect, Load::kAmbientOcclusion, Query::kRaySceneIntersect)
    ->Arg(1)
    ->UseRealTime();

}  // namespace
}  // namespace iblkit

BENCHMARK_MAIN();
