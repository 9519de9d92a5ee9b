#include "reference/renderer.h"

#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "core/error.h"

namespace iblkit {

namespace {

// Running sums of one pixel's feature layers over its samples (double: millions of samples add up
// exactly enough); the beauty's are exact, in the PassSum.
struct PixelSums {
  glm::dvec3 albedo{0.0}, normal{0.0}, unoccluded{0.0}, direct{0.0};
  double distance = 0.0, coverage = 0.0;
};

void checkSettings(const RenderSettings& settings) {
  const auto inRange = [](long long value, long long lo, long long hi) { return value >= lo && value <= hi; };
  if (!inRange(settings.width, 1, kMaxImageSide) || !inRange(settings.height, 1, kMaxImageSide))
    fail("render", "image size " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                       " is outside 1.." + std::to_string(kMaxImageSide));
  if (!inRange(settings.samplesPerPixel, 1, kMaxSamplesPerPixel))
    fail("render", "samples per pixel " + std::to_string(settings.samplesPerPixel) + " is outside 1.." +
                       std::to_string(kMaxSamplesPerPixel));
  if (!inRange(settings.firstSample, 0, kMaxSamplesPerPixel - settings.samplesPerPixel))
    fail("render", "samples " + std::to_string(settings.firstSample) + " + " +
                       std::to_string(settings.samplesPerPixel) + " end beyond " +
                       std::to_string(kMaxSamplesPerPixel));
  if (!(settings.textureFootprint >= 0.0f) || !std::isfinite(settings.textureFootprint))
    fail("render", "texture footprint " + std::to_string(settings.textureFootprint) + " is not finite and >= 0");
  if (!inRange(settings.threads, 0, kMaxRenderThreads))
    fail("render", "thread count " + std::to_string(settings.threads) + " is outside 0.." +
                       std::to_string(kMaxRenderThreads));
}

glm::vec4 grey(double value) { return glm::vec4(glm::vec3(static_cast<float>(value)), 1.0f); }
glm::vec4 opaque(const glm::dvec3& rgb) { return glm::vec4(glm::vec3(rgb), 1.0f); }

RenderResult resolve(const std::vector<PixelSums>& sums, PassSum&& radiance, const RenderSettings& settings,
                     int samples) {
  const int w = settings.width, h = settings.height;
  RenderResult result;
  for (Image* image : {&result.albedo, &result.normal, &result.depth, &result.mask, &result.bentNormal, &result.direct})
    *image = Image(w, h);
  result.beauty = meanRadiance(radiance);
  result.variance = meanVariance(radiance);
  result.sum = std::move(radiance);
  const double n = samples;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const PixelSums& s =
          sums[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)];
      result.albedo.at(x, y) = opaque(s.albedo / n);
      result.direct.at(x, y) = opaque(s.direct / n);
      const double normalLength = glm::length(s.normal);
      result.normal.at(x, y) = opaque(normalLength > 0.0 ? s.normal / normalLength : glm::dvec3(0.0));
      const double bentLength = glm::length(s.unoccluded);
      result.bentNormal.at(x, y) = opaque(bentLength > 0.0 ? s.unoccluded / bentLength : glm::dvec3(0.0));
      result.depth.at(x, y) = grey(s.distance / n);
      result.mask.at(x, y) = grey(s.coverage / n);
    }
  result.samplesPerPixel = samples;
  return result;
}

}  // namespace

RayCone cameraRayCone(const Camera& camera, int height, float footprint) {
  const float step = footprint * 2.0f * std::tan(0.5f * camera.yfovRadians) / float(std::max(height, 1));
  // PrimaryRays' basis: d = forward + ndcX aspect tan right + ndcY tan up, so one pixel along x or y
  // changes d by 2 tan / height along right or -up (square pixels).
  const glm::vec3 right = glm::normalize(glm::cross(camera.forward, camera.up));
  const glm::vec3 up = glm::cross(right, camera.forward);
  return RayCone{0.0f, step, PixelDifferentials{camera.forward, step * right, -step * up}};
}

