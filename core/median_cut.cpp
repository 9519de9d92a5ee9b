// medianCutLights (core/environment_lights.h): Debevec, "A Median Cut Algorithm for Light Probe
// Sampling", SIGGRAPH 2005 poster. docs/dominant-lights.md, "Median cut".
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/environment_lights.h"
#include "core/latlong.h"

namespace iblkit {

namespace {

struct Rectangle {
  int x0, y0, x1, y1;  // texels [x0, x1) x [y0, y1)
};

// Summed-area table of the texel energies (luminance x solid angle, intensity applied) in double:
// at(x, y) is the energy of the texels [0, x) x [0, y), so any rectangle's energy is four lookups
// (Crow 1984, "Summed-Area Tables for Texture Mapping").
class EnergyTable {
 public:
  explicit EnergyTable(const EnvironmentMap& map)
      : width_(map.width()), sums_(stride() * (map.height() + 1), 0.0) {
    for (int y = 0; y < map.height(); ++y) {
      const double solidAngle = map.texelSolidAngle(y);
      double row = 0.0;
      for (int x = 0; x < width_; ++x) {
        row += static_cast<double>(map.texelLuminance(x, y)) * solidAngle;
        sums_[index(x + 1, y + 1)] = sums_[index(x + 1, y)] + row;
      }
    }
  }
  double energy(int x0, int y0, int x1, int y1) const {
    return sums_[index(x1, y1)] - sums_[index(x0, y1)] - sums_[index(x1, y0)] + sums_[index(x0, y0)];
  }
  double energy(const Rectangle& r) const { return energy(r.x0, r.y0, r.x1, r.y1); }

