#include "reference/noise_split.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include "core/file_io.h"
#include "core/halves_noise.h"

namespace iblkit {

namespace {

// The image of both halves' samples: the mean of each layer, the normals renormalised, the
// variance of the mean (var(a) + var(b)) / 4.
RenderResult meanOf(const RenderResult& a, const RenderResult& b) {
  RenderResult mean;
  const auto average = [](const Image& x, const Image& y, float scale) {
    Image out(x.width(), x.height());
    for (std::size_t i = 0; i < x.pixelCount(); ++i) {
      out.pixels()[i] = scale * (x.pixels()[i] + y.pixels()[i]);
      out.pixels()[i].a = 1.0f;
    }
    return out;
  };
  mean.beauty = average(a.beauty, b.beauty, 0.5f);
  mean.albedo = average(a.albedo, b.albedo, 0.5f);
  mean.direct = average(a.direct, b.direct, 0.5f);
  mean.depth = average(a.depth, b.depth, 0.5f);
  mean.mask = average(a.mask, b.mask, 0.5f);
  mean.variance = average(a.variance, b.variance, 0.25f);
  for (auto [layer, x, y] : {std::tuple{&mean.normal, &a.normal, &b.normal},
                             std::tuple{&mean.bentNormal, &a.bentNormal, &b.bentNormal}}) {
    *layer = average(*x, *y, 0.5f);
    for (glm::vec4& p : layer->pixels()) {
      const float length = glm::length(glm::vec3(p));
      p = glm::vec4(length > 0.0f ? glm::vec3(p) / length : glm::vec3(0.0f), 1.0f);
    }
  }
  mean.samplesPerPixel = a.samplesPerPixel + b.samplesPerPixel;
  mean.seconds = a.seconds + b.seconds;
  mean.rays = a.rays + b.rays;
  return mean;
}

}  // namespace

NoiseSplit renderNoiseSplit(const Integrator& integrator, const Camera& camera,
                            const RenderSettings& settings, const RenderProgress& progress) {
  if (settings.samplesPerPixel % 2 != 0)
    throw std::invalid_argument("renderNoiseSplit: the samples per pixel must be even");
  NoiseSplit split;
  RenderSettings half = settings;
  half.samplesPerPixel = settings.samplesPerPixel / 2;
  half.timeSeconds = settings.timeSeconds / 2.0;
  half.seed = 2 * settings.seed;
  split.a = render(integrator, camera, half, progress);
  half.seed = 2 * settings.seed + 1;
  split.b = render(integrator, camera, half, progress);
  split.mean = meanOf(split.a, split.b);

  const std::size_t count = split.mean.beauty.pixelCount();
  std::vector<std::uint8_t> geometry(count), object(count), ground(count);
  for (std::size_t i = 0; i < count; ++i) {
    geometry[i] = split.mean.depth.pixels()[i].r > 0.0f;
    object[i] = geometry[i] && split.mean.mask.pixels()[i].r >= 0.5f;
    ground[i] = geometry[i] && !object[i];
  }
  const auto share = [&](const std::vector<std::uint8_t>& mask) {
    NoiseShare s;
    for (std::uint8_t m : mask) s.pixels += m;
    if (s.pixels > 0) s.relMse = halvesRelMseEstimate(split.a.beauty, split.b.beauty, mask);
    return s;
  };
  split.object = share(object);
  split.ground = share(ground);
  const double total =
      split.object.relMse * double(split.object.pixels) + split.ground.relMse * double(split.ground.pixels);
  for (NoiseShare* s : {&split.object, &split.ground})
    s->share = total > 0.0 ? s->relMse * double(s->pixels) / total : 0.0;
  const std::size_t pixels = split.object.pixels + split.ground.pixels;
  split.relMse = pixels > 0 ? total / double(pixels) : 0.0;
  if (pixels > 0) {
    // By depth: the direct part, and the indirect one as beauty - direct.
    const auto indirectOf = [](const RenderResult& r) {
      Image out = r.beauty;
      for (std::size_t i = 0; i < out.pixelCount(); ++i) out.pixels()[i] -= r.direct.pixels()[i];
      return out;
    };
    const Image indirectA = indirectOf(split.a), indirectB = indirectOf(split.b);
    split.direct = {pixels, halvesPartRelMseEstimate(split.a.direct, split.b.direct, split.a.beauty, split.b.beauty, geometry), 0.0};
    split.indirect = {pixels, halvesPartRelMseEstimate(indirectA, indirectB, split.a.beauty, split.b.beauty, geometry), 0.0};
    const double parts = split.direct.relMse + split.indirect.relMse;
    split.direct.share = parts > 0.0 ? split.direct.relMse / parts : 0.0;
    split.indirect.share = parts > 0.0 ? split.indirect.relMse / parts : 0.0;
    split.geometry = std::move(geometry);
  }
  return split;
}

void writeNoiseSplitJson(const std::filesystem::path& file, const NoiseSplit& split, double halvesMeanFlip) {
  using nlohmann::json;
  const auto share = [](const NoiseShare& s) {
    return json{{"pixels", s.pixels}, {"relMse", s.relMse}, {"share", s.share}};
  };
  const json document = {{"spp", split.mean.samplesPerPixel},
                         {"seconds", split.mean.seconds},
                         {"relMseEstimate", split.relMse},
                         {"halvesMeanFlip", halvesMeanFlip},
                         {"byFirstHit", {{"object", share(split.object)}, {"ground", share(split.ground)}}},
                         {"byDepth", {{"direct", share(split.direct)}, {"indirect", share(split.indirect)}}}};
  writeAtomically(file, [&](const std::filesystem::path& temporary) {
    std::ofstream(temporary) << document.dump(2) << "\n";
  });
}

}  // namespace iblkit
