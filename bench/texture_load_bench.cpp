// Load time of a glb with 4k textures (issue 14, "Speed"): a quad whose material fills four slots
// with 4096 x 4096 images, base colour and occlusion as JPEG, metallic-roughness and normal as PNG,
// embedded in the glb's buffer (the layout an exporter writes). The file is generated once per run
// into a temporary folder (not committed; stb_image_write encodes the images, writeSceneGlb writes
// the glb), then loadScene (what every program calls: parse, decode every image) is timed. The same
// quad without images (BM_LoadScene/0) is the loader's fixed cost, so the difference is what the
// textures cost. Run it with `build/bench/texture_load_bench`; the
// generated file is kept when IBLKIT_TEXTURE_BENCH_KEEP names a path (for `time iblkit-info`).
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>
#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "bakefile/scene_glb.h"
#include "core/scene.h"

namespace {

namespace fs = std::filesystem;
using namespace iblkit;

constexpr int kSize = 4096;

void append(void* context, void* data, int size) {
  auto& out = *static_cast<std::vector<std::uint8_t>*>(context);
  out.insert(out.end(), static_cast<std::uint8_t*>(data), static_cast<std::uint8_t*>(data) + size);
}

// Texture-like content: smooth gradients with a fine hashed grain in every channel, so neither
// codec sees a trivially compressible image (a flat colour would decode faster than any asset).
std::vector<std::uint8_t> pixels(int seed) {
  std::vector<std::uint8_t> rgb(std::size_t(kSize) * kSize * 3);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      std::uint32_t h = std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u ^ std::uint32_t(seed) * 83492791u;
      h ^= h >> 13;
      h *= 0x5bd1e995u;
      std::uint8_t* p = &rgb[(std::size_t(y) * kSize + x) * 3];
      p[0] = std::uint8_t((x >> 4) + (h & 15));
      p[1] = std::uint8_t((y >> 4) + ((h >> 4) & 15));
      p[2] = std::uint8_t(((x + y) >> 5) + ((h >> 8) & 15));
    }
  return rgb;
}

TextureImage image(const char* name, bool png, int seed) {
  TextureImage result;
  result.name = name;
  result.mimeType = png ? "image/png" : "image/jpeg";
  result.width = result.height = kSize;
  const std::vector<std::uint8_t> rgb = pixels(seed);
  if (png)
    stbi_write_png_to_func(append, &result.encoded, kSize, kSize, 3, rgb.data(), kSize * 3);
  else
    stbi_write_jpg_to_func(append, &result.encoded, kSize, kSize, 3, rgb.data(), 90);
  return result;
}

// The quad, with its four textures or without any.
Scene quadScene(bool textured) {
  Scene scene;
  Mesh quad;
  quad.name = "quad";
  quad.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
  quad.normals.assign(4, glm::vec3(0, 1, 0));
  quad.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  quad.tangents.assign(4, glm::vec4(1, 0, 0, 1));
  quad.indices = {0, 2, 1, 0, 3, 2};
  scene.meshes = {quad};
  scene.materials = {Material{}};
  if (!textured) return scene;
  scene.images = {image("baseColor", false, 1), image("metallicRoughness", true, 2), image("normal", true, 3),
                  image("occlusion", false, 4)};
  for (int i = 0; i < 4; ++i) {
    Texture texture;
    texture.image = i;
    scene.textures.push_back(texture);
  }
  Material& material = scene.materials[0];
  material.baseColorTexture.texture = 0;
  material.metallicRoughnessTexture.texture = 1;
  material.normalTexture.texture = 2;
  material.occlusionTexture.texture = 3;
  return scene;
}

const fs::path& glbFile(bool textured) {
  static const fs::path folder = [] {
    const fs::path dir = fs::temp_directory_path() / "iblkit-texture-load-bench";
    fs::create_directories(dir);
    return dir;
  }();
  static const fs::path files[2] = {folder / "untextured.glb", folder / "textured.glb"};
  static bool written = false;
  if (!written) {
    writeSceneGlb(quadScene(true), files[1]);
    if (const char* keep = std::getenv("IBLKIT_TEXTURE_BENCH_KEEP"))
      fs::copy_file(files[1], keep, fs::copy_options::overwrite_existing);
    writeSceneGlb(quadScene(false), files[0]);
    written = true;
  }
  return files[textured ? 1 : 0];
}

void BM_LoadScene(benchmark::State& state) {
  const fs::path& file = glbFile(state.range(0) != 0);
  state.counters["MiB"] = double(fs::file_size(file)) / (1024.0 * 1024.0);
  for (auto _ : state) benchmark::DoNotOptimize(loadScene(file));
}
BENCHMARK(BM_LoadScene)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
