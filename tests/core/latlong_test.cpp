#include "core/latlong.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "support/expect_near.h"

namespace iblkit {
namespace {

constexpr double kPi = std::numbers::pi;

using test::expectNear;

// Uniform random unit directions, plus directions within 1e-3 .. 1e-12 radians of the poles and
// on both sides of the seam (-Z, x = +-tiny), each scaled by a random length to check that
// lengths do not matter.
std::vector<glm::vec3> testDirections() {
  std::mt19937 rng(7);
  std::normal_distribution<float> normal;
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  std::vector<glm::vec3> directions;
  for (int i = 0; i < 20000; ++i)
    directions.push_back(glm::normalize(glm::vec3(normal(rng), normal(rng), normal(rng))));
  for (float epsilon : {1e-3f, 1e-5f, 1e-7f, 1e-9f, 1e-12f}) {
    for (int i = 0; i < 16; ++i) {
      const float phi = 2.0f * static_cast<float>(kPi) * uniform(rng);
      const glm::vec3 side(epsilon * std::cos(phi), 0.0f, epsilon * std::sin(phi));
      directions.push_back(glm::normalize(glm::vec3(0.0f, 1.0f, 0.0f) + side));
      directions.push_back(glm::normalize(glm::vec3(0.0f, -1.0f, 0.0f) + side));
      const float y = uniform(rng) - 0.5f;
      directions.push_back(glm::normalize(glm::vec3(epsilon, y, -1.0f)));
      directions.push_back(glm::normalize(glm::vec3(-epsilon, y, -1.0f)));
    }
  }
  directions.push_back({0.0f, 0.0f, -1.0f});
  directions.push_back({-0.0f, 0.0f, -1.0f});
  return directions;
}

TEST(LatLong, AxesFollowOpenExr) {
  expectNear(latLongDirection({0.5f, 0.5f}), {0, 0, 1}, 1e-6f);
  expectNear(latLongDirection({0.25f, 0.5f}), {1, 0, 0}, 1e-6f);
  expectNear(latLongDirection({0.75f, 0.5f}), {-1, 0, 0}, 1e-6f);
  expectNear(latLongDirection({0.0f, 0.5f}), {0, 0, -1}, 1e-6f);
  expectNear(latLongDirection({0.3f, 0.0f}), {0, 1, 0}, 1e-6f);
  expectNear(latLongDirection({0.3f, 1.0f}), {0, -1, 0}, 1e-6f);
  // Longitude increases to the left: a little left of the centre is towards +X.
  EXPECT_GT(latLongDirection({0.45f, 0.5f}).x, 0.0f);
  EXPECT_EQ(latLongUv({1, 0, 0}), glm::vec2(0.25f, 0.5f));
  EXPECT_EQ(latLongUv({-1, 0, 0}), glm::vec2(0.75f, 0.5f));
  EXPECT_EQ(latLongUv({0, 0, 1}), glm::vec2(0.5f, 0.5f));
  EXPECT_EQ(latLongUv({0, 1, 0}).y, 0.0f);
  EXPECT_EQ(latLongUv({0, -1, 0}).y, 1.0f);
  // 45 degrees up, in the +X half.
  const glm::vec2 uv = latLongUv({1, std::sqrt(2.0f), 1});
  EXPECT_NEAR(uv.x, 0.5f - 0.125f, 1e-7f);
  EXPECT_NEAR(uv.y, 0.25f, 1e-7f);
}

TEST(LatLong, ZeroAndScaledDirections) {
  EXPECT_EQ(latLongUv({0, 0, 0}), glm::vec2(0.5f, 0.5f));
  const glm::vec3 d(0.3f, -0.2f, 0.9f);
  EXPECT_EQ(latLongUv(d * 1000.0f), latLongUv(d));
  const glm::vec2 small = latLongUv(d * 1e-20f), unit = latLongUv(d);
  EXPECT_NEAR(small.x, unit.x, 1e-7f);
  EXPECT_NEAR(small.y, unit.y, 1e-7f);
}

TEST(LatLong, DirectionToUvToDirectionRoundTrip) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> scale(-3.0f, 3.0f);
  for (const glm::vec3& d : testDirections()) {
    const glm::vec3 back = latLongDirection(latLongUv(d * std::pow(10.0f, scale(rng))));
    ASSERT_NEAR(glm::length(back - d), 0.0f, 1e-5f) << d.x << " " << d.y << " " << d.z;
  }
}

TEST(LatLong, UvToDirectionToUvRoundTrip) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> inside(0.01f, 0.99f);
  for (int i = 0; i < 20000; ++i) {
    const glm::vec2 uv(inside(rng), inside(rng));
    const glm::vec2 back = latLongUv(latLongDirection(uv));
    ASSERT_NEAR(back.x, uv.x, 1e-5f);
    ASSERT_NEAR(back.y, uv.y, 1e-5f);
  }
}

