#include "core/latlong.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "core/fast_atan2.h"

namespace iblkit {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

bool isFinite(const glm::vec2& uv) { return std::isfinite(uv.x) && std::isfinite(uv.y); }

glm::vec3 notANumber() { return glm::vec3(std::numeric_limits<float>::quiet_NaN()); }

// u reduced to [0, 1] (1 only when a tiny negative u rounds up), so that u * width is a safe int.
float wrapUnit(float u) { return u - std::floor(u); }

}  // namespace

glm::vec2 latLongUv(const glm::vec3& direction) {
  const float longitude = fastAtan2(direction.x, direction.z);
  const float latitude = fastAtan2(direction.y, std::hypot(direction.x, direction.z));
  return {0.5f - longitude / (2.0f * kPi), 0.5f - latitude / kPi};
}

glm::vec2 latLongLongitude(float u) {
  const float longitude = 2.0f * kPi * (0.5f - u);
  return {std::sin(longitude), std::cos(longitude)};
}

glm::vec2 latLongLatitude(float v) {
  const float latitude = kPi * (0.5f - v);
  return {std::cos(latitude), std::sin(latitude)};
}

glm::vec3 latLongDirection(const glm::vec2& uv) {
  return latLongDirection(latLongLongitude(uv.x), latLongLatitude(uv.y));
}

float latLongTexelSolidAngle(int width, int height, int y) {
  const double pi = std::numbers::pi;
  const double latitudeTop = pi * (0.5 - double(y) / height);
  const double latitudeBottom = pi * (0.5 - double(y + 1) / height);
  return static_cast<float>(2.0 * pi / width * (std::sin(latitudeTop) - std::sin(latitudeBottom)));
}

glm::vec3 sampleLatLongBilinear(const Image& latLong, const glm::vec2& uv) {
  if (!isFinite(uv)) return notANumber();
  const int w = latLong.width(), h = latLong.height();
  // Continuous texel coordinates: texel centres sit at integers.
  const float px = wrapUnit(uv.x) * static_cast<float>(w) - 0.5f;
  const float py = std::clamp(uv.y, 0.0f, 1.0f) * static_cast<float>(h) - 0.5f;
  const float floorX = std::floor(px), floorY = std::floor(py);
  const float fx = px - floorX, fy = py - floorY;
  // floorX is in [-1, w - 1]: wrap the two columns without an integer division.
  const int ix = static_cast<int>(floorX);
  const int x0 = ix < 0 ? w - 1 : ix, x1 = ix + 1 >= w ? 0 : ix + 1;
  const int y0 = std::max(static_cast<int>(floorY), 0), y1 = std::min(static_cast<int>(floorY) + 1, h - 1);
  const glm::vec3 top = glm::mix(glm::vec3(latLong.at(x0, y0)), glm::vec3(latLong.at(x1, y0)), fx);
  const glm::vec3 bottom = glm::mix(glm::vec3(latLong.at(x0, y1)), glm::vec3(latLong.at(x1, y1)), fx);
  return glm::mix(top, bottom, fy);
}

glm::vec3 sampleLatLongNearest(const Image& latLong, const glm::vec2& uv) {
  if (!isFinite(uv)) return notANumber();
  const int w = latLong.width(), h = latLong.height();
  // wrapUnit(u) * w can round up to w; the modulo folds it back onto column 0.
  const int x = static_cast<int>(wrapUnit(uv.x) * static_cast<float>(w)) % w;
  const int y = std::min(static_cast<int>(std::clamp(uv.y, 0.0f, 1.0f) * static_cast<float>(h)), h - 1);
  return glm::vec3(latLong.at(x, y));
}

Image latLongFromRadiance(int width, int height, int samplesPerAxis, const RadianceFunction& radiance) {
  if (width < 1 || height < 1 || samplesPerAxis < 1)
    throw std::invalid_argument("latLongFromRadiance: width, height and samplesPerAxis must be >= 1");
  Image image(width, height);
  const float n = static_cast<float>(samplesPerAxis);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      glm::vec3 sum(0.0f);
      float weightSum = 0.0f;
      for (int j = 0; j < samplesPerAxis; ++j) {
        for (int i = 0; i < samplesPerAxis; ++i) {
          const glm::vec2 uv = (glm::vec2(x, y) + (glm::vec2(i, j) + 0.5f) / n) / glm::vec2(width, height);
          const float weight = std::cos(kPi * (0.5f - uv.y));
          sum += weight * radiance(latLongDirection(uv));
          weightSum += weight;
        }
      }
      image.at(x, y) = glm::vec4(sum / weightSum, 1.0f);
    }
  }
  return image;
}

}  // namespace iblkit
