// The engine's lights modes on llvmpipe (docs/benchmarks.md, "Engine: dominant lights and shadow
// maps"; issue 15, "Speed"): the 1280 x 720 frame of `lights-shadowed` with 1 to 4 shadowed lights
// against the `full` frame of the same scene, `lights` (the same without shadow lookups), and the
// frame whose shadow maps are rendered again (what a light change costs; a camera move does not
// render them). Scene: assets/scenes/bunny.json (IBLKIT_ASSETS, default ./assets) baked in memory
// under a synthetic map with four disk suns (radii 0.5 to 3 degrees) over a dim sky, so that sun
// extraction (extractSuns) finds exactly four lights; the residual's stages are computed like the
// map's (kViewerEnvironmentStages).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <glm/gtc/constants.hpp>
#include <memory>

#include "baker/bake_in_memory.h"
#include "baker/environment_stages.h"
#include "core/environment_lights.h"
#include "core/image_io.h"
#include "core/latlong.h"
#include "core/temporary_files.h"
#include "engine/gl/gl_debug.h"
#include "engine/gl/headless_context.h"
#include "engine/gl/render_target.h"
#include "engine/gl/renderer.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 1280, kHeight = 720;

struct Sun {
  float azimuth, elevation, radius, radiance;  // degrees, degrees, degrees, radiance
};
constexpr Sun kSuns[] = {{-60.0f, 50.0f, 0.5f, 60000.0f}, {40.0f, 35.0f, 1.0f, 8000.0f}, {150.0f, 25.0f, 2.0f, 1500.0f},
                         {-150.0f, 60.0f, 3.0f, 700.0f}};

glm::vec3 direction(float azimuthDegrees, float elevationDegrees) {
  const float a = glm::radians(azimuthDegrees), e = glm::radians(elevationDegrees);
  return {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
}

struct Fixture {
  HeadlessContext context = HeadlessContext::create();
  BakedScene bake;
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<RenderTarget> target;
  Camera camera;

  Fixture() {
    enableGlDebugOutput(GlDebugMode::Strict);
    const Image map = latLongFromRadiance(1024, 512, 2, [](const glm::vec3& d) {
      glm::vec3 radiance = glm::vec3(0.3f, 0.4f, 0.6f) * (0.6f + 0.4f * std::max(d.y, 0.0f));
      for (const Sun& sun : kSuns)
        if (glm::dot(d, direction(sun.azimuth, sun.elevation)) >= std::cos(glm::radians(sun.radius)))
          radiance += glm::vec3(sun.radiance);
      return radiance;
    });
    const fs::path file = fs::temp_directory_path() / "iblkit_engine_lights_bench.exr";
    writeExr(file, map, {.pixelType = PixelType::Float, .envmap = EnvmapLayout::LatLong});
    const char* assets = std::getenv("IBLKIT_ASSETS");
    InMemoryBakeOptions options;
    options.environment.file = file;
    bake = loadOrBakeScene((assets && *assets ? fs::path(assets) : fs::path("assets")) / "scenes/bunny.json", options);
    fs::remove(file);
    const EnvironmentMap environment = EnvironmentMap::fromImage(map, file);
    const ExtractedSuns extracted = extractSuns(environment);
    const EnvironmentStages residual =
        computeEnvironmentStages(EnvironmentMap::fromImage(extracted.residual, file), kViewerEnvironmentStages);
    bake.env.lights.suns = extracted.suns;
    bake.env.residualSh9 = residual.sh9;
    bake.env.residualSpecular = residual.specular;
    renderer = std::make_unique<Renderer>(bake);
    target = std::make_unique<RenderTarget>(kWidth, kHeight, 1);
    camera = sceneCamera(bake.scene, float(kWidth) / float(kHeight));
  }

  void frame(const FrameSettings& settings) {
    renderer->render(camera, settings, target->framebuffer(), kWidth, kHeight);
    glFinish();
  }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

void runFrames(benchmark::State& state, ShadingMode mode, int lights, bool newShadowMaps) {
  Fixture& f = fixture();
  FrameSettings settings;
  settings.mode = mode;
  settings.lightCount = lights;
  if (int(f.bake.env.lights.suns.size()) < 4) state.SkipWithError("the map gave fewer than 4 suns");
  f.frame(settings);  // shaders compiled, maps rendered
  for (auto _ : state) {
    if (newShadowMaps) f.renderer->invalidateShadowMaps();
    f.frame(settings);
  }
  checkGlErrors("engine_lights_bench");
  state.counters["lights"] = double(lights);
}

void BM_Full(benchmark::State& state) { runFrames(state, ShadingMode::Full, 0, false); }
void BM_Lights(benchmark::State& state) { runFrames(state, ShadingMode::Lights, int(state.range(0)), false); }
void BM_LightsShadowed(benchmark::State& state) {
  runFrames(state, ShadingMode::LightsShadowed, int(state.range(0)), false);
}
void BM_LightsShadowedNewMaps(benchmark::State& state) {
  runFrames(state, ShadingMode::LightsShadowed, int(state.range(0)), true);
}

BENCHMARK(BM_Full)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(BM_Lights)->Arg(0)->Arg(4)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(BM_LightsShadowed)->DenseRange(1, 4)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(BM_LightsShadowedNewMaps)->DenseRange(1, 4)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

}  // namespace
}  // namespace iblkit

BENCHMARK_MAIN();
