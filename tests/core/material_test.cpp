#include "core/material.h"

#include <gtest/gtest.h>

#include <limits>

namespace iblkit {
namespace {

TEST(ClampedToGltfRanges, ClampsEachFactorToItsRange) {
  Material m;
  m.name = "out of range";
  m.baseColor = glm::vec3(-0.5f, 0.25f, 1.5f);
  m.metallic = 2.0f;
  m.roughness = -1.0f;
  m.specular = 1.25f;
  m.specularColor = glm::vec3(-1.0f, 0.5f, 3.0f);  // KHR_materials_specular allows > 1
  m.emissive = glm::vec3(4.0f, -1.0f, 0.0f);
  const Material c = clampedToGltfRanges(m);
  EXPECT_EQ(c.baseColor, glm::vec3(0.0f, 0.25f, 1.0f));
  EXPECT_EQ(c.metallic, 1.0f);
  EXPECT_EQ(c.roughness, 0.0f);
  EXPECT_EQ(c.specular, 1.0f);
  EXPECT_EQ(c.specularColor, glm::vec3(0.0f, 0.5f, 3.0f));
  EXPECT_EQ(c.emissive, m.emissive);
  EXPECT_EQ(c.name, m.name);
}

TEST(ClampedToGltfRanges, KeepsInRangeFactorsAndTheLowerEnds) {
  Material m;
  m.baseColor = glm::vec3(0.1f, 0.2f, 0.3f);
  m.metallic = 0.0f;
  m.roughness = 0.5f;
  m.specular = 0.75f;
  m.specularColor = glm::vec3(0.0f, 1.0f, 2.0f);
  const Material c = clampedToGltfRanges(m);
  EXPECT_EQ(c.baseColor, m.baseColor);
  EXPECT_EQ(c.metallic, 0.0f);
  EXPECT_EQ(c.roughness, 0.5f);
  EXPECT_EQ(c.specular, 0.75f);
  EXPECT_EQ(c.specularColor, m.specularColor);
  const Material defaults = clampedToGltfRanges(Material{});  // the glTF defaults are in range
  EXPECT_EQ(defaults.metallic, 1.0f);
  EXPECT_EQ(defaults.roughness, 1.0f);
  EXPECT_EQ(defaults.specularColor, glm::vec3(1.0f));
}

TEST(ClampedToGltfRanges, InfiniteFactorsGoToTheRangeEnds) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  Material m;
  m.metallic = kInf;
  m.roughness = -kInf;
  m.specularColor = glm::vec3(-kInf);
  const Material c = clampedToGltfRanges(m);
  EXPECT_EQ(c.metallic, 1.0f);
  EXPECT_EQ(c.roughness, 0.0f);
  EXPECT_EQ(c.specularColor, glm::vec3(0.0f));
}

}  // namespace
}  // namespace iblkit
