// AO bake cost (docs/benchmarks.md, "Baker"): how close the per-vertex visibility bake comes to
// Embree's raw rtcOccluded1 throughput, and how its time grows with the vertex count.
//
//   BM_BakeBunny/T         bakeVertexVisibility of assets/scenes/bunny.json (the bunny and the
//                          scene's ground), 256 rays per vertex, on T = 1 or 2 threads. items_per_second =
//                          visibility rays per second, over the whole bake (scene build included).
//   BM_ReplayBunnyRays/T   the very same rays (vertexVisibilityRays: same origins, directions and
//                          order), replayed through rtcOccluded1 with Embree's C API on T threads
//                          in chunks of 64 vertices' rays: the ceiling for the bake's ray rate.
//   BM_BakeSphere/N        a generated UV sphere of N rings (2 + (N - 1) 2N vertices) on a ground
//                          square, 256 rays per vertex, 2 threads: time per vertex ("us_per_vertex")
//                          from the bunny's size (~2.7k) to 179k vertices; with
//                          IBLKIT_BENCH_LARGE=1 also ~1M vertices (N = 707, one iteration: 95 s on
//                          the loaded 2-core machine, too long for every scripts/bench.sh run).
//
// Set IBLKIT_ASSETS to the folder holding scenes/, models/ and hdri/ (default: ./assets).

#include <benchmark/benchmark.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "baker/vertex_visibility.h"
#include "bench/raw_embree.h"
#include "core/procedural_mesh.h"
#include "core/scene.h"
#include "raytrace/ray_scene.h"

namespace iblkit {
namespace {

constexpr int kRays = 256;
constexpr std::size_t kVertexGrain = 64;  // vertex_visibility.cpp's chunk size

VisibilitySettings bakeSettings() {
  VisibilitySettings settings;
  settings.rayCount = kRays;
  return settings;
}

const std::vector<Mesh>& bunnyMeshes() {
  static const std::vector<Mesh> meshes = [] {
    const char* assets = std::getenv("IBLKIT_ASSETS");
    return loadScene(std::filesystem::path(assets ? assets : "assets") / "scenes" / "bunny.json").meshes;
  }();
  return meshes;
}

void bake(benchmark::State& state, const std::vector<Mesh>& meshes, int threads) {
  tbb::task_arena arena(threads);
  VisibilityStatistics statistics;
  for (auto _ : state) {
    arena.execute(
        [&] { benchmark::DoNotOptimize(bakeVertexVisibility(meshes, bakeSettings(), &statistics)); });
  }
  const auto vertices = double(statistics.vertices);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * statistics.rays));
  state.counters["vertices"] = vertices;
  state.counters["us_per_vertex"] =
      benchmark::Counter(vertices * double(state.iterations()) * 1e-6,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["trace_rays_per_second"] = double(statistics.rays) / statistics.raySeconds;
}

void BM_BakeBunny(benchmark::State& state) { bake(state, bunnyMeshes(), static_cast<int>(state.range(0))); }
BENCHMARK(BM_BakeBunny)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ReplayBunnyRays(benchmark::State& state) {
  const std::vector<Mesh>& meshes = bunnyMeshes();
  const std::vector<Ray> rays = vertexVisibilityRays(meshes, bakeSettings());
  RayScene scene;
  for (const Mesh& mesh : meshes) scene.addTriangleMesh(mesh.positions, mesh.indices);
  scene.commit();
  const RTCScene embree = scene.embreeScene();
  tbb::task_arena arena(static_cast<int>(state.range(0)));
  std::size_t occluded = 0;
  for (auto _ : state) {
    occluded = arena.execute([&] {
      return tbb::parallel_reduce(
          tbb::blocked_range<std::size_t>(0, rays.size(), kVertexGrain * kRays), std::size_t(0),
          [&](const tbb::blocked_range<std::size_t>& range, std::size_t count) {
            for (std::size_t i = range.begin(); i != range.end(); ++i) count += rawOccluded(embree, rays[i]);
            return count;
          },
          std::plus<>());
    });
    benchmark::DoNotOptimize(occluded);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * rays.size()));
  state.counters["occluded_fraction"] = double(occluded) / double(rays.size());
}
BENCHMARK(BM_ReplayBunnyRays)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_BakeSphere(benchmark::State& state) {
  const int rings = static_cast<int>(state.range(0));
  const std::vector<Mesh> meshes = {
      toMesh(uvSphere(glm::vec3(0.0f, 1.0f, 0.0f), 1.0f, rings, 2 * rings), "sphere"),
      toMesh(plane(glm::vec3(0.0f), 20.0f), "ground")};
  bake(state, meshes, 2);
}
// 2,666 / 11,102 / 44,702 / 179,402 / 998,286 sphere vertices (plus the ground's 4).
BENCHMARK(BM_BakeSphere)->Arg(37)->Arg(75)->Arg(150)->Arg(300)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace iblkit

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  const char* large = std::getenv("IBLKIT_BENCH_LARGE");
  if (large && std::string(large) == "1")
    benchmark::RegisterBenchmark("BM_BakeSphere", iblkit::BM_BakeSphere)
        ->Arg(707)
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