TEST(LatLong, TexelSolidAnglesSumToTheSphere) {
  for (const int height : {1, 2, 3, 32, 256, 1024}) {
    const int width = 2 * height;
    double sum = 0.0;
    for (int y = 0; y < height; ++y) sum += double(width) * latLongTexelSolidAngle(width, height, y);
    EXPECT_NEAR(sum / (4.0 * kPi), 1.0, 1e-4) << height;
  }
  // A 2x1 map: two hemispheres.
  EXPECT_NEAR(latLongTexelSolidAngle(2, 1, 0), 2.0 * kPi, 1e-5);
}

TEST(LatLong, TexelSolidAngleAgainstTheSinThetaApproximation) {
  // dOmega = sin(theta) dtheta dphi at the row centre is (2pi/W)(pi/H) sin(theta); the exact
  // value is that times sin(h)/h with h = pi / (2H), the same factor for every row.
  const int width = 64, height = 32;
  const double h = kPi / (2.0 * height), factor = std::sin(h) / h;
  for (int y = 0; y < height; ++y) {
    const double theta = kPi * (y + 0.5) / height;  // angle from +Y
    const double approximation = (2.0 * kPi / width) * (kPi / height) * std::sin(theta);
    EXPECT_NEAR(latLongTexelSolidAngle(width, height, y) / approximation, factor, 1e-5) << y;
  }
  EXPECT_LT(1.0 - factor, 1e-3);
  EXPECT_GT(1.0 - factor, 1e-4);
}

Image numberedImage(int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.at(x, y) = glm::vec4(float(x), float(y), float(x * 100 + y), 1.0f);
  return image;
}

glm::vec3 texel(const Image& image, int x, int y) { return glm::vec3(image.at(x, y)); }

TEST(LatLong, BilinearAtTexelCentreReturnsTheTexel) {
  const Image image = numberedImage(64, 32);
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 64; ++x) {
      const glm::vec2 centre((x + 0.5f) / 64.0f, (y + 0.5f) / 32.0f);
      ASSERT_EQ(sampleLatLongBilinear(image, centre), texel(image, x, y)) << x << "," << y;
      ASSERT_EQ(sampleLatLongNearest(image, centre), texel(image, x, y));
    }
  }
}

TEST(LatLong, BilinearBlendsAcrossTheSeam) {
  const Image image = numberedImage(64, 32);
  const float v = 10.5f / 32.0f;
  const glm::vec3 first = texel(image, 0, 10), last = texel(image, 63, 10);
  // u = 0 and u = 1 are the same meridian, halfway between the centres of columns 63 and 0.
  expectNear(sampleLatLongBilinear(image, {0.0f, v}), 0.5f * (first + last), 1e-4f);
  expectNear(sampleLatLongBilinear(image, {1.0f, v}), 0.5f * (first + last), 1e-4f);
  // A quarter texel either side of the seam.
  expectNear(sampleLatLongBilinear(image, {0.25f / 64.0f, v}), 0.75f * first + 0.25f * last, 1e-3f);
  expectNear(sampleLatLongBilinear(image, {1.0f - 0.25f / 64.0f, v}), 0.25f * first + 0.75f * last, 1e-3f);
  // u is periodic.
  expectNear(sampleLatLongBilinear(image, {-0.75f + 3.5f / 64.0f, v}), texel(image, 19, 10), 1e-3f);
  expectNear(sampleLatLongBilinear(image, {2.0f + 3.5f / 64.0f, v}), texel(image, 3, 10), 1e-3f);
}

