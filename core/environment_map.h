#pragma once
// The distant lighting of a scene: a lat-long radiance map (linear Rec.709, docs/conventions.md)
// turned about +Y and scaled. Lookups take world directions:
//   L_world(d) = intensity * L_map(R_y(-rotation) d)
// where R_y(a) is the right-handed rotation about +Y by a (it takes +Z to +X for a = +90 degrees).
// So a positive rotation turns the environment with the right-hand rule about +Y: what the map
// shows at +Z (the image centre) is seen in world direction +X after a rotation of +90 degrees.

#include <filesystem>
#include <glm/glm.hpp>
#include <utility>

#include "core/image.h"

namespace iblkit {

class EnvironmentMap {
 public:
  // The largest radiance a texel may have: a map's texel sums (importance sampling, SH projection)
  // stay finite in float even for the largest maps. The sun is about 1e9.
  static constexpr float kMaxRadiance = 1e18f;

  // Takes a lat-long map. Throws Error("<file>: lat-long map is WxH, expected a 2:1 aspect ratio")
  // unless width == 2 * height, Error("<file>: lat-long map is 0x0, expected at least 2x1") for
  // an empty image, and Error("<file>: lat-long map has N pixels that are NaN, infinite, negative
  // or above 1e18") for radiance no light can have (loaders repair NaN and negative pixels before
  // they get here; kMaxRadiance keeps sums over the map finite in float).
  static EnvironmentMap fromImage(Image latLong, const std::filesystem::path& fileForErrors);
  // The same radiance in every direction, as a width x width/2 map (width even, >= 2).
  static EnvironmentMap constant(const glm::vec3& radiance, int width = 16);
  // Black except texel (x, y) of a width x width/2 map: a test light of known direction and
  // known power (radiance * texelSolidAngle(y)).
  static EnvironmentMap hotPixel(int width, int x, int y, const glm::vec3& radiance);

  // The lat-long map as loaded (rotation and intensity not applied).
  const Image& image() const { return image_; }
  // The image, moved out of a map that is done with (it is left empty): a large map's stages turn
  // it into the residual in place (computeEnvironmentStages) instead of copying it.
  Image releaseImage() && { return std::move(image_); }
  // The largest R, G or B of any texel, intensity not applied.
  float brightestTexel() const;
  int width() const { return image_.width(); }
  int height() const { return image_.height(); }

  float rotationDegrees() const { return rotationDegrees_; }
  // Throws std::invalid_argument unless the angle is finite.
  void setRotationDegrees(float degrees);
  float intensity() const { return intensity_; }
  // Throws std::invalid_argument unless the multiplier is finite and >= 0.
  void setIntensity(float intensity);

  // World direction -> direction in the map's own frame, and back (rotation only, lengths kept).
  glm::vec3 toMapDirection(const glm::vec3& worldDirection) const;
  glm::vec3 toWorldDirection(const glm::vec3& mapDirection) const;

  // Radiance arriving from world direction `worldDirection` (any non-zero length), bilinear
  // (seamless in longitude, clamped in latitude) or nearest texel; intensity applied.
  glm::vec3 radiance(const glm::vec3& worldDirection) const;
  glm::vec3 radianceNearest(const glm::vec3& worldDirection) const;

  // Per-texel data for an importance sampler, all with intensity applied: the texel's radiance
  // and luminance, the solid angle of row y (steradians), and the world direction of its centre.
  glm::vec3 texelRadiance(int x, int y) const;
  float texelLuminance(int x, int y) const;
  float texelSolidAngle(int y) const;
  glm::vec3 texelDirection(int x, int y) const;

 private:
  explicit EnvironmentMap(Image latLong) : image_(std::move(latLong)) {}

  Image image_;
  float rotationDegrees_ = 0.0f;
  float intensity_ = 1.0f;
  // cos and sin of the rotation, cached for lookups.
  float cosRotation_ = 1.0f, sinRotation_ = 0.0f;
};

}  // namespace iblkit
