#include "core/energy_preserving_repair.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <vector>

#include "core/latlong.h"

namespace iblkit {

namespace {

// The window radii tried in turn, each about 1.5 times the last (a ring of DWAB overshoot is a
// few texels wide: the sun itself pays at radius 2 or 3).
constexpr std::array<int, 8> kRepairRadii = {1, 2, 3, 4, 6, 8, 12, kMaxRepairRadius};

// The columns of a window of `radius` around column x, wrapping in longitude, each column once
// (a window wider than the map is the whole row).
std::vector<int> windowColumns(int x, int radius, int width) {
  std::vector<int> columns;
  if (2 * radius + 1 >= width) {
    for (int c = 0; c < width; ++c) columns.push_back(c);
    return columns;
  }
  for (int dx = -radius; dx <= radius; ++dx) columns.push_back(((x + dx) % width + width) % width);
  return columns;
}

// The energy of channel c's positive values in the window (columns x rows y0..y1).
double positiveEnergy(const Image& image, int c, const std::vector<int>& columns, int y0, int y1,
                      const std::vector<double>& solidAngle) {
  double energy = 0.0;
  for (int y = y0; y <= y1; ++y) {
    double row = 0.0;
    for (int x : columns) row += std::max(0.0f, image.at(x, y)[c]);
    energy += row * solidAngle[static_cast<std::size_t>(y)];
  }
  return energy;
}

// Scales channel c's positive values in the window by `factor` (in [0, 1]).
void scalePositive(Image& image, int c, const std::vector<int>& columns, int y0, int y1, double factor) {
  for (int y = y0; y <= y1; ++y)
    for (int x : columns) {
      float& value = image.at(x, y)[c];
      if (value > 0.0f) value = static_cast<float>(value * factor);
    }
}

}  // namespace

NegativeRadianceRepair repairNegativeRadiance(Image& latLong) {
  NegativeRadianceRepair repair;
  const int width = latLong.width(), height = latLong.height();
  std::vector<double> solidAngle(static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y)
    solidAngle[static_cast<std::size_t>(y)] = latLongTexelSolidAngle(width, height, y);
  for (glm::vec4& pixel : latLong.pixels())
    if (pixel.a < 0.0f) {
      pixel.a = 0.0f;
      ++repair.negativeValues;
    }
  for (int c = 0; c < 3; ++c) {
    double positive = 0.0, negative = 0.0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const double energy = latLong.at(x, y)[c] * solidAngle[static_cast<std::size_t>(y)];
        (energy > 0.0 ? positive : negative) += energy;
      }
    repair.signedEnergy[c] = positive + negative;
    repair.negativeEnergy[c] = negative;
    if (negative == 0.0) continue;
    if (positive + negative <= 0.0) {
      // More negative than positive energy: no non-negative map has this integral.
      repair.energyKept = false;
      for (glm::vec4& pixel : latLong.pixels())
        if (pixel[c] < 0.0f) {
          pixel[c] = 0.0f;
          ++repair.negativeValues;
        }
      continue;
    }
    double unpaid = 0.0;  // debts of the whole map, paid at the end
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        float& value = latLong.at(x, y)[c];
        if (value >= 0.0f) continue;
        ++repair.negativeValues;
        const double debt = -static_cast<double>(value) * solidAngle[static_cast<std::size_t>(y)];
        value = 0.0f;
        bool paid = false;
        for (int radius : kRepairRadii) {
          const std::vector<int> columns = windowColumns(x, radius, width);
          const int y0 = std::max(0, y - radius), y1 = std::min(height - 1, y + radius);
          const double pool = positiveEnergy(latLong, c, columns, y0, y1, solidAngle);
          if (pool < debt) continue;
          scalePositive(latLong, c, columns, y0, y1, 1.0 - debt / pool);
          repair.largestRadius = std::max(repair.largestRadius, radius);
          paid = true;
          break;
        }
        if (!paid) {
          unpaid += debt;
          ++repair.paidByWholeMap;
        }
      }
    if (unpaid > 0.0) {
      std::vector<int> columns(static_cast<std::size_t>(width));
      for (int x = 0; x < width; ++x) columns[static_cast<std::size_t>(x)] = x;
      const double pool = positiveEnergy(latLong, c, columns, 0, height - 1, solidAngle);
      scalePositive(latLong, c, columns, 0, height - 1, std::max(0.0, 1.0 - unpaid / pool));
    }
  }
  return repair;
}

std::string environmentRepairSummary(const PixelRepairCounts& nonFinite,
                                     const NegativeRadianceRepair& negative) {
  PixelRepairCounts counts = nonFinite;
  counts.negative = negative.negativeValues;
  std::string summary = pixelRepairSummary(counts);
  const glm::vec3 weights(0.2126f, 0.7152f, 0.0722f);  // luminance(), in double
  const double negativeLuminance = glm::dot(negative.negativeEnergy, glm::dvec3(weights));
  if (negativeLuminance == 0.0) return summary;
  if (!negative.energyKept)
    return summary + "; the map's energy is not kept (its negative values outweigh the positive ones)";
  const double total = glm::dot(negative.signedEnergy, glm::dvec3(weights));
  char percent[32];
  std::snprintf(percent, sizeof percent, "%.3g%%", 100.0 * negativeLuminance / total);
  summary += "; the negative values' " + std::string(percent) +
             " of the map's energy (luminance) taken from positive texels";
  if (negative.largestRadius > 0) {
    summary += " within " + std::to_string(negative.largestRadius) +
               (negative.largestRadius == 1 ? " texel" : " texels");
    if (negative.paidByWholeMap > 0)
      summary += " and, for " + std::to_string(negative.paidByWholeMap) + ", from the whole map";
  } else {
    summary += " of the whole map";
  }
  return summary;
}

}  // namespace iblkit