RenderResult render(const Integrator& integrator, const Camera& camera, const RenderSettings& settings,
                    const RenderProgress& progress) {
  checkSettings(settings);
  const int w = settings.width, h = settings.height;
  std::vector<PixelSums> sums(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  PassSum radianceSum(w, h, {static_cast<std::uint32_t>(settings.firstSample), 0});
  std::atomic<std::uint64_t> rays{0};
  std::mutex progressMutex;
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const int tilesX = (w + kTileSize - 1) / kTileSize, tilesY = (h + kTileSize - 1) / kTileSize;
  const double tileCount = static_cast<double>(tilesX) * tilesY;

  const PixelFilter filter(settings.filter);
  const PrimaryRays primaryRays(camera, w, h);
  const RayCone cone = cameraRayCone(camera, h, settings.textureFootprint);
  tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
  int samples = 0;
  do {
    const int first = settings.firstSample + samples,
              last = std::min(first + settings.samplesPerPixel, kMaxSamplesPerPixel);
    std::atomic<int> tilesDone{0};
    arena.execute([&] {
      tbb::parallel_for(
          tbb::blocked_range2d<int>(0, tilesY, 1, 0, tilesX, 1), [&](const tbb::blocked_range2d<int>& r) {
            for (int ty = r.rows().begin(); ty < r.rows().end(); ++ty)
              for (int tx = r.cols().begin(); tx < r.cols().end(); ++tx) {
                std::uint64_t tileRays = 0;
                // The tile's samples, pixel by pixel and in index order within a pixel, traced in
                // batches (Integrator::traceBatch) and summed in that same order.
                std::array<Ray, kTraceBatch> batchRays;
                std::array<std::uint32_t, kTraceBatch> batchPixels;
                std::vector<PixelSampler> batchSamplers;
                batchSamplers.reserve(kTraceBatch);
                std::array<CameraSample, kTraceBatch> batchResults;
                const auto flush = [&] {
                  const std::size_t size = batchSamplers.size();
                  integrator.traceBatch(std::span<const Ray>(batchRays.data(), size), batchSamplers, cone,
                                        std::span<CameraSample>(batchResults.data(), size));
                  for (std::size_t b = 0; b < size; ++b) {
                    const CameraSample& c = batchResults[b];
                    PixelSums& s = sums[batchPixels[b]];
                    radianceSum.addSample(batchPixels[b], c.radiance);
                    s.albedo += glm::dvec3(c.albedo);
                    s.direct += glm::dvec3(c.direct);
                    s.normal += glm::dvec3(c.normal);
                    s.unoccluded += glm::dvec3(c.unoccludedDirection);
                    s.distance += c.distance;
                    s.coverage += c.objectCoverage;
                    tileRays += c.rays;
                  }
                  batchSamplers.clear();
                };
                for (int y = ty * kTileSize; y < std::min(h, (ty + 1) * kTileSize); ++y)
                  for (int x = tx * kTileSize; x < std::min(w, (tx + 1) * kTileSize); ++x) {
                    const auto pixel = static_cast<std::uint32_t>(y * w + x);
                    const PixelSeeds seeds(settings.seed, pixel);
                    for (int i = first; i < last; ++i) {
                      PixelSampler& sampler = batchSamplers.emplace_back(seeds, static_cast<std::uint32_t>(i));
                      const glm::vec2 raster = glm::vec2(x, y) + filter.sample(sampler.next2D());
                      const std::size_t b = batchSamplers.size() - 1;
                      batchRays[b] = primaryRays(raster);
                      batchPixels[b] = pixel;
                      if (batchSamplers.size() == kTraceBatch) flush();
                    }
                  }
                if (!batchSamplers.empty()) flush();
                rays += tileRays;
                const int done = ++tilesDone;
                if (progress) {
                  const std::lock_guard lock(progressMutex);
                  const double seconds = elapsed();
                  const double fraction = settings.timeSeconds > 0.0
                                              ? std::min(1.0, seconds / settings.timeSeconds)
                                              : done / tileCount;
                  progress(fraction, seconds);
                }
              }
          });
    });
    samples = last - settings.firstSample;
  } while (settings.timeSeconds > 0.0 && elapsed() < settings.timeSeconds &&
           settings.firstSample + samples < kMaxSamplesPerPixel);

  radianceSum.samples.front().count = static_cast<std::uint32_t>(samples);
  RenderResult result = resolve(sums, std::move(radianceSum), settings, samples);
  result.seconds = elapsed();
  result.rays = rays;
  return result;
}

}  // namespace iblkit
