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
// BM_ReplayBatched traces them as the render does since it batches them: each batch's camera
// rays in 8-wide coherent packets (RayScene::intersectCoherent), each batch's shadow rays of a
// depth in 8-wide packets (the batch RayScene::occluded), the bounce rays one by one: Embree's
// rate for the same rays through the same calls. BM_Replay is the one-ray-at-a-time yardstick the
// issue's target was set against.
//
// The second argument picks the scene: 0 the bunny as bundled (5,650 triangles on the ground), 1
// the same scene with the bunny replaced by a dense UV sphere of 600 rings x 1200 segments (1.44 M
// triangles) of the bunny's size and material where it stood: whether the overhead falls as Embree's
// share of a ray grows with the mesh (barely: docs/benchmarks.md).
//
// BM_RenderBrdfOnly / BM_ReplayBrdfOnly: the same pair for the leanest estimator (BRDF sampling
// only, no ground occlusion), with its own recorded rays: the path loop's cost per ray without any
// light sampling, against which the default estimator's ratio is read.
//
// BM_RenderTextured: the bunny scene made fully textured (every mesh given planar TEXCOORD_0 and
// a material with all five slots: 1024 x 1024 generated base colour (sRGB, alpha 1), metallic-
// roughness, normal, occlusion and emissive textures, trilinear, repeat; tangents generated),
// rendered with the textures read (third argument 1) and with every slot off (0: the same scene,
// the same mip chains built, the constant factors traced; iblkit-trace --no-textures). Its
// Mrays/s ratio is the cost of texture sampling (issue 14: at most 15%).
// Third argument 2: slots off, but each material's factors multiplied by its textures' mean
// (base colour and emissive averaged in linear, roughness G and metallic B; the normal map's mean
// is near flat and left out), so the baseline traces about the same light transport as 1 and the
// ratio 1 : 2 is closer to the lookups' own cost than 1 : 0 (docs/benchmarks.md).
//
// Needs the assets: IBLKIT_ASSETS (scripts/bench.sh sets it) or ./assets.

#include <benchmark/benchmark.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <limits>
#include <span>
#include <cmath>
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

enum SceneVariant { kBunny = 0, kDenseSphere = 1, kTexturedBunny = 2 };

// A size x size image of smooth noise-like patterns (sums of sines), channel c's pattern scaled
// into [lo[c], hi[c]] (8-bit values).
TextureImage patternImage(int size, glm::vec4 lo, glm::vec4 hi, float frequency) {
  TextureImage image;
  image.name = "bench pattern";
  image.mimeType = "image/png";
  image.width = image.height = size;
  image.rgba.resize(std::size_t(size) * std::size_t(size) * 4);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      for (int c = 0; c < 4; ++c) {
        const float u = float(x) / float(size), v = float(y) / float(size);
        const float w = 0.5f + 0.25f * std::sin(6.2832f * frequency * (u + 0.3f * c)) +
                        0.25f * std::sin(6.2832f * frequency * (v * 1.3f + 0.7f * u + 0.2f * c));
        image.rgba[(std::size_t(y) * std::size_t(size) + std::size_t(x)) * 4 + std::size_t(c)] =
            static_cast<std::uint8_t>(std::lround(lo[c] + (hi[c] - lo[c]) * w));
      }
  return image;
}

// Every mesh of `scene` textured with all five slots (see BM_RenderTextured).
void textureEverything(Scene& scene) {
  constexpr int kTextureSize = 1024;
  const glm::vec4 lo[5] = {
      {150, 140, 120, 255}, {0, 120, 0, 255}, {110, 110, 235, 255}, {180, 180, 180, 255}, {0, 0, 0, 255}};
  const glm::vec4 hi[5] = {
      {240, 230, 220, 255}, {0, 255, 40, 255}, {146, 146, 255, 255}, {255, 255, 255, 255}, {40, 30, 20, 255}};
  scene.images.clear();
  scene.textures.clear();
  for (int i = 0; i < 5; ++i) {
    scene.images.push_back(patternImage(kTextureSize, lo[i], hi[i], 8.0f + 3.0f * float(i)));
    Texture texture;
    texture.image = i;
    scene.textures.push_back(texture);
  }
  for (Material& material : scene.materials) {
    material.baseColorTexture.texture = 0;
    material.metallicRoughnessTexture.texture = 1;
    material.normalTexture.texture = 2;
    material.occlusionTexture.texture = 3;
    material.emissiveTexture.texture = 4;
    material.emissive = glm::vec3(0.05f);
  }
  const Bounds bounds = objectBounds(scene.meshes);
  const float size = std::max(bounds.max.x - bounds.min.x, bounds.max.z - bounds.min.z);
  for (Mesh& mesh : scene.meshes) {
    mesh.texcoords.clear();
    // Planar uv from x and z: 4 repeats across the object, the ground's repeat of the same scale.
    for (const glm::vec3& p : mesh.positions) mesh.texcoords.push_back(glm::vec2(p.x, p.z) * (4.0f / size));
    mesh.tangents.clear();  // RenderScene generates them
  }
}

