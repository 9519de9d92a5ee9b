// The reference path tracer's ray rate against Embree's own rate for the same rays
// (docs/benchmarks.md, "Reference tracer", speed).
//
// BM_Render renders the bundled bunny-on-plane scene (assets/scenes/bunny.json, under its own
// map, sky.exr) with the `path` integrator and MIS, 320 x 180 at 4 spp, through reference/'s
// render(): everything iblkit-trace does except loading and writing files. items_per_second is
// rays per second (closest-hit + shadow rays the integrator traced).
//
// BM_Replay traces the very same rays (recorded once from the same render with a RayRecorder,
// origins, directions and extents included) with bare rtcIntersect1 / rtcOccluded1 calls and no
// shading: Embree's rate for the tracer's own ray mix. Both run on 1 and 2 threads (a TBB
// task_arena of that size). Shading overhead = 1 - replay time / render time.
//
// The second argument picks the scene: 0 the bunny as bundled (5,650 triangles on the ground), 1
// the same scene with the bunny replaced by a dense UV sphere of 600 rings x 1200 segments (1.44 M
// triangles) of the bunny's size and material where it stood: whether the overhead falls as Embree's
// share of a ray grows with the mesh (barely: docs/benchmarks.md).
//
// Needs the assets: IBLKIT_ASSETS (scripts/bench.sh sets it) or ./assets.

#include <benchmark/benchmark.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

#include "core/procedural_mesh.h"
#include "core/scene.h"
#include "core/scene_environment.h"
#include "reference/environment_sampler.h"
#include "reference/integrator.h"
#include "reference/ray_recorder.h"
#include "reference/render_scene.h"
#include "reference/renderer.h"

namespace iblkit {
namespace {

constexpr int kWidth = 320, kHeight = 180, kSamplesPerPixel = 4;

std::filesystem::path assetsDir() {
  const char* assets = std::getenv("IBLKIT_ASSETS");
  return assets && *assets ? std::filesystem::path(assets) : std::filesystem::path("assets");
}

struct Tracer {
  std::unique_ptr<EnvironmentMap> environment;
  std::unique_ptr<EnvironmentSampler> sampler;
  std::unique_ptr<RenderScene> scene;
  std::unique_ptr<Integrator> integrator;
  Camera camera;
  std::vector<RecordedRay> rays;  // what one render traces