 private:
  std::size_t stride() const { return static_cast<std::size_t>(width_) + 1; }
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * stride() + static_cast<std::size_t>(x);
  }
  int width_;
  std::vector<double> sums_;
};

// The cut position k in (lo, hi) whose first part [lo, k) holds the energy closest to half the
// region's: the energy of [lo, k) rises with k, so a binary search finds the first k at or above
// the half and the one before it is the other candidate (each an O(1) table lookup). A black region
// has no median: it is cut in the middle.
template <class EnergyBefore>
int medianCut(int lo, int hi, double total, const EnergyBefore& energyBefore) {
  if (!(total > 0.0)) return lo + (hi - lo) / 2;
  const double half = 0.5 * total;
  int first = lo + 1, last = hi - 1;  // search [first, last] for the first k with energyBefore(k) >= half
  while (first < last) {
    const int mid = first + (last - first) / 2;
    if (energyBefore(mid) >= half)
      last = mid;
    else
      first = mid + 1;
  }
  int k = first;
  if (k > lo + 1 && std::abs(energyBefore(k - 1) - half) <= std::abs(energyBefore(k) - half)) --k;
  return k;
}

// Splits r in two along its longer side measured in solid angle: its angular width scaled by the
// cosine of the latitude at its centre (a lat-long texel row shrinks by cos(latitude)) against its
// angular height. A side of one texel cannot be cut, so the other is.
bool split(const Rectangle& r, const EnergyTable& table, int width, int height, Rectangle* a, Rectangle* b) {
  const int columns = r.x1 - r.x0, rows = r.y1 - r.y0;
  if (columns <= 1 && rows <= 1) return false;
  const double pi = std::numbers::pi;
  const double centreLatitude = pi * (0.5 - 0.5 * (r.y0 + r.y1) / height);
  const double angularWidth = columns * (2.0 * pi / width) * std::cos(centreLatitude);
  const double angularHeight = rows * (pi / height);
  const bool cutColumns = rows <= 1 || (columns > 1 && angularWidth > angularHeight);
  const double total = table.energy(r);
  *a = r;
  *b = r;
  if (cutColumns) {
    const int k = medianCut(r.x0, r.x1, total, [&](int x) { return table.energy(r.x0, r.y0, x, r.y1); });
    a->x1 = k;
    b->x0 = k;
  } else {
    const int k = medianCut(r.y0, r.y1, total, [&](int y) { return table.energy(r.x0, r.y0, r.x1, y); });
    a->y1 = k;
    b->y0 = k;
  }
  return true;
}

// The light of one region: sums over its texels in double (its energy centroid, irradiance and
// solid angle), its SH9 summed row by row like projectEnvironmentSh9.
EnvironmentLight regionLight(const EnvironmentMap& map, const Rectangle& r) {
  glm::dvec3 centroid(0.0), irradiance(0.0);
  double solidAngle = 0.0, energy = 0.0;
  EnvironmentLight light;
  light.kind = EnvironmentLightKind::MedianCut;
  for (int y = r.y0; y < r.y1; ++y) {
    const float texelSolidAngle = map.texelSolidAngle(y);
    SphericalHarmonics9 row;
    for (int x = r.x0; x < r.x1; ++x) {
      const glm::vec3 radiance = map.texelRadiance(x, y);
      const glm::vec3 direction = map.texelDirection(x, y);
      const double texelEnergy = static_cast<double>(luminance(radiance)) * texelSolidAngle;
      centroid += glm::dvec3(direction) * texelEnergy;
      irradiance += glm::dvec3(radiance) * static_cast<double>(texelSolidAngle);
      energy += texelEnergy;
      row.accumulate(direction, radiance, texelSolidAngle);
    }
    solidAngle += static_cast<double>(texelSolidAngle) * (r.x1 - r.x0);
    light.sh9 += row;
  }
  // A black region, or one so symmetric that its centroid vanishes (the whole sphere at levels 0),
  // points at its rectangle's centre.
  if (glm::length(centroid) > 1e-3 * energy && energy > 0.0) {
    light.direction = glm::vec3(glm::normalize(centroid));
  } else {
    const glm::vec2 centre(0.5f * static_cast<float>(r.x0 + r.x1) / static_cast<float>(map.width()),
                           0.5f * static_cast<float>(r.y0 + r.y1) / static_cast<float>(map.height()));
    light.direction = map.toWorldDirection(latLongDirection(centre));
  }
  light.irradiance = glm::vec3(irradiance);
  light.solidAngle = static_cast<float>(solidAngle);
  // 2 pi (1 - cos r) = solidAngle.
  light.angularRadius =
      static_cast<float>(std::acos(std::clamp(1.0 - solidAngle / (2.0 * std::numbers::pi), -1.0, 1.0)));
  light.radiance = solidAngle > 0.0 ? glm::vec3(irradiance / solidAngle) : glm::vec3(0.0f);
  light.x0 = r.x0;
  light.y0 = r.y0;
  light.x1 = r.x1;
  light.y1 = r.y1;
  return light;
}

}  // namespace

std::vector<EnvironmentLight> medianCutLights(const EnvironmentMap& map, int levels) {
  if (levels < 0 || levels > 12)
    throw std::invalid_argument("medianCutLights: levels must be in 0..12, not " + std::to_string(levels));
  const EnergyTable table(map);
  // Every level cuts every region (Debevec's 2^n regions); a region's two halves take its place in
  // the list, so the order depends only on the map.
  std::vector<Rectangle> regions{{0, 0, map.width(), map.height()}};
  for (int level = 0; level < levels; ++level) {
    std::vector<Rectangle> next;
    next.reserve(2 * regions.size());
    for (const Rectangle& r : regions) {
      Rectangle a{}, b{};
      if (split(r, table, map.width(), map.height(), &a, &b)) {
        next.push_back(a);
        next.push_back(b);
      } else {
        next.push_back(r);
      }
    }
    regions = std::move(next);
  }
  std::vector<EnvironmentLight> lights(regions.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, regions.size()),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i)
                        lights[i] = regionLight(map, regions[i]);
                    });
  return lights;
}

}  // namespace iblkit