// The mean of channel `c` of `image`, decoded from sRGB when `srgb`, as a value in [0, 1].
float channelMean(const TextureImage& image, int c, bool srgb) {
  double sum = 0.0;
  const std::size_t texels = image.rgba.size() / 4;
  for (std::size_t i = 0; i < texels; ++i) {
    const std::uint8_t value = image.rgba[4 * i + std::size_t(c)];
    sum += srgb ? srgbToLinear(value) : value / 255.0;
  }
  return static_cast<float>(sum / double(texels));
}

// textureEverything's materials with their factors times the textures' means (BM_RenderTextured/T/2).
void meanFactors(Scene& scene) {
  const TextureImage& base = scene.images[0];
  const TextureImage& mr = scene.images[1];
  const TextureImage& emissive = scene.images[4];
  const glm::vec3 baseMean(channelMean(base, 0, true), channelMean(base, 1, true),
                           channelMean(base, 2, true));
  const glm::vec3 emissiveMean(channelMean(emissive, 0, true), channelMean(emissive, 1, true),
                               channelMean(emissive, 2, true));
  for (Material& material : scene.materials) {
    material.baseColor *= baseMean;
    material.roughness *= channelMean(mr, 1, false);
    material.metallic *= channelMean(mr, 2, false);
    material.emissive *= emissiveMean;
  }
}

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
  if (variant == kTexturedBunny) textureEverything(scene);
  return scene;
}

// The tracer of `variant`; `slots` the texture slots read (the textured variant only).
// `means`: the textured variant's factors times the textures' means (meanFactors).
// `brdfOnly`: the leanest estimator, --env-sampling brdf --ground-occlusion off (BM_RenderBrdfOnly).
const Tracer& tracer(SceneVariant variant, unsigned slots = kAllTextureSlots, bool means = false,
                     bool brdfOnly = false) {
  static std::unique_ptr<Tracer> tracers[7];
  const bool off = variant == kTexturedBunny && slots == 0;
  std::unique_ptr<Tracer>& slot = tracers[brdfOnly ? 5 + variant : off && means ? 4 : off ? 3 : variant];
  if (slot) return *slot;
  slot = std::make_unique<Tracer>();
  Tracer& t = *slot;
  {
    Scene scene = benchScene(variant);
    if (variant == kTexturedBunny && means) meanFactors(scene);
    t.environment = std::make_unique<EnvironmentMap>(loadSceneEnvironment(scene));
    t.sampler = std::make_unique<EnvironmentSampler>(*t.environment);
    t.camera = sceneCamera(scene, static_cast<float>(kWidth) / kHeight);
    t.scene = std::make_unique<RenderScene>(std::move(scene), slots);
    IntegratorSettings integratorSettings;
    if (brdfOnly) {
      integratorSettings.envSampling = EnvSampling::Brdf;
      integratorSettings.groundOcclusion = false;
    }
    t.integrator = std::make_unique<Integrator>(*t.scene, *t.environment, *t.sampler, integratorSettings);
    RayRecorder recorder;
    t.integrator->recordRays(&recorder);
    render(*t.integrator, t.camera, t.settings(2));
    t.integrator->recordRays(nullptr);
    t.rays = recorder.rays();
  }
  return t;
}