  RenderSettings settings(int threads) const {
    RenderSettings s;
    s.width = kWidth;
    s.height = kHeight;
    s.samplesPerPixel = kSamplesPerPixel;
    s.seed = 1;
    s.threads = threads;
    return s;
  }
};

enum SceneVariant { kBunny = 0, kDenseSphere = 1 };

// bunny.json, or (kDenseSphere) with every non-ground mesh replaced by one dense sphere filling
// the same bounds.
Scene benchScene(SceneVariant variant) {
  Scene scene = loadScene(assetsDir() / "scenes" / "bunny.json");
  if (variant == kDenseSphere) {
    const Bounds bounds = objectBounds(scene.meshes);
    const glm::vec3 extent = bounds.max - bounds.min;
    const float radius = 0.5f * std::min({extent.x, extent.y, extent.z});
    const glm::vec3 centre(bounds.center().x, bounds.min.y + radius, bounds.center().z);
    std::vector<Mesh> meshes;
    int material = 0;
    for (Mesh& mesh : scene.meshes) {
      if (mesh.isGround)
        meshes.push_back(std::move(mesh));
      else
        material = mesh.material;
    }
    meshes.push_back(toMesh(uvSphere(centre, radius, 600, 1200), "dense sphere", material));
    scene.meshes = std::move(meshes);
    scene.bounds = objectBounds(scene.meshes);
  }
  return scene;
}

const Tracer& tracer(SceneVariant variant) {
  static std::unique_ptr<Tracer> tracers[2];
  std::unique_ptr<Tracer>& slot = tracers[variant];
  if (slot) return *slot;
  slot = std::make_unique<Tracer>();
  Tracer& t = *slot;
  {
    Scene scene = benchScene(variant);
    t.environment = std::make_unique<EnvironmentMap>(loadSceneEnvironment(scene));
    t.sampler = std::make_unique<EnvironmentSampler>(*t.environment);
    t.camera = sceneCamera(scene, static_cast<float>(kWidth) / kHeight);
    t.scene = std::make_unique<RenderScene>(std::move(scene));
    t.integrator = std::make_unique<Integrator>(*t.scene, *t.environment, *t.sampler, IntegratorSettings{});
    RayRecorder recorder;
    t.integrator->recordRays(&recorder);
    render(*t.integrator, t.camera, t.settings(2));
    t.integrator->recordRays(nullptr);
    t.rays = recorder.rays();
  }
  return t;
}

bool replay(RTCScene scene, const RecordedRay& r) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  if (r.occlusion) {
    RTCRay query{};
    query.org_x = r.origin.x, query.org_y = r.origin.y, query.org_z = r.origin.z;
    query.dir_x = r.direction.x, query.dir_y = r.direction.y, query.dir_z = r.direction.z;
    query.tnear = r.tmin;
    query.tfar = r.tmax;
    query.mask = ~0u;
    rtcOccluded1(scene, &context, &query);
    return query.tfar < 0.0f;
  }
  RTCRayHit query{};
  query.ray.org_x = r.origin.x, query.ray.org_y = r.origin.y, query.ray.org_z = r.origin.z;
  query.ray.dir_x = r.direction.x, query.ray.dir_y = r.direction.y, query.ray.dir_z = r.direction.z;
  query.ray.tnear = r.tmin;
  query.ray.tfar = r.tmax;
  query.ray.mask = ~0u;
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &context, &query);
  return query.hit.geomID != RTC_INVALID_GEOMETRY_ID;
}

void BM_Render(benchmark::State& state) {
  const Tracer& t = tracer(static_cast<SceneVariant>(state.range(1)));
  const RenderSettings settings = t.settings(static_cast<int>(state.range(0)));
  std::uint64_t rays = 0;
  for (auto _ : state) {
    const RenderResult result = render(*t.integrator, t.camera, settings);
    rays += result.rays;
    if (result.rays != t.rays.size())
      state.SkipWithError("render traced a different number of rays than recorded");
  }
  state.SetItemsProcessed(static_cast<int64_t>(rays));
  state.counters["rays"] = static_cast<double>(t.rays.size());
}

void BM_Replay(benchmark::State& state) {
  const Tracer& t = tracer(static_cast<SceneVariant>(state.range(1)));
  const RTCScene scene = t.scene->rays().embreeScene();
  tbb::task_arena arena(static_cast<int>(state.range(0)));
  std::size_t hits = 0;
  for (auto _ : state) {
    hits = arena.execute([&] {
      return tbb::parallel_reduce(
          tbb::blocked_range<std::size_t>(0, t.rays.size(), 1024), std::size_t(0),
          [&](const tbb::blocked_range<std::size_t>& range, std::size_t count) {
            for (std::size_t i = range.begin(); i != range.end(); ++i)
              count += replay(scene, t.rays[i]) ? 1 : 0;
            return count;
          },
          std::plus<>());
    });
    benchmark::DoNotOptimize(hits);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * t.rays.size()));
  state.counters["rays"] = static_cast<double>(t.rays.size());
  state.counters["hit_fraction"] = static_cast<double>(hits) / static_cast<double>(t.rays.size());
}

// Arguments: threads, scene (SceneVariant).
BENCHMARK(BM_Render)->ArgsProduct({{1, 2}, {kBunny, kDenseSphere}})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Replay)->ArgsProduct({{1, 2}, {kBunny, kDenseSphere}})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace iblkit

BENCHMARK_MAIN();
