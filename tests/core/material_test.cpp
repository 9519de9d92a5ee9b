#include "core/material.h"
#include "core/brdf.h"

#include <gtest/gtest.h>

#include <glm/gtx/component_wise.hpp>  // GLM_ENABLE_EXPERIMENTAL: iblkit_core defines it

#include <algorithm>
#include <cmath>
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

// drawnAlphaMode: OPAQUE exactly where the material's own test keeps every point (BLEND keeps a
// point where u < alpha for u in [0, 1), MASK where alpha >= cutoff), checked against
// surfacePresent's rule over u; a base colour texture's alpha keeps the mode.
TEST(DrawnAlphaMode, OpaqueOnlyWhereTheAlphaTestKeepsEveryPoint) {
  for (AlphaMode mode : {AlphaMode::Opaque, AlphaMode::Mask, AlphaMode::Blend})
    for (float alpha : {-0.5f, 0.0f, 0.3f, 0.5f, 0.99999f, 1.0f, 1.5f}) {
      Material m;
      m.alphaMode = mode;
      m.alpha = alpha;
      m.alphaCutoff = 0.5f;
      // u over [0, 1) on a fine grid and its largest float, with the engine's clamp of alpha to [0, 1].
      const float a = std::clamp(alpha, 0.0f, 1.0f);
      bool everyPoint = true;
      for (int k = 0; k <= 4096; ++k) {
        const float u = k < 4096 ? float(k) / 4096.0f : std::nextafter(1.0f, 0.0f);
        const bool present = mode == AlphaMode::Mask ? a >= m.alphaCutoff : mode == AlphaMode::Blend ? u < a : true;
        everyPoint = everyPoint && present;
      }
      const AlphaMode drawn = drawnAlphaMode(m, false);
      EXPECT_EQ(drawn, everyPoint ? AlphaMode::Opaque : mode) << int(mode) << " alpha " << alpha;
      EXPECT_EQ(drawnAlphaMode(m, true), mode) << int(mode) << " alpha " << alpha;
    }
}

// hasSpecularLayer: false exactly where brdfLobes gives f0 = f90 = 0 (specular and metallic
// factors 0 after the glTF clamp), whatever the other factors.
TEST(HasSpecularLayer, FalseExactlyWhereTheLobesHaveNoFresnel) {
  for (float specular : {-1.0f, 0.0f, 1e-30f, 0.5f, 1.0f})
    for (float metallic : {-0.5f, 0.0f, 1e-30f, 1.0f}) {
      Material m;
      m.baseColor = glm::vec3(0.8f, 0.4f, 0.2f);
      m.specular = specular;
      m.metallic = metallic;
      const BrdfLobes lobes = brdfLobes(m);
      const bool fresnel = glm::compMax(lobes.f0) > 0.0f || glm::compMax(lobes.f90) > 0.0f;
      EXPECT_EQ(hasSpecularLayer(m), fresnel) << "specular " << specular << " metallic " << metallic;
    }
}

}  // namespace
}  // namespace iblkit