bool replay(RTCScene scene, const RecordedRay& r) {
  // The query's context, as RayScene passes it: the scene's filter callbacks (single-sided back
  // faces culled for camera rays, alpha) read it, and run in the replay as in the render.
  RayQueryContext queryContext(r.query);
  RTCIntersectContext& context = queryContext.context;
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

void renderRecorded(benchmark::State& state, const Tracer& t) {
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

void BM_Render(benchmark::State& state) { renderRecorded(state, tracer(static_cast<SceneVariant>(state.range(1)))); }

// Replays `units` units of work (rays, or runs of rays) on state.range(0) threads, `grain` units per
// task; hitsIn(i) traces unit i and returns its hits. Reports the recorded rays per second and the
// fraction of them that hit.
template <class HitsIn>
void replayInArena(benchmark::State& state, const Tracer& t, std::size_t units, std::size_t grain, const HitsIn& hitsIn) {
  tbb::task_arena arena(static_cast<int>(state.range(0)));
  std::size_t hits = 0;
  for (auto _ : state) {
    hits = arena.execute([&] {
      return tbb::parallel_reduce(
          tbb::blocked_range<std::size_t>(0, units, grain), std::size_t(0),
          [&](const tbb::blocked_range<std::size_t>& range, std::size_t count) {
            for (std::size_t i = range.begin(); i != range.end(); ++i) count += hitsIn(i);
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

void replayOneByOne(benchmark::State& state, const Tracer& t) {
  const RTCScene scene = t.scene->rays().embreeScene();
  replayInArena(state, t, t.rays.size(), 1024,
                [&](std::size_t i) -> std::size_t { return replay(scene, t.rays[i]) ? 1 : 0; });
}

void BM_Replay(benchmark::State& state) { replayOneByOne(state, tracer(static_cast<SceneVariant>(state.range(1)))); }

// The leanest estimator the tracer has: BRDF sampling only (no light samples, no environment
// sampler, no ground occlusion; escapes read the map), its own recorded rays rendered and replayed.
// What the path loop itself costs per ray, against which the default estimator's ratio is read
// (docs/benchmarks.md, "The leanest estimator's ray rate").
void BM_RenderBrdfOnly(benchmark::State& state) {
  renderRecorded(state, tracer(static_cast<SceneVariant>(state.range(1)), kAllTextureSlots, false, true));
}
void BM_ReplayBrdfOnly(benchmark::State& state) {
  replayOneByOne(state, tracer(static_cast<SceneVariant>(state.range(1)), kAllTextureSlots, false, true));
}

// The recorded rays as the render traces them: each run of camera rays (one batch's, one query)
// through RayScene::intersectCoherent, each run of shadow rays through the batch occluded, the
// bounce rays one by one. Embree's rate with the packet queries the render itself uses.
struct ReplayRun {
  std::size_t begin, end;
  enum Kind { Camera, Shadow, Single } kind;
};

std::vector<ReplayRun> replayRuns(const std::vector<RecordedRay>& rays) {
  const auto kindOf = [](const RecordedRay& r) {
    return r.occlusion ? ReplayRun::Shadow : r.query.kind == RayKind::Camera ? ReplayRun::Camera : ReplayRun::Single;
  };
  std::vector<ReplayRun> runs;
  for (std::size_t i = 0; i < rays.size();) {
    const ReplayRun::Kind kind = kindOf(rays[i]);
    std::size_t end = i + 1;
    if (kind != ReplayRun::Single)
      while (end < rays.size() && kindOf(rays[end]) == kind && end - i < kTraceBatch * kMaxSplitLightDraws) ++end;
    runs.push_back({i, end, kind});
    i = end;
  }
  return runs;
}

std::size_t replayRun(const RayScene& scene, const std::vector<RecordedRay>& rays, const ReplayRun& run) {
  const std::size_t size = run.end - run.begin;
  std::size_t count = 0;
  if (run.kind == ReplayRun::Camera) {
    std::array<Ray, kTraceBatch> batch;
    std::array<Hit, kTraceBatch> hits;
    for (std::size_t first = 0; first < size; first += kTraceBatch) {
      const std::size_t n = std::min<std::size_t>(kTraceBatch, size - first);
      for (std::size_t k = 0; k < n; ++k) batch[k] = {rays[run.begin + first + k].origin, rays[run.begin + first + k].direction};
      scene.intersectCoherent(std::span<const Ray>(batch.data(), n), 0.0f, std::numeric_limits<float>::infinity(),
                              rays[run.begin + first].query, std::span<Hit>(hits.data(), n));
      for (std::size_t k = 0; k < n; ++k) count += hits[k].hit;
    }
  } else if (run.kind == ReplayRun::Shadow) {
    thread_local std::vector<OcclusionQuery> batch;
    thread_local std::vector<std::uint8_t> blocked;
    batch.clear();
    for (std::size_t i = run.begin; i < run.end; ++i)
      batch.push_back({rays[i].origin, rays[i].direction, rays[i].tmin, rays[i].tmax, rays[i].query});
    blocked.resize(size);
    scene.occluded(batch, blocked);
    for (const std::uint8_t b : blocked) count += b;
  } else {
    for (std::size_t i = run.begin; i < run.end; ++i) count += replay(scene.embreeScene(), rays[i]) ? 1 : 0;
  }
  return count;
}

void BM_ReplayBatched(benchmark::State& state) {
  const Tracer& t = tracer(static_cast<SceneVariant>(state.range(1)));
  const std::vector<ReplayRun> runs = replayRuns(t.rays);
  replayInArena(state, t, runs.size(), 256,
                [&](std::size_t i) -> std::size_t { return replayRun(t.scene->rays(), t.rays, runs[i]); });
}

void BM_RenderTextured(benchmark::State& state) {
  const Tracer& t = tracer(kTexturedBunny, state.range(1) == 1 ? kAllTextureSlots : 0u, state.range(1) == 2);
  const RenderSettings settings = t.settings(static_cast<int>(state.range(0)));
  std::uint64_t rays = 0;
  for (auto _ : state) rays += render(*t.integrator, t.camera, settings).rays;
  state.SetItemsProcessed(static_cast<int64_t>(rays));
  state.counters["rays"] = static_cast<double>(rays) / static_cast<double>(state.iterations());
}

// Arguments: threads, scene (SceneVariant).
BENCHMARK(BM_Render)
    ->ArgsProduct({{1, 2}, {kBunny, kDenseSphere}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Replay)
    ->ArgsProduct({{1, 2}, {kBunny, kDenseSphere}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_RenderBrdfOnly)
    ->ArgsProduct({{1, 2}, {kBunny, kDenseSphere}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_ReplayBrdfOnly)
    ->ArgsProduct({{1, 2}, {kBunny, kDenseSphere}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_ReplayBatched)
    ->ArgsProduct({{1, 2}, {kBunny, kDenseSphere}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
// Arguments: threads, textures read (1) or every slot off (0).
BENCHMARK(BM_RenderTextured)->ArgsProduct({{1, 2}, {0, 1, 2}})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace iblkit

BENCHMARK_MAIN();
