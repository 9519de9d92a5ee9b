#include "core/light_probe.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/error.h"
#include "core/latlong.h"

namespace iblkit {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Normalised image coordinates (x right, y up, unit disk inscribed) <-> (u, v) with v down.
glm::vec2 uvFromImagePoint(const glm::vec2& p) { return {0.5f * (p.x + 1.0f), 0.5f * (1.0f - p.y)}; }
glm::vec2 imagePointFromUv(const glm::vec2& uv) { return {2.0f * uv.x - 1.0f, 1.0f - 2.0f * uv.y}; }

const glm::vec2 kRimUv(1.0f, 0.5f);
const glm::vec2 kCentreUv(0.5f, 0.5f);
// The direction seen on the rim of both probes.
const glm::vec3 kBackward(0.0f, 0.0f, -1.0f);

// Bilinear lookup that leaves out taps whose pixel centre lies outside the disk (they show the
// camera's surroundings, not the probe) and renormalises the rest.
glm::vec3 sampleInsideDisk(const Image& probe, const glm::vec2& uv) {
  const int n = probe.width();
  const glm::vec2 p = uv * static_cast<float>(n) - 0.5f;
  const glm::vec2 p0 = glm::floor(p), f = p - p0;
  glm::vec3 sum(0.0f), nearest(0.0f);
  float weightSum = 0.0f, nearestWeight = -1.0f;
  for (int dy = 0; dy < 2; ++dy) {
    for (int dx = 0; dx < 2; ++dx) {
      const int x = static_cast<int>(p0.x) + dx, y = static_cast<int>(p0.y) + dy;
      if (x < 0 || x >= n || y < 0 || y >= n) continue;
      const float weight = (dx ? f.x : 1.0f - f.x) * (dy ? f.y : 1.0f - f.y);
      const glm::vec3 rgb(probe.at(x, y));
      if (weight > nearestWeight) {
        nearestWeight = weight;
        nearest = rgb;
      }
      const glm::vec2 centre = imagePointFromUv((glm::vec2(x, y) + 0.5f) / static_cast<float>(n));
      if (glm::dot(centre, centre) <= 1.0f) {
        sum += weight * rgb;
        weightSum += weight;
      }
    }
  }
  return weightSum > 0.0f ? sum / weightSum : nearest;
}

Image latLongFromProbe(const Image& probe, int width, int samplesPerAxis,
                       const std::filesystem::path& fileForErrors, const std::string& format,
                       glm::vec2 (*probeUv)(const glm::vec3&)) {
  if (probe.empty() || probe.width() != probe.height())
    fail(fileForErrors, format + " is " + std::to_string(probe.width()) + "x" +
                            std::to_string(probe.height()) + ", expected a square image");
  if (width < 2 || width % 2 != 0)
    throw std::invalid_argument("latLongFromProbe: width must be even and >= 2");
  return latLongFromRadiance(width, width / 2, samplesPerAxis, [&probe, probeUv](const glm::vec3& direction) {
    return sampleInsideDisk(probe, probeUv(direction));
  });
}

}  // namespace

glm::vec2 mirrorBallUv(const glm::vec3& direction) {
  const float length = glm::length(direction);
  if (length == 0.0f) return kCentreUv;
  // The ball's normal halves the angle between the reflected direction and the way back to the
  // camera (+Z); its x, y are the image point.
  const glm::vec3 halfway = direction / length + glm::vec3(0.0f, 0.0f, 1.0f);
  const float halfwayLength = glm::length(halfway);
  if (halfwayLength == 0.0f) return kRimUv;
  return uvFromImagePoint(glm::vec2(halfway) / halfwayLength);
}

glm::vec3 mirrorBallDirection(const glm::vec2& uv) {
  const glm::vec2 p = imagePointFromUv(uv);
  const float rSquared = glm::dot(p, p);
  if (rSquared >= 1.0f) return kBackward;
  const float nz = std::sqrt(1.0f - rSquared);
  // reflect((0, 0, -1), n) with n = (p, nz).
  return {2.0f * nz * p.x, 2.0f * nz * p.y, 2.0f * nz * nz - 1.0f};
}

glm::vec2 angularMapUv(const glm::vec3& direction) {
  const float sinThetaScaled = std::hypot(direction.x, direction.y);
  if (sinThetaScaled == 0.0f) return direction.z < 0.0f ? kRimUv : kCentreUv;
  // atan2 rather than acos(d_z): accurate near both poles and free of the direction's length.
  const float theta = std::atan2(sinThetaScaled, direction.z);
  return uvFromImagePoint(glm::vec2(direction.x, direction.y) * (theta / (kPi * sinThetaScaled)));
}

glm::vec3 angularMapDirection(const glm::vec2& uv) {
  const glm::vec2 p = imagePointFromUv(uv);
  const float r = glm::length(p);
  if (r >= 1.0f) return kBackward;
  if (r == 0.0f) return {0.0f, 0.0f, 1.0f};
  const float theta = kPi * r;
  const glm::vec2 xy = p * (std::sin(theta) / r);
  return {xy.x, xy.y, std::cos(theta)};
}

Image latLongFromMirrorBall(const Image& probe, int width, int samplesPerAxis,
                            const std::filesystem::path& fileForErrors) {
  return latLongFromProbe(probe, width, samplesPerAxis, fileForErrors, "mirror-ball probe", mirrorBallUv);
}

Image latLongFromAngularMap(const Image& probe, int width, int samplesPerAxis,
                            const std::filesystem::path& fileForErrors) {
  return latLongFromProbe(probe, width, samplesPerAxis, fileForErrors, "angular map", angularMapUv);
}

}  // namespace iblkit
