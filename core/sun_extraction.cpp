// extractSuns and automaticSunThreshold (core/environment_lights.h, docs/dominant-lights.md).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/gtc/constants.hpp>
#include <numeric>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include "core/environment_lights.h"

namespace iblkit {
namespace {

// Union-find over indices (path halving, union by index: the smaller index is the root, so
// the labelling does not depend on the order of the unions).
class TexelRegions {
 public:
  explicit TexelRegions(std::size_t count) : parent_(count) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::size_t root(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void join(std::size_t a, std::size_t b) {
    a = root(a);
    b = root(b);
    if (a < b) parent_[b] = a;
    if (b < a) parent_[a] = b;
  }

 private:
  std::vector<std::size_t> parent_;
};

struct Region {
  std::vector<std::size_t> texels;  // y * width + x
  double energy = 0.0;              // luminance of the light's irradiance
};

// The shortest run of columns (wrapping) holding every column in `used` (sorted, unique): starts
// after the widest gap between consecutive used columns. Returns [x0, x1), x1 may exceed width.
std::pair<int, int> wrappedColumnSpan(const std::vector<int>& used, int width) {
  if (int(used.size()) == width) return {0, width};
  int widestGap = -1, start = used.front();
  for (std::size_t i = 0; i < used.size(); ++i) {
    const int next = i + 1 < used.size() ? used[i + 1] : used.front() + width;
    const int gap = next - used[i] - 1;
    if (gap > widestGap) {
      widestGap = gap;
      start = next % width;
    }
  }
  return {start, start + width - widestGap};
}

// What the residual keeps of a texel above the threshold (stored units, intensity not applied).
glm::vec3 residualPart(const EnvironmentMap& map, int x, int y, float threshold) {
  return glm::vec3(map.image().at(x, y)) * (threshold / map.texelLuminance(x, y));
}

// The light a region's texels make.
EnvironmentLight regionLight(const EnvironmentMap& map, const Region& region, float threshold) {
  const int width = map.width();
  EnvironmentLight light;
  light.kind = EnvironmentLightKind::Sun;
  glm::dvec3 centroid(0.0), irradiance(0.0);
  double energy = 0.0, texelSpread = 0.0;  // sums of luminance x solid angle, and x solid angle^2
  std::vector<int> columns;
  light.y0 = map.height();
  light.y1 = 0;
  glm::vec3 brightestDirection(0.0f, 1.0f, 0.0f);
  float brightest = -1.0f;
  for (const std::size_t index : region.texels) {
    const int x = int(index % std::size_t(width)), y = int(index / std::size_t(width));
    const float lum = map.texelLuminance(x, y);
    // The light's part is what the residual does not keep, so the two add up to the texel.
    const glm::vec3 carried =
        map.intensity() * (glm::vec3(map.image().at(x, y)) - residualPart(map, x, y, threshold));
    const float dOmega = map.texelSolidAngle(y);
    const glm::vec3 direction = map.texelDirection(x, y);
    // Unit to double precision, so that a single texel's centroid has length 1 (spread 0).
    const glm::dvec3 unit = glm::normalize(glm::dvec3(direction));
    irradiance += glm::dvec3(carried) * double(dOmega);
    const double weight = double(luminance(carried)) * dOmega;
    centroid += unit * weight;
    energy += weight;
    texelSpread += weight * dOmega;
    light.sh9.accumulate(direction, carried, dOmega);
    columns.push_back(x);
    light.y0 = std::min(light.y0, y);
    light.y1 = std::max(light.y1, y + 1);
    if (lum > brightest) {
      brightest = lum;
      brightestDirection = direction;
    }
  }
  // A region symmetric about the centre of the sphere (a band all around) has no centroid: its
  // brightest texel stands for it.
  const double length = glm::length(centroid);
  light.direction = length > 1e-6 * energy ? glm::vec3(centroid / length) : brightestDirection;
  light.irradiance = glm::vec3(irradiance);
  // The disk of the same spread: a uniform disk of solid angle W has mean cosine to its centre
  // 1 - W / (4 pi), so W = 4 pi (1 - |centroid| / energy) for the spread of the texel centres, plus
  // the energy-weighted mean solid angle of a texel for the spread within each texel (second
  // moments add). A single texel gives its own solid angle.
  const double pi = glm::pi<double>();
  const double solidAngle =
      std::min(4.0 * pi * std::max(0.0, 1.0 - length / energy) + texelSpread / energy, 4.0 * pi);
  light.solidAngle = float(solidAngle);
  light.angularRadius = float(std::acos(std::clamp(1.0 - solidAngle / (2.0 * pi), -1.0, 1.0)));
  light.radiance = light.irradiance / light.solidAngle;
  std::sort(columns.begin(), columns.end());
  columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
  std::tie(light.x0, light.x1) = wrappedColumnSpan(columns, width);
  return light;
}

}  // namespace

float automaticSunThreshold(const EnvironmentMap& map, float peakToMean) {
  if (!(peakToMean >= 1.0f)) throw std::invalid_argument("automaticSunThreshold: peakToMean must be >= 1");
  const int width = map.width(), height = map.height();
  const std::size_t count = std::size_t(width) * std::size_t(height);
  // The luminances' histogram by the top 16 bits of their float (the order of non-negative floats
  // is their bits' order), for the cutoffs below.
  std::vector<std::size_t> histogram(std::size_t(1) << 16, 0);
  const auto bucket = [](float lum) { return std::bit_cast<std::uint32_t>(lum > 0.0f ? lum : 0.0f) >> 16; };
  double lit = 0.0, sphere = 0.0;  // sum of luminance x solid angle; the solid angle (4 pi)
  float brightest = 0.0f;
  for (int y = 0; y < height; ++y) {
    const float dOmega = map.texelSolidAngle(y);
    for (int x = 0; x < width; ++x) {
      const float lum = map.texelLuminance(x, y);
      ++histogram[bucket(lum)];
      lit += double(lum) * dOmega;
      sphere += dOmega;
      brightest = std::max(brightest, lum);
    }
  }
  const double k = peakToMean;
  if (k * lit / sphere >= double(brightest)) return float(k * lit / sphere);
  // g(t) = k mean(min(lum, t)) - t is concave with g(0) = 0, so g >= 0 exactly on [0, t*]. Between
  // the i-th and (i+1)-th brightest luminance, mean(min(lum, t)) = (below + t above) / sphere with
  // `above` the solid angle of the i brightest texels and `below` the energy of the others: g is
  // linear there and its root t = k below / (sphere - k above). The largest root is in the first
  // interval (from the top) that holds its own root.
  // The walk needs the texels brightest first only down to that interval, which on a sunny map
  // lies just below the sun's texels (thousands of the 134 million of a 16384 x 8192 map, whose
  // full sort was most of the lights' stage). So it takes the texels at or above a cutoff, the
  // lowest edge of the histogram's buckets that holds `wanted` of them, sorted; past them it takes
  // 16 times as many, and at last all. Every texel it leaves out is below every one it takes: the
  // walk over those it takes is the walk over all of them, as far as it goes.
  std::vector<std::pair<float, float>> texels;  // (luminance, solid angle), brightest first
  for (std::size_t wanted = std::size_t(1) << 16;; wanted *= 16) {
    std::uint32_t first = 0;  // the lowest bucket taken
    if (wanted < count) {
      std::size_t taken = 0;
      for (first = std::uint32_t(histogram.size()); first > 0 && taken < wanted;) taken += histogram[--first];
    }
    texels.clear();
    for (int y = 0; y < height; ++y) {
      const float dOmega = map.texelSolidAngle(y);
      for (int x = 0; x < width; ++x) {
        const float lum = map.texelLuminance(x, y);
        if (bucket(lum) >= first) texels.emplace_back(lum, dOmega);
      }
    }
    const bool all = texels.size() == count;
    std::sort(texels.begin(), texels.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    double above = 0.0, below = lit;
    for (std::size_t i = 0; i < texels.size(); ++i) {
      // t in [texels[i].first, previous luminance]: texels 0..i-1 above t.
      const double upper = i == 0 ? INFINITY : double(texels[i - 1].first);
      const double lower = texels[i].first;
      const double denominator = sphere - k * above;
      if (denominator <= 0.0) return 0.0f;  // g falls for every t below: the root is 0
      const double root = k * below / denominator;
      if (root >= lower && root <= upper) return float(root);
      above += texels[i].second;
      below -= double(texels[i].first) * texels[i].second;
      below = std::max(below, 0.0);
    }
    if (all) return 0.0f;
  }
}

ExtractedSuns extractSuns(const EnvironmentMap& map, const SunExtractionOptions& options) {
  if (!std::isfinite(options.threshold)) throw std::invalid_argument("extractSuns: threshold must be finite");
  if (options.maxLights < 0) throw std::invalid_argument("extractSuns: maxLights must be >= 0");
  if (!(options.minEnergyFraction >= 0.0f && options.minEnergyFraction <= 1.0f))
    throw std::invalid_argument("extractSuns: minEnergyFraction must be in [0, 1]");
  if (!(options.maxAngularRadius >= 0.0f))
    throw std::invalid_argument("extractSuns: maxAngularRadius must be >= 0");
  ExtractedSuns result;
  result.threshold =
      options.threshold > 0.0f ? options.threshold : automaticSunThreshold(map, options.peakToMean);
  if (options.residualImage) result.residual = map.image();
  const int width = map.width(), height = map.height();
  // The texels above the threshold, in index order (y * width + x), and where each row starts:
  // the regions are found among them alone, so the tables grow with the bright texels, not with
  // the map (a 16384 x 8192 map held two 8-byte tables per texel, 2 GiB).
  std::vector<std::size_t> aboveTexels;
  std::vector<std::size_t> rowStart(std::size_t(height) + 1, 0);
  double mapEnergy = 0.0;
  for (int y = 0; y < height; ++y) {
    rowStart[std::size_t(y)] = aboveTexels.size();
    const float dOmega = map.texelSolidAngle(y);
    for (int x = 0; x < width; ++x) {
      const float lum = map.texelLuminance(x, y);
      if (lum > result.threshold) aboveTexels.push_back(std::size_t(y) * std::size_t(width) + std::size_t(x));
      mapEnergy += double(lum) * dOmega;
    }
  }
  rowStart[std::size_t(height)] = aboveTexels.size();
  // The position in aboveTexels of texel (x, y), or none when it is not above.
  constexpr std::size_t kNone = ~std::size_t(0);
  auto above = [&](int x, int y) {
    const auto first = aboveTexels.begin() + std::ptrdiff_t(rowStart[std::size_t(y)]);
    const auto last = aboveTexels.begin() + std::ptrdiff_t(rowStart[std::size_t(y) + 1]);
    const std::size_t texel = std::size_t(y) * std::size_t(width) + std::size_t(x);
    const auto found = std::lower_bound(first, last, texel);
    return found != last && *found == texel ? std::size_t(found - aboveTexels.begin()) : kNone;
  };
  // Positions keep the texels' order, so the smaller position is the smaller texel index: the
  // union-find's roots, and so the regions and their order, are those of one over all texels.
  TexelRegions regions(aboveTexels.size());
  for (std::size_t i = 0; i < aboveTexels.size(); ++i) {
    const int x = int(aboveTexels[i] % std::size_t(width)), y = int(aboveTexels[i] / std::size_t(width));
    // Half of the 8 neighbours (the other half joins from their side), longitude wrapping.
    const int right = (x + 1) % width;
    if (const std::size_t j = above(right, y); j != kNone) regions.join(i, j);
    if (y + 1 < height)
      for (const int nx : {(x + width - 1) % width, x, right})
        if (const std::size_t j = above(nx, y + 1); j != kNone) regions.join(i, j);
  }
  // The texels of the top row all touch at the pole (+Y), those of the bottom row at -Y.
  for (const int y : {0, height - 1})
    for (std::size_t i = rowStart[std::size_t(y)]; i < rowStart[std::size_t(y) + 1]; ++i)
      regions.join(rowStart[std::size_t(y)], i);
  std::vector<Region> found;
  std::vector<std::size_t> regionOfRoot(aboveTexels.size(), kNone);
  for (std::size_t i = 0; i < aboveTexels.size(); ++i) {
    const std::size_t root = regions.root(i);
    if (regionOfRoot[root] == kNone) {
      regionOfRoot[root] = found.size();
      found.emplace_back();
    }
    Region& region = found[regionOfRoot[root]];
    const std::size_t texel = aboveTexels[i];
    region.texels.push_back(texel);
    const int x = int(texel % std::size_t(width)), y = int(texel / std::size_t(width));
    region.energy += double(map.texelLuminance(x, y) - result.threshold) * map.texelSolidAngle(y);
  }
  // Brightest first; ties by first texel, so the order is the same on every run.
  std::stable_sort(found.begin(), found.end(),
                   [](const Region& a, const Region& b) { return a.energy > b.energy; });
  for (const Region& region : found) {
    if (int(result.suns.size()) >= options.maxLights) break;
    if (region.energy < double(options.minEnergyFraction) * mapEnergy || region.energy <= 0.0) break;
    EnvironmentLight light = regionLight(map, region, result.threshold);
    if (light.angularRadius > options.maxAngularRadius) continue;  // no sun: it stays in the residual
    for (const std::size_t i : region.texels) {
      const int x = int(i % std::size_t(width)), y = int(i / std::size_t(width));
      const glm::vec4 residual(residualPart(map, x, y, result.threshold), map.image().at(x, y).a);
      result.residualTexels.emplace_back(i, residual);
      if (options.residualImage) result.residual.at(x, y) = residual;
    }
    result.suns.push_back(std::move(light));
  }
  return result;
}

}  // namespace iblkit
