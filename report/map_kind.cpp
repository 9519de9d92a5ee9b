#include "report/map_kind.h"

#include <algorithm>
#include <numbers>
#include <vector>

namespace iblkit {

namespace {

struct TexelEnergy {
  float luminance;
  float solidAngle;
};

std::vector<TexelEnergy> texelsBrightestFirst(const EnvironmentMap& map) {
  std::vector<TexelEnergy> texels;
  texels.reserve(std::size_t(map.width()) * std::size_t(map.height()));
  for (int y = 0; y < map.height(); ++y) {
    const float solidAngle = map.texelSolidAngle(y);
    for (int x = 0; x < map.width(); ++x) texels.push_back({map.texelLuminance(x, y), solidAngle});
  }
  std::sort(texels.begin(), texels.end(),
            [](const TexelEnergy& a, const TexelEnergy& b) { return a.luminance > b.luminance; });
  return texels;
}

double shareOf(const std::vector<TexelEnergy>& texels, double total, double sphereFraction) {
  if (!(total > 0.0)) return 0.0;
  double solidAngleLeft = sphereFraction * 4.0 * std::numbers::pi, energy = 0.0;
  for (const TexelEnergy& texel : texels) {
    if (solidAngleLeft <= 0.0) break;
    const double taken = std::min<double>(texel.solidAngle, solidAngleLeft);
    energy += double(texel.luminance) * taken;
    solidAngleLeft -= taken;
  }
  return std::min(1.0, energy / total);
}

double totalEnergy(const std::vector<TexelEnergy>& texels) {
  double total = 0.0;
  for (const TexelEnergy& texel : texels) total += double(texel.luminance) * texel.solidAngle;
  return total;
}

}  // namespace

double brightestEnergyShare(const EnvironmentMap& map, double sphereFraction) {
  const std::vector<TexelEnergy> texels = texelsBrightestFirst(map);
  return shareOf(texels, totalEnergy(texels), sphereFraction);
}

MapConcentration mapConcentration(const EnvironmentMap& map) {
  const std::vector<TexelEnergy> texels = texelsBrightestFirst(map);
  const double total = totalEnergy(texels);
  return {shareOf(texels, total, kSunSolidAngleFraction), shareOf(texels, total, kSourceSolidAngleFraction)};
}

MapKind classifyMap(const MapConcentration& concentration) {
  if (concentration.sunShare >= kSunnyShare) return MapKind::Sunny;
  if (concentration.sourceShare >= kStudioShare) return MapKind::Studio;
  return MapKind::Soft;
}

std::string_view mapKindName(MapKind kind) { return enumNameOf(kMapKindNames, kind); }

}  // namespace iblkit
