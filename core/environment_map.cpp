#include "core/environment_map.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/error.h"
#include "core/latlong.h"

namespace iblkit {
namespace {

std::string sizeText(const Image& image) {
  return std::to_string(image.width()) + "x" + std::to_string(image.height());
}

bool isValidRadiance(const glm::vec4& pixel) {
  for (int c = 0; c < 3; ++c)
    if (!(pixel[c] >= 0.0f && pixel[c] <= EnvironmentMap::kMaxRadiance)) return false;
  return true;
}

void checkMapWidth(int width) {
  if (width < 2 || width % 2 != 0) throw std::invalid_argument("EnvironmentMap: width must be even and >= 2");
}

}  // namespace

EnvironmentMap EnvironmentMap::fromImage(Image latLong, const std::filesystem::path& fileForErrors) {
  if (latLong.empty())
    fail(fileForErrors, "lat-long map is " + sizeText(latLong) + ", expected at least 2x1");
  if (latLong.width() != 2 * latLong.height())
    fail(fileForErrors, "lat-long map is " + sizeText(latLong) + ", expected a 2:1 aspect ratio");
  std::size_t invalid = 0;
  for (const glm::vec4& pixel : latLong.pixels()) invalid += isValidRadiance(pixel) ? 0 : 1;
  if (invalid > 0)
    fail(fileForErrors,
         "lat-long map has " + std::to_string(invalid) + " pixels that are NaN, infinite, negative or above 1e18");
  return EnvironmentMap(std::move(latLong));
}

float EnvironmentMap::brightestTexel() const {
  float brightest = 0.0f;
  for (const glm::vec4& pixel : image_.pixels()) brightest = std::max({brightest, pixel.r, pixel.g, pixel.b});
  return brightest;
}

EnvironmentMap EnvironmentMap::constant(const glm::vec3& radiance, int width) {
  checkMapWidth(width);
  return EnvironmentMap(Image(width, width / 2, glm::vec4(radiance, 1.0f)));
}

EnvironmentMap EnvironmentMap::hotPixel(int width, int x, int y, const glm::vec3& radiance) {
  checkMapWidth(width);
  if (x < 0 || x >= width || y < 0 || y >= width / 2)
    throw std::invalid_argument("EnvironmentMap::hotPixel: texel outside the map");
  Image image(width, width / 2);
  image.at(x, y) = glm::vec4(radiance, 1.0f);
  return EnvironmentMap(std::move(image));
}

void EnvironmentMap::setRotationDegrees(float degrees) {
  if (!std::isfinite(degrees)) throw std::invalid_argument("EnvironmentMap: rotation must be finite");
  rotationDegrees_ = degrees;
  // In double so that multiples of 90 degrees give cos/sin that round to exact 0 and +-1.
  const double radians = static_cast<double>(degrees) * std::numbers::pi / 180.0;
  cosRotation_ = static_cast<float>(std::cos(radians));
  sinRotation_ = static_cast<float>(std::sin(radians));
}

void EnvironmentMap::setIntensity(float intensity) {
  if (!std::isfinite(intensity) || intensity < 0.0f)
    throw std::invalid_argument("EnvironmentMap: intensity must be finite and >= 0");
  intensity_ = intensity;
}

glm::vec3 EnvironmentMap::toMapDirection(const glm::vec3& d) const {
  // R_y(-rotation)
  return {cosRotation_ * d.x - sinRotation_ * d.z, d.y, sinRotation_ * d.x + cosRotation_ * d.z};
}

glm::vec3 EnvironmentMap::toWorldDirection(const glm::vec3& d) const {
  // R_y(rotation): x' = x cos + z sin, z' = -x sin + z cos.
  return {cosRotation_ * d.x + sinRotation_ * d.z, d.y, -sinRotation_ * d.x + cosRotation_ * d.z};
}

glm::vec3 EnvironmentMap::radiance(const glm::vec3& worldDirection) const {
  return intensity_ * sampleLatLongBilinear(image_, latLongUv(toMapDirection(worldDirection)));
}

glm::vec3 EnvironmentMap::radianceNearest(const glm::vec3& worldDirection) const {
  return intensity_ * sampleLatLongNearest(image_, latLongUv(toMapDirection(worldDirection)));
}

glm::vec3 EnvironmentMap::texelRadiance(int x, int y) const {
  return intensity_ * glm::vec3(image_.at(x, y));
}

float EnvironmentMap::texelLuminance(int x, int y) const { return luminance(texelRadiance(x, y)); }

float EnvironmentMap::texelSolidAngle(int y) const { return latLongTexelSolidAngle(width(), height(), y); }

glm::vec3 EnvironmentMap::texelDirection(int x, int y) const {
  const glm::vec2 uv((static_cast<float>(x) + 0.5f) / static_cast<float>(width()),
                     (static_cast<float>(y) + 0.5f) / static_cast<float>(height()));
  return toWorldDirection(latLongDirection(uv));
}

}  // namespace iblkit
