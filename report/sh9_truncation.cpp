#include "report/sh9_truncation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "bakefile/bake_layout.h"
#include "bakefile/sh9_json.h"
#include "core/environment_sh.h"
#include "core/error.h"
#include "core/latlong.h"
#include "core/scene.h"
#include "core/scene_environment.h"

namespace iblkit {

Image averageLatLongDown(const Image& latLong, int maxWidth) {
  int factor = 1;
  while (latLong.width() / factor > maxWidth && latLong.width() % (2 * factor) == 0 &&
         latLong.height() % (2 * factor) == 0)
    factor *= 2;
  if (factor == 1) return latLong;
  const int width = latLong.width() / factor, height = latLong.height() / factor;
  Image out(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      glm::dvec3 sum(0.0);
      double weight = 0.0;
      for (int j = 0; j < factor; ++j) {
        const int row = y * factor + j;
        const double rowWeight = latLongTexelSolidAngle(latLong.width(), latLong.height(), row);
        for (int i = 0; i < factor; ++i) {
          sum += rowWeight * glm::dvec3(glm::vec3(latLong.at(x * factor + i, row)));
          weight += rowWeight;
        }
      }
      out.at(x, y) = glm::vec4(glm::vec3(sum / weight), 1.0f);
    }
  return out;
}

Sh9Truncation sh9Truncation(const EnvironmentMap& environment, const SphericalHarmonics9& sh, const Image& normals,
                            std::span<const std::uint8_t> mask, int bruteForceWidth) {
  if (mask.size() != normals.pixelCount())
    throw Error("SH9 truncation: mask has " + std::to_string(mask.size()) + " pixels, normals " +
                std::to_string(normals.pixelCount()));
  // Each distinct normal once (a ground plane's pixels share one): pixelDirection[k] indexes directions.
  std::vector<std::size_t> pixels, pixelDirection;
  std::vector<glm::vec3> directions;
  std::map<std::tuple<float, float, float>, std::size_t> seen;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (!mask[i]) continue;
    const glm::vec3 n(normals.pixels()[i]);
    const float length = glm::length(n);
    if (!std::isfinite(length) || length < 0.5f) continue;
    const auto [found, added] = seen.try_emplace({n.x, n.y, n.z}, directions.size());
    if (added) directions.push_back(n / length);
    pixels.push_back(i);
    pixelDirection.push_back(found->second);
  }
  EnvironmentMap coarse =
      EnvironmentMap::fromImage(averageLatLongDown(environment.image(), bruteForceWidth), "SH9 truncation map");
  coarse.setRotationDegrees(environment.rotationDegrees());
  coarse.setIntensity(environment.intensity());
  const std::vector<glm::vec3> exact = bruteForceIrradiance(coarse, directions);
  Sh9Truncation result;
  result.ratio.assign(mask.size(), 1.0f);
  double difference = 0.0, total = 0.0;
  for (std::size_t k = 0; k < pixels.size(); ++k) {
    const std::size_t d = pixelDirection[k];
    const double truth = luminance(exact[d]), approximation = luminance(sh.irradiance(directions[d]));
    difference += std::abs(approximation - truth);
    total += truth;
    if (truth > 0.0) result.ratio[pixels[k]] = float(approximation / truth);
  }
  result.meanRelativeError = total > 0.0 ? difference / total : 0.0;
  return result;
}

double errorBeyondSh9(const Image& reference, const Image& frame, const Sh9Truncation& truncation,
                      std::span<const std::uint8_t> mask, int block) {
  const int width = reference.width(), height = reference.height();
  if (frame.width() != width || frame.height() != height || mask.size() != reference.pixelCount() ||
      truncation.ratio.size() != mask.size())
    throw Error("SH9 truncation: images, mask and ratios differ in size");
  double blocks = 0.0, total = 0.0;
  for (int by = 0; by < height; by += block)
    for (int bx = 0; bx < width; bx += block) {
      double sum = 0.0;
      for (int y = by; y < std::min(by + block, height); ++y)
        for (int x = bx; x < std::min(bx + block, width); ++x) {
          const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
          if (!mask[i]) continue;
          const double ref = luminance(glm::vec3(reference.pixels()[i]));
          sum += luminance(glm::vec3(frame.pixels()[i])) - truncation.ratio[i] * ref;
          total += ref;
        }
      blocks += std::abs(sum);
    }
  return total > 0.0 ? blocks / total : 0.0;
}

Sh9Truncation caseSh9Truncation(const std::filesystem::path& sceneFile,
                                const std::filesystem::path& environmentFile,
                                const std::filesystem::path& bake, const Image& normals,
                                std::span<const std::uint8_t> mask) {
  const EnvironmentMap environment = loadSceneEnvironment(loadScene(sceneFile), environmentFile);
  return sh9Truncation(environment, readSh9Json(bake / kBakeSh9File), normals, mask);
}

}  // namespace iblkit
