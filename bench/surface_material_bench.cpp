// What texture sampling costs per hit point (docs/benchmarks.md, "Textured materials"):
// evaluateSurfaceMaterial with all five slots textured (five 1024 x 1024 images, trilinear at
// random footprints, or bilinear at footprint 0) against the same material with every slot
// switched off, over 4096 precomputed random points (uv, footprint, tangent frame).
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "core/surface_material.h"

namespace {

using namespace iblkit;

struct Setup {
  std::vector<Texture> textures;
  std::vector<TextureImage> images;
  Material material;
  SceneTextures sceneTextures;
  std::vector<SurfaceInputs> points;

  explicit Setup(int size) {
    std::mt19937 rng(14);
    std::uniform_int_distribution<int> byte(0, 255);
    for (int i = 0; i < 5; ++i) {
      TextureImage image;
      image.width = image.height = size;
      image.rgba.resize(static_cast<std::size_t>(size) * size * 4);
      for (std::uint8_t& value : image.rgba) value = static_cast<std::uint8_t>(byte(rng));
      images.push_back(std::move(image));
      Texture texture;
      texture.image = i;
      textures.push_back(texture);
    }
    material.baseColorTexture.texture = 0;
    material.metallicRoughnessTexture.texture = 1;
    material.normalTexture.texture = 2;
    material.occlusionTexture.texture = 3;
    material.emissiveTexture.texture = 4;
    material.emissive = glm::vec3(1.0f);
    sceneTextures = SceneTextures(textures, images, {material});
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int i = 0; i < 4096; ++i) {
      SurfaceInputs inputs;
      inputs.texcoords[0] = glm::vec2(unit(rng), unit(rng)) * 4.0f - 2.0f;
      inputs.footprintUv[0] = std::exp2(-10.0f + 8.0f * unit(rng));  // lambda from 0 to 8
      inputs.normal = glm::vec3(0.0f, 0.0f, 1.0f);
      inputs.tangent = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
      points.push_back(inputs);
    }
  }
};

const Setup& setup(int size) {
  static const Setup large(1024), small(64);
  return size == 64 ? small : large;
}

// range(0): slots switched on; range(1): 1 keeps the random footprints (trilinear), 0 uses 0
// (bilinear); range(2): the images' size (1024: lookups miss the caches, 64: they hit them).
void BM_EvaluateSurfaceMaterial(benchmark::State& state) {
  const Setup& s = setup(static_cast<int>(state.range(2)));
  std::vector<SurfaceInputs> points = s.points;
  for (SurfaceInputs& inputs : points) {
    inputs.slots = static_cast<unsigned>(state.range(0));
    if (state.range(1) == 0) inputs.footprintUv[0] = 0.0f;
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(evaluateSurfaceMaterial(s.material, s.sceneTextures, points[i]));
    i = (i + 1) & 4095;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EvaluateSurfaceMaterial)
    ->ArgNames({"slots", "trilinear", "size"})
    ->Args({0, 0, 1024})
    ->Args({kAllTextureSlots, 0, 1024})
    ->Args({kAllTextureSlots, 1, 1024})
    ->Args({kAllTextureSlots, 0, 64})
    ->Args({kAllTextureSlots, 1, 64});

}  // namespace

BENCHMARK_MAIN();
