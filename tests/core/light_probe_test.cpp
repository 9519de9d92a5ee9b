#include "core/light_probe.h"

#include <gtest/gtest.h>

#include "support/error_capture.h"

#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>

#include "core/error.h"
#include "core/latlong.h"

namespace iblkit {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

std::vector<glm::vec3> randomDirections(int count) {
  std::mt19937 rng(17);
  std::normal_distribution<float> normal;
  std::vector<glm::vec3> directions;
  for (int i = 0; i < count; ++i)
    directions.push_back(glm::normalize(glm::vec3(normal(rng), normal(rng), normal(rng))));
  return directions;
}

// Random (u, v) whose image point lies within radius maxRadius of the centre.
std::vector<glm::vec2> randomUvsInDisk(int count, float maxRadius) {
  std::mt19937 rng(19);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  std::vector<glm::vec2> uvs;
  while (static_cast<int>(uvs.size()) < count) {
    const glm::vec2 p(uniform(rng), uniform(rng));
    if (glm::length(p) < maxRadius) uvs.push_back({0.5f * (p.x + 1.0f), 0.5f * (1.0f - p.y)});
  }
  return uvs;
}

TEST(LightProbe, MirrorBallAxes) {
  const float r90 = std::sin(kPi / 4.0f);  // image radius of the directions 90 degrees from +Z
  expectNear(mirrorBallDirection({0.5f, 0.5f}), {0, 0, 1}, 1e-7f);
  expectNear(mirrorBallDirection({0.5f + 0.5f * r90, 0.5f}), {1, 0, 0}, 1e-6f);
  expectNear(mirrorBallDirection({0.5f - 0.5f * r90, 0.5f}), {-1, 0, 0}, 1e-6f);
  expectNear(mirrorBallDirection({0.5f, 0.5f - 0.5f * r90}), {0, 1, 0}, 1e-6f);  // up in the image is +Y
  // Radius sin(theta / 2): 0.5 sees 60 degrees from +Z.
  expectNear(mirrorBallDirection({0.75f, 0.5f}), {std::sqrt(3.0f) / 2.0f, 0.0f, 0.5f}, 1e-6f);
  // The rim, and beyond it, sees -Z; just inside, nearly so.
  EXPECT_EQ(mirrorBallDirection({1.0f, 0.5f}), glm::vec3(0, 0, -1));
  EXPECT_EQ(mirrorBallDirection({1.0f, 1.0f}), glm::vec3(0, 0, -1));
  EXPECT_LT(mirrorBallDirection({0.5f, 0.999f}).z, -0.99f);
  EXPECT_EQ(mirrorBallUv({0, 0, -1}), glm::vec2(1.0f, 0.5f));
  EXPECT_EQ(mirrorBallUv({0, 0, 0}), glm::vec2(0.5f, 0.5f));
  const glm::vec2 uv = mirrorBallUv({0, 5, 0});
  EXPECT_NEAR(uv.x, 0.5f, 1e-7f);
  EXPECT_NEAR(uv.y, 0.5f - 0.5f * r90, 1e-6f);
}

TEST(LightProbe, MirrorBallObeysTheLawOfReflection) {
  // The ball's normal at image point (x, y) is (x, y, sqrt(1 - r^2)); the view ray (0, 0, -1)
  // and the reflected direction make equal angles with it, in the plane of the two.
  for (const glm::vec2& uv : randomUvsInDisk(2000, 0.999f)) {
    const glm::vec2 p(2.0f * uv.x - 1.0f, 1.0f - 2.0f * uv.y);
    const glm::vec3 n(p, std::sqrt(1.0f - glm::dot(p, p)));
    const glm::vec3 view(0.0f, 0.0f, -1.0f), d = mirrorBallDirection(uv);
    ASSERT_NEAR(glm::length(d), 1.0f, 1e-5f);
    ASSERT_NEAR(glm::dot(d, n), -glm::dot(view, n), 1e-5f);
    ASSERT_NEAR(glm::dot(glm::cross(view, n), d), 0.0f, 1e-5f);
  }
}

TEST(LightProbe, AngularMapFollowsAngmapCal) {
  // angmap.cal (Radiance): u = .5 + Dx * r, v = .5 + Dy * r with r = acos(Dz) / (2 pi sqrt(Dx^2 + Dy^2)),
  // v measured upwards; our v runs down the image.
  for (const glm::vec3& d : randomDirections(2000)) {
    const float r = std::acos(d.z) / (2.0f * kPi * std::sqrt(d.x * d.x + d.y * d.y));
    const glm::vec2 uv = angularMapUv(d * 3.0f);
    ASSERT_NEAR(uv.x, 0.5f + d.x * r, 1e-5f);
    ASSERT_NEAR(uv.y, 1.0f - (0.5f + d.y * r), 1e-5f);
  }
  expectNear(angularMapDirection({0.5f, 0.5f}), {0, 0, 1}, 1e-7f);
  expectNear(angularMapDirection({0.75f, 0.5f}), {1, 0, 0}, 1e-6f);
  expectNear(angularMapDirection({0.5f, 0.25f}), {0, 1, 0}, 1e-6f);
  expectNear(angularMapDirection({0.5f, 1.0f}), {0, 0, -1}, 1e-6f);
  expectNear(angularMapDirection({0.0f, 0.0f}), {0, 0, -1}, 1e-6f);
  EXPECT_EQ(angularMapUv({0, 0, -2}), glm::vec2(1.0f, 0.5f));
  EXPECT_EQ(angularMapUv({0, 0, 0}), glm::vec2(0.5f, 0.5f));
}

TEST(LightProbe, DirectionToUvToDirectionRoundTrips) {
  for (const glm::vec3& d : randomDirections(20000)) {
    ASSERT_NEAR(glm::length(angularMapDirection(angularMapUv(d)) - d), 0.0f, 1e-5f);
    // The mirror ball squeezes the back hemisphere into a thin ring; skip the last 25 degrees.
    if (d.z > -0.9f) {
      ASSERT_NEAR(glm::length(mirrorBallDirection(mirrorBallUv(d)) - d), 0.0f, 1e-5f);
    }
  }
}

TEST(LightProbe, UvToDirectionToUvRoundTrips) {
  for (const glm::vec2& uv : randomUvsInDisk(20000, 0.95f)) {
    const glm::vec2 mirror = mirrorBallUv(mirrorBallDirection(uv)),
                    angular = angularMapUv(angularMapDirection(uv));
    ASSERT_NEAR(glm::length(mirror - uv), 0.0f, 1e-5f);
    ASSERT_NEAR(glm::length(angular - uv), 0.0f, 1e-5f);
  }
}

glm::vec3 smoothRadiance(const glm::vec3& d) {
  return {1.0f + 0.5f * d.x, 0.8f + 0.3f * d.y * d.z, 0.5f + 0.5f * d.z * d.z};
}

// A probe of `size` pixels rendered from smoothRadiance at pixel centres inside the disk, with a
// huge value outside it that the conversion must never read.
Image renderProbe(int size, glm::vec3 (*probeDirection)(const glm::vec2&)) {
  Image probe(size, size, glm::vec4(1e6f));
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const glm::vec2 uv = (glm::vec2(x, y) + 0.5f) / static_cast<float>(size);
      if (glm::length(glm::vec2(2.0f * uv.x - 1.0f, 1.0f - 2.0f * uv.y)) <= 1.0f)
        probe.at(x, y) = glm::vec4(smoothRadiance(probeDirection(uv)), 1.0f);
    }
  }
  return probe;
}

