// The dominant lights' cost (docs/dominant-lights.md, docs/benchmarks.md): sun extraction, the
// median cut, and the residual's SH9 and specular chain, for the sunny asset map sky.exr (512 x
// 256) and the same map upsampled to 2048 x 1024; and what the lights add to the viewer's
// in-memory stages. Set IBLKIT_ASSETS to the folder holding hdri/ (default: ./assets).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <map>

#include "baker/environment_stages.h"
#include "baker/specular_prefilter.h"
#include "core/environment_lights.h"
#include "core/environment_sh.h"
#include "bench/asset_environment.h"

namespace {

using iblkit::EnvironmentMap;

const EnvironmentMap& environment(int width) { return iblkit::bench::assetEnvironment("sky", width); }

// The map without its suns (extractSuns with the defaults).
const EnvironmentMap& residual(int width) {
  static std::map<int, EnvironmentMap> residuals;
  auto found = residuals.find(width);
  if (found == residuals.end())
    found = residuals.emplace(width, EnvironmentMap::fromImage(iblkit::extractSuns(environment(width)).residual,
                                                                "residual"))
                .first;
  return found->second;
}

void BM_ExtractSuns(benchmark::State& state) {
  const EnvironmentMap& map = environment(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(iblkit::extractSuns(map));
}
BENCHMARK(BM_ExtractSuns)->Arg(512)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_MedianCut(benchmark::State& state) {
  const EnvironmentMap& map = environment(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(iblkit::medianCutLights(map, iblkit::kDefaultMedianCutLevels));
}
BENCHMARK(BM_MedianCut)->Arg(512)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();

// As computeEnvironmentStages does it: the projection, windowed (the window is 9 multiplications).
void BM_ResidualSh9(benchmark::State& state) {
  const EnvironmentMap& map = residual(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(iblkit::windowSh9(iblkit::projectEnvironmentSh9(map), 8.0f));
}
BENCHMARK(BM_ResidualSh9)->Arg(512)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();

// The baker's chain (default options: base width / 4, 1024 samples for the roughest level).
void BM_ResidualSpecularChain(benchmark::State& state) {
  const EnvironmentMap& map = residual(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(iblkit::prefilterSpecular(map));
}
BENCHMARK(BM_ResidualSpecularChain)
    ->Arg(512)
    ->Arg(2048)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

// The viewer's in-memory stages of the 512 x 256 map without (0) and with (1) the lights.
void BM_ViewerStages(benchmark::State& state) {
  iblkit::EnvironmentStageOptions options = iblkit::kViewerEnvironmentStages;
  options.lights = state.range(0) != 0;
  for (auto _ : state) benchmark::DoNotOptimize(iblkit::computeEnvironmentStages(environment(512), options));
}
BENCHMARK(BM_ViewerStages)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
