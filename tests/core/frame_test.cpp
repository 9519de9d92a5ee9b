#include "core/frame.h"

#include <gtest/gtest.h>

#include "core/rng.h"
#include "core/sampling.h"

namespace iblkit {
namespace {

void expectOrthonormalRightHanded(const Frame& f, const glm::vec3& z) {
  EXPECT_NEAR(glm::length(f.x), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::length(f.y), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(f.x, f.y), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(f.x, z), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(f.y, z), 0.0f, 1e-5f);
  const glm::vec3 c = glm::cross(f.x, f.y);
  EXPECT_NEAR(glm::length(c - z), 0.0f, 1e-5f) << "x cross y must be z";
  EXPECT_EQ(f.z, z);
}

TEST(Frame, IdentityForThePositiveZAxis) {
  const Frame f = Frame::fromZ({0.0f, 0.0f, 1.0f});
  EXPECT_EQ(f.x, glm::vec3(1.0f, 0.0f, 0.0f));
  EXPECT_EQ(f.y, glm::vec3(0.0f, 1.0f, 0.0f));
}

TEST(Frame, OrthonormalIncludingNearTheNegativeZAxis) {
  // Frisvad's original construction breaks down near z = (0,0,-1); Duff et al.'s does not.
  expectOrthonormalRightHanded(Frame::fromZ({0.0f, 0.0f, -1.0f}), {0.0f, 0.0f, -1.0f});
  const glm::vec3 nearlyDown = glm::normalize(glm::vec3(1e-4f, -2e-4f, -1.0f));
  expectOrthonormalRightHanded(Frame::fromZ(nearlyDown), nearlyDown);
  PCG32 rng(2u);
  for (int i = 0; i < 1000; ++i) {
    const glm::vec3 z = sampleUniformSphere(rng.uniform2D());
    expectOrthonormalRightHanded(Frame::fromZ(z), z);
  }
}

TEST(Frame, LocalAndWorldAreInverse) {
  const glm::vec3 z = glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f));
  const Frame f = Frame::fromZ(z);
  const glm::vec3 local = f.toLocal(z);
  EXPECT_NEAR(local.x, 0.0f, 1e-6f);
  EXPECT_NEAR(local.y, 0.0f, 1e-6f);
  EXPECT_NEAR(local.z, 1.0f, 1e-6f);
  const glm::vec3 v(0.2f, 0.7f, -0.4f);
  const glm::vec3 back = f.toWorld(f.toLocal(v));
  EXPECT_NEAR(glm::length(back - v), 0.0f, 1e-6f);
}

}  // namespace
}  // namespace iblkit