// Largest RGB error of `converted` against the exact lat-long rendering of smoothRadiance, over
// texels whose centre direction has z above minZ; every texel must be free of outside pixels.
float worstError(const Image& converted, float minZ) {
  const Image exact = latLongFromRadiance(converted.width(), converted.height(), 2, smoothRadiance);
  float worst = 0.0f;
  for (int y = 0; y < converted.height(); ++y) {
    for (int x = 0; x < converted.width(); ++x) {
      const glm::vec3 value(converted.at(x, y));
      EXPECT_LT(value.x, 2.0f) << x << "," << y;
      const glm::vec2 uv = (glm::vec2(x, y) + 0.5f) / glm::vec2(converted.width(), converted.height());
      if (latLongDirection(uv).z > minZ)
        worst = std::max(worst, glm::length(value - glm::vec3(exact.at(x, y))));
    }
  }
  return worst;
}

TEST(LightProbe, MirrorBallToLatLong) {
  const Image latLong = latLongFromMirrorBall(renderProbe(256, mirrorBallDirection), 64, 2, "ball.exr");
  ASSERT_EQ(latLong.width(), 64);
  ASSERT_EQ(latLong.height(), 32);
  EXPECT_LT(worstError(latLong, -0.7f), 5e-4f);
  // Near -Z a probe pixel spans many degrees: the error is a texel's worth of variation there.
  EXPECT_LT(worstError(latLong, -2.0f), 5e-2f);
}

TEST(LightProbe, AngularMapToLatLong) {
  // The angular map's resolution holds up all the way round to -Z.
  const Image latLong = latLongFromAngularMap(renderProbe(256, angularMapDirection), 64, 2, "probe.exr");
  EXPECT_LT(worstError(latLong, -2.0f), 5e-4f);
}

TEST(LightProbe, ProbesMustBeSquare) {
  EXPECT_EQ(test::errorMessage([] { latLongFromMirrorBall(Image(30, 20), 64, 1, "ball.hdr"); }),
            "ball.hdr: mirror-ball probe is 30x20, expected a square image");
  EXPECT_EQ(test::errorMessage([] { latLongFromAngularMap(Image(), 64, 1, "probe.exr"); }),
            "probe.exr: angular map is 0x0, expected a square image");
  EXPECT_THROW(latLongFromAngularMap(Image(8, 8), 63, 1, "probe.exr"), std::invalid_argument);
}

}  // namespace
}  // namespace iblkit
