// Prefiltering cost: SH9 projection, the whole GGX specular chain (default options: base face
// width / 4, full chain, 1024 samples per texel) and the 16 x 16 irradiance cube (the baker's and
// the viewer's size) for a 512 x 256 asset map and the same map upsampled to 2048 x 1024. Set IBLKIT_ASSETS to the folder holding hdri/ (default: ./assets).
#include <benchmark/benchmark.h>


#include "core/environment_sh.h"
#include "baker/irradiance_cube.h"
#include "baker/specular_prefilter.h"
#include "bench/asset_environment.h"

namespace {

using iblkit::EnvironmentMap;

const EnvironmentMap& environment(int width) { return iblkit::bench::assetEnvironment("park", width); }

void BM_ProjectSh9(benchmark::State& state) {
  const EnvironmentMap& map = environment(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(iblkit::projectEnvironmentSh9(map));
}
BENCHMARK(BM_ProjectSh9)->Arg(512)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SpecularChain(benchmark::State& state) {
  const EnvironmentMap& map = environment(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(iblkit::prefilterSpecular(map));
}
BENCHMARK(BM_SpecularChain)->Arg(512)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

void BM_IrradianceCube(benchmark::State& state) {
  const EnvironmentMap& map = environment(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(iblkit::irradianceCube(map, 16));
}
BENCHMARK(BM_IrradianceCube)->Arg(512)->Arg(2048)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
