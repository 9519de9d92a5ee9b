// iblkit-bake: precomputes what the real-time engine needs for a scene (docs/baker.md).
//
//   iblkit-bake SCENE [--env ENV] -o OUTDIR [--ao-rays N] [--ao-distance D] [--seed S] [--threads T]
//
// OUTDIR/scene.glb  the whole flattened scene (world-space meshes, ground included, materials with
//                   the scene's overrides applied, camera) with per-vertex visibility attributes
//                   (visibility_attributes.h);
// OUTDIR/bake.json  inputs, parameters, per-stage timings and ray counts.
// OUTDIR appears only when everything is written (output_directory.h).

#include <tbb/global_control.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>

#include "baker/baked_scene_gltf.h"
#include "baker/output_directory.h"
#include "baker/vertex_visibility.h"
#include "baker/visibility_attributes.h"
#include "engine/core/error.h"
#include "engine/core/scene.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kProgram = "iblkit-bake";
constexpr const char* kVersion = "iblkit-bake 1";

struct Options {
  fs::path scene, environment, output;
  int aoRays = 256;
  float aoDistance = 0.0f;
  std::uint32_t seed = 0;
  int threads = 0;  // 0: every core
};

class Stopwatch {
 public:
  // Seconds since the previous call (or construction).
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// A one-line progress bar on stderr, redrawn when the whole percentage changes; only when stderr
// is a terminal, so logs and tests see no carriage returns. Called from the worker threads.
std::function<void(std::size_t, std::size_t)> progressBar() {
  if (!isatty(STDERR_FILENO)) return {};
  struct State {
    std::mutex mutex;
    int shown = -1;
  };
  auto state = std::make_shared<State>();
  return [state](std::size_t done, std::size_t total) {
    const int percent = total ? int(100 * done / total) : 100;
    const std::lock_guard lock(state->mutex);
    if (percent <= state->shown) return;
    state->shown = percent;
    constexpr int kWidth = 40;
    const int filled = percent * kWidth / 100;
    std::fprintf(stderr, "\r%s: visibility [%s%s] %3d%%%s", kProgram, std::string(filled, '#').c_str(),
                 std::string(kWidth - filled, ' ').c_str(), percent, percent == 100 ? "\n" : "");
  };
}

void writeJson(const fs::path& file, const json& document) {
  std::ofstream stream(file);
  stream << document.dump(2) << '\n';
  if (!stream.flush()) fail(file, "cannot write file");
}

int bake(const Options& options) {
  Stopwatch stopwatch;
  json timings;
  Scene scene = loadScene(options.scene);
  timings["load_s"] = stopwatch.lap();

  const fs::path environment = options.environment.empty() ? scene.environment.file : options.environment;
  std::error_code error;
  if (!environment.empty() && !fs::is_regular_file(environment, error)) fail(environment, "does not exist");

  VisibilitySettings settings;
  settings.rayCount = options.aoRays;
  settings.maxDistance = options.aoDistance;
  settings.seed = options.seed;
  settings.progress = progressBar();
  VisibilityStatistics statistics;
  const std::vector<MeshVisibility> visibility = bakeVertexVisibility(scene.meshes, settings, &statistics);
  const double visibilitySeconds = stopwatch.lap();
  timings["visibility_s"] = visibilitySeconds;
  attachVisibilityAttributes(scene.meshes, visibility);

  std::size_t triangles = 0;
  for (const Mesh& mesh : scene.meshes) triangles += mesh.triangleCount();
  writeDirectoryAtomically(options.output, [&](const fs::path& folder) {
    writeSceneGlb(scene, folder / "scene.glb");
    timings["write_scene_s"] = stopwatch.lap();
    // The environment stages (env/sh9.json, env/specular.exr, env/brdf_lut.exr) belong here,
    // written into `folder` from `environment`; they are not part of this program yet, so no env/
    // folder is written and bake.json lists only the files that exist.
    const json report = {
        {"version", kVersion},
        {"inputs",
         {{"scene", options.scene.string()},
          {"environment", environment.empty() ? json(nullptr) : json(environment.string())}}},
        {"parameters",
         {{"ao_rays", options.aoRays}, {"ao_distance", options.aoDistance}, {"seed", options.seed}}},
        {"outputs", {"scene.glb", "bake.json"}},
        {"timings", timings},
        {"counts",
         {{"meshes", scene.meshes.size()},
          {"vertices", statistics.vertices},
          {"triangles", triangles},
          {"rays", statistics.rays},
          {"rejected_directions", statistics.rejected}}},
        {"rays_per_second", visibilitySeconds > 0.0 ? double(statistics.rays) / visibilitySeconds : 0.0}};
    writeJson(folder / "bake.json", report);
  });
  std::cout << kProgram << ": wrote " << options.output.string() << " (" << statistics.vertices
            << " vertices, " << statistics.rays << " rays in " << visibilitySeconds << " s)\n";
  return 0;
}

}  // namespace
}  // namespace iblkit

int main(int argc, char** argv) {
  iblkit::Options options;
  CLI::App app{"Bakes per-vertex ambient occlusion, bent normals and SH transfer for a scene."};
  app.add_option("scene", options.scene, "scene: .json description, .gltf or .glb")->required();
  app.add_option("--env", options.environment, "environment map (default: the scene's)");
  app.add_option("-o,--output", options.output, "output folder, replaced only after success")->required();
  app.add_option("--ao-rays", options.aoRays, "visibility rays per vertex")
      ->check(CLI::Range(1, 1 << 24))
      ->capture_default_str();
  app.add_option("--ao-distance", options.aoDistance,
                 "occluders beyond this distance are ignored; 0 = infinite")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--seed", options.seed, "sample scrambling seed")->capture_default_str();
  app.add_option("--threads", options.threads, "worker threads; 0 = every core")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  std::unique_ptr<tbb::global_control> threads;
  if (options.threads > 0)
    threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                    std::size_t(options.threads));
  try {
    return iblkit::bake(options);
  } catch (const std::exception& e) {
    std::cerr << iblkit::kProgram << ": " << e.what() << '\n';
    return 1;
  }
}