TEST(LatLong, BilinearClampsInLatitude) {
  const Image image = numberedImage(64, 32);
  const float u = 5.5f / 64.0f;
  EXPECT_EQ(sampleLatLongBilinear(image, {u, 0.0f}), texel(image, 5, 0));
  EXPECT_EQ(sampleLatLongBilinear(image, {u, 0.25f / 32.0f}), texel(image, 5, 0));
  EXPECT_EQ(sampleLatLongBilinear(image, {u, 1.0f}), texel(image, 5, 31));
  EXPECT_EQ(sampleLatLongBilinear(image, {u, 7.0f}), texel(image, 5, 31));
  // Between rows 3 and 4.
  expectNear(sampleLatLongBilinear(image, {u, 4.0f / 32.0f}),
             0.5f * (texel(image, 5, 3) + texel(image, 5, 4)), 1e-4f);
}

TEST(LatLong, NearestPicksTheContainingTexel) {
  const Image image = numberedImage(8, 4);
  EXPECT_EQ(sampleLatLongNearest(image, {0.0f, 0.0f}), texel(image, 0, 0));
  EXPECT_EQ(sampleLatLongNearest(image, {0.999f / 8.0f, 1.999f / 4.0f}), texel(image, 0, 1));
  EXPECT_EQ(sampleLatLongNearest(image, {1.0f, 1.0f}), texel(image, 0, 3));
  EXPECT_EQ(sampleLatLongNearest(image, {-0.01f, 0.5f}), texel(image, 7, 2));
}

TEST(LatLong, NonFiniteUvGivesNaN) {
  const Image image = numberedImage(8, 4);
  EXPECT_TRUE(std::isnan(sampleLatLongBilinear(image, {NAN, 0.5f}).x));
  EXPECT_TRUE(std::isnan(sampleLatLongNearest(image, {0.5f, INFINITY}).y));
}

TEST(LatLong, RenderingARadianceFunction) {
  const Image constant = latLongFromRadiance(16, 8, 3, [](const glm::vec3&) { return glm::vec3(2, 3, 4); });
  for (const glm::vec4& p : constant.pixels()) {
    expectNear(glm::vec3(p), {2, 3, 4}, 1e-5f);
    EXPECT_EQ(p.a, 1.0f);
  }
  // A single sample per texel is the value at the texel centre.
  const Image direction = latLongFromRadiance(16, 8, 1, [](const glm::vec3& d) { return d; });
  expectNear(glm::vec3(direction.at(5, 2)), latLongDirection({5.5f / 16.0f, 2.5f / 8.0f}), 1e-6f);
  // The solid-angle-weighted mean of y over the whole top row is the mean height of that cap:
  // the integral of sin(lat) cos(lat) over lat in [pi/2 - pi/H, pi/2], divided by that of cos(lat).
  const Image height = latLongFromRadiance(2, 4, 64, [](const glm::vec3& d) { return glm::vec3(d.y); });
  const double low = kPi / 2.0 - kPi / 4.0;
  const double expected = 0.5 * (1.0 - std::sin(low) * std::sin(low)) / (1.0 - std::sin(low));
  EXPECT_NEAR(height.at(0, 0).x, expected, 1e-4);
  EXPECT_THROW(latLongFromRadiance(0, 8, 1, [](const glm::vec3& d) { return d; }), std::invalid_argument);
  EXPECT_THROW(latLongFromRadiance(16, 8, 0, [](const glm::vec3& d) { return d; }), std::invalid_argument);
}

}  // namespace
}  // namespace iblkit
