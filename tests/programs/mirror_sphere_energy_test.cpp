// The DWAB-compressed sky.exr through iblkit-trace: a mirror sphere reflecting the sun renders the
// energy of the raw file's signed values (the negative ring around the sun included), as a path
// tracer that reads the file as stored does, not the 13% more that clamping the ring to 0 gave.
// The prediction is computed here from the raw map, through the same camera rays and an exact
// sphere; the traced image is the program's, with the map loaded by loadEnvironmentMap.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <string>

#include "core/camera.h"
#include "core/image_io.h"
#include "core/latlong.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

constexpr int kSize = 96;              // image width and height
constexpr int kPredictionSamples = 6;  // per axis and pixel
constexpr float kCameraDistance = 4.0f;
// A close-up of the sphere's centre (the unit sphere is 29 degrees across from 4 away): the image
// reflects the directions within about 12 degrees of the sun, some 17 texels of sky.exr, so the
// sun and its ring cover hundreds of pixels, and the repair (within 3 texels) stays inside.
constexpr float kYfovDegrees = 3.0f;

// The direction of the brightest texel (luminance) of `latLong`: the sun.
glm::vec3 brightestDirection(const Image& latLong) {
  int bestX = 0, bestY = 0;
  for (int y = 0; y < latLong.height(); ++y)
    for (int x = 0; x < latLong.width(); ++x)
      if (luminance(glm::vec3(latLong.at(x, y))) > luminance(glm::vec3(latLong.at(bestX, bestY)))) {
        bestX = x;
        bestY = y;
      }
  return latLongDirection({(bestX + 0.5f) / latLong.width(), (bestY + 0.5f) / latLong.height()});
}

// What each pixel of the mirror sphere's image shows under `latLong` (bilinear, as the tracer
// looks the map up): the mean over kPredictionSamples^2 stratified positions of the map along the
// camera ray reflected off the exact unit sphere, or along the ray itself where it misses.
Image mirrorSphereImage(const Camera& camera, const Image& latLong) {
  const PrimaryRays rays(camera, kSize, kSize);
  Image image(kSize, kSize);
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) {
      glm::vec3 sum(0.0f);
      for (int sy = 0; sy < kPredictionSamples; ++sy)
        for (int sx = 0; sx < kPredictionSamples; ++sx) {
          const Ray ray = rays({i + (sx + 0.5f) / kPredictionSamples, j + (sy + 0.5f) / kPredictionSamples});
          glm::vec3 direction = ray.direction;
          const float b = glm::dot(ray.origin, ray.direction);
          const float discriminant = b * b - (glm::dot(ray.origin, ray.origin) - 1.0f);
          if (discriminant > 0.0f) {
            const glm::vec3 n = glm::normalize(ray.origin + (-b - std::sqrt(discriminant)) * ray.direction);
            direction = glm::reflect(ray.direction, n);
          }
          sum += sampleLatLongBilinear(latLong, latLongUv(direction));
        }
      image.at(i, j) = glm::vec4(sum / float(kPredictionSamples * kPredictionSamples), 1.0f);
    }
  return image;
}

// The mean luminance of `image` over the pixels the sphere covers fully.
double meanOnSphere(const Image& image, const Image& mask) {
  double sum = 0.0;
  int count = 0;
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i)
      if (mask.at(i, j).r >= 0.999f) {
        sum += luminance(glm::vec3(image.at(i, j)));
        ++count;
      }
  return count ? sum / count : 0.0;
}

TEST(MirrorSphereEnergy, SkyExrRendersTheRawSignedMapsEnergy) {
  const std::filesystem::path sky = test::assetsDir() / "hdri" / "sky.exr";
  if (!std::filesystem::is_regular_file(sky)) GTEST_SKIP() << "no asset " << sky;
  const Image raw = readExr(sky, nullptr, 0, PixelRepair::Keep);
  Image clamped = raw;
  for (glm::vec4& pixel : clamped.pixels()) pixel = glm::max(pixel, glm::vec4(0.0f));
  // The camera between the sun and the sphere sees the sun's reflection at the sphere's centre,
  // where the image resolves it best.
  const glm::vec3 sun = brightestDirection(raw);
  const glm::vec3 eye = kCameraDistance * sun;
  const glm::vec3 up = std::abs(sun.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const Camera camera = Camera::lookAt(eye, glm::vec3(0.0f), up, glm::radians(kYfovDegrees), 0.1f, 100.0f);

  const std::filesystem::path dir = test::scratchDir();
  std::ofstream(dir / "scene.json")
      << R"({"models": [{"shape": "sphere", "material": {"baseColor": [1, 1, 1], "metallic": 1, "roughness": 0}}],)"
      << R"("environment": {"file": )" << '"' << sky.string() << '"' << "}, "
      << R"("camera": {"position": [)" << eye.x << ", " << eye.y << ", " << eye.z << "], "
      << R"("target": [0, 0, 0], "up": [)" << up.x << ", " << up.y << ", " << up.z << "], "
      << R"("yfov": )" << kYfovDegrees << ", \"znear\": 0.1, \"zfar\": 100}, "
      << R"("width": )" << kSize << R"(, "height": )" << kSize << "}";
  std::string output;
  ASSERT_EQ(test::runCommand("cd " + test::shellQuoted(dir) + " && " +
                                 test::shellQuoted(test::binDir() / "iblkit-trace") +
                                 " scene.json -o beauty.exr --mask mask.exr --spp 8 --threads 2",
                             &output),
            0)
      << output;
  const Image mask = readExr(dir / "mask.exr");
  const double traced = meanOnSphere(readExr(dir / "beauty.exr"), mask);
  const double signedPrediction = meanOnSphere(mirrorSphereImage(camera, raw), mask);
  const double clampedPrediction = meanOnSphere(mirrorSphereImage(camera, clamped), mask);
  std::cout << "traced / signed prediction " << traced / signedPrediction << ", clamped / signed prediction "
            << clampedPrediction / signedPrediction << '\n';
  EXPECT_NEAR(traced / signedPrediction, 1.0, 0.01);
  EXPECT_GT(clampedPrediction / signedPrediction, 1.1);  // what the clamp to 0 showed
}

}  // namespace
}  // namespace iblkit
