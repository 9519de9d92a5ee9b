// The lobe weights of the engine's `full` mode (brdfLobes and diffuseWeight of shaders/brdf.glsl,
// which fullMaterialModel uses), evaluated by the GPU over a table of materials and angles
// (shaders/brdf_lobes_probe.frag) and compared with core/brdf.cpp's.
#include <gtest/gtest.h>

#include <vector>

#include "core/brdf.h"
#include "core/image.h"
#include "core/material.h"
#include "gl/fragment_probe.h"

namespace iblkit {
namespace {

// Dielectrics, metals and mixes; the specular extension's factor and (coloured, > 1, clamped to
// f0 = 1) tint; factors out of range, which the renderer clamps with clampedToGltfRanges; an ior
// other than 1.5, which clampedToGltfRanges folds into the specular colour.
const std::vector<Material> kMaterials = {
    Material{.name = "dielectric",
             .baseColor = {0.8f, 0.2f, 0.1f},
             .metallic = 0.0f,
             .roughness = 0.5f,
             .specular = 1.0f,
             .specularColor = {1.0f, 1.0f, 1.0f}},
    Material{.name = "gold",
             .baseColor = {0.9f, 0.6f, 0.2f},
             .metallic = 1.0f,
             .roughness = 0.2f,
             .specular = 1.0f,
             .specularColor = {1.0f, 1.0f, 1.0f}},
    Material{.name = "half metal, tinted",
             .baseColor = {0.5f, 0.5f, 0.5f},
             .metallic = 0.5f,
             .roughness = 1.0f,
             .specular = 0.5f,
             .specularColor = {1.0f, 0.5f, 0.25f}},
    Material{.name = "specular 0",
             .baseColor = {0.3f, 0.7f, 0.4f},
             .metallic = 0.0f,
             .roughness = 0.05f,
             .specular = 0.0f,
             .specularColor = {1.0f, 1.0f, 1.0f}},
    Material{.name = "tint above 1",
             .baseColor = {0.2f, 0.3f, 0.9f},
             .metallic = 0.25f,
             .roughness = 0.7f,
             .specular = 0.8f,
             .specularColor = {3.0f, 30.0f, 12.5f}},
    Material{.name = "f0 clamped to 1",
             .baseColor = {0.1f, 0.1f, 0.1f},
             .metallic = 0.0f,
             .roughness = 0.0f,
             .specular = 1.0f,
             .specularColor = {25.0f, 25.0f, 25.0f}},
    Material{.name = "above the ranges",
             .baseColor = {1.5f, -0.5f, 0.5f},
             .metallic = 1.5f,
             .roughness = -0.2f,
             .specular = 2.0f,
             .specularColor = {-1.0f, 2.0f, 0.5f}},
    Material{.name = "below the ranges",
             .baseColor = {0.6f, 0.6f, 0.6f},
             .metallic = -1.0f,
             .roughness = 1.5f,
             .specular = -0.5f,
             .specularColor = {0.5f, 0.5f, 0.5f}},
    // KHR_materials_ior: water, diamond (tinted), and 0 (F0 1, no diffuse left).
    Material{.name = "ior 1.33",
             .baseColor = {0.2f, 0.4f, 0.8f},
             .metallic = 0.0f,
             .roughness = 0.3f,
             .specular = 1.0f,
             .specularColor = {1.0f, 1.0f, 1.0f},
             .ior = 1.33f},
    Material{.name = "ior 2.42, tinted",
             .baseColor = {0.9f, 0.9f, 0.9f},
             .metallic = 0.2f,
             .roughness = 0.6f,
             .specular = 0.7f,
             .specularColor = {1.0f, 0.6f, 3.0f},
             .ior = 2.42f},
    Material{.name = "ior 0",
             .baseColor = {0.5f, 0.5f, 0.5f},
             .metallic = 0.0f,
             .roughness = 0.4f,
             .specular = 1.0f,
             .specularColor = {1.0f, 1.0f, 1.0f},
             .ior = 0.0f},
};
const float kCosines[] = {0.0f, 0.05f, 0.2f, 0.5f, 0.8f, 0.99f, 1.0f};
constexpr float kTolerance = 2e-6f;

struct Case {
  Material material;
  float cosTheta;
};

std::vector<Case> cases() {
  std::vector<Case> all;
  for (const Material& m : kMaterials)
    for (float c : kCosines) all.push_back({m, c});
  return all;
}

// The probe's four outputs per case, with the material clamped as the renderer uploads it.
std::vector<std::vector<glm::vec4>> probe(const std::vector<Case>& all) {
  const int n = int(all.size());
  Image a(n, 1), b(n, 1), c(n, 1);
  for (int i = 0; i < n; ++i) {
    const Material m = clampedToGltfRanges(all[std::size_t(i)].material);
    a.at(i, 0) = glm::vec4(m.baseColor, m.metallic);
    b.at(i, 0) = glm::vec4(m.specularColor, m.specular);
    c.at(i, 0) = glm::vec4(m.roughness, all[std::size_t(i)].cosTheta, 0.0f, 0.0f);
  }
  std::vector<std::vector<glm::vec4>> outputs;
  for (int quantity = 0; quantity < 4; ++quantity)
    outputs.push_back(test::runFragmentProbe("brdf_lobes_probe.frag",
                                             {{"materialA", &a}, {"materialB", &b}, {"angle", &c}},
                                             [&](const ShaderProgram& p) { p.set("quantity", quantity); }));
  return outputs;
}

void expectNear(const glm::vec3& gpu, const glm::vec3& cpu, const char* what, const Case& c) {
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(gpu[k], cpu[k], kTolerance)
        << what << "[" << k << "], " << c.material.name << ", cos " << c.cosTheta;
}

TEST(BrdfLobesGlsl, MatchTheCpuBrdfOverMaterialsAndAngles) {
  const std::vector<Case> all = cases();
  const std::vector<std::vector<glm::vec4>> gpu = probe(all);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const BrdfLobes cpu = brdfLobes(all[i].material);
    const float cosTheta = all[i].cosTheta;
    expectNear(glm::vec3(gpu[0][i]), cpu.f0, "f0", all[i]);
    EXPECT_NEAR(gpu[0][i].w, cpu.alpha, kTolerance) << "alpha, " << all[i].material.name;
    expectNear(glm::vec3(gpu[1][i]), cpu.f90, "f90", all[i]);
    EXPECT_NEAR(gpu[1][i].w, diffuseWeight(cpu, cosTheta), kTolerance)
        << "diffuse weight, " << all[i].material.name << ", cos " << cosTheta;
    expectNear(glm::vec3(gpu[2][i]), specularFresnel(cpu, cosTheta), "Fresnel", all[i]);
    EXPECT_NEAR(gpu[2][i].w, cpu.specular, kTolerance) << "specular, " << all[i].material.name;
    expectNear(glm::vec3(gpu[3][i]), cpu.dielectricF0, "dielectricF0", all[i]);
    EXPECT_NEAR(gpu[3][i].w, cpu.metallic, kTolerance) << "metallic, " << all[i].material.name;
  }
}

// The table reaches the cases that tell the weights apart: a clamped f0 of 1 (no diffuse left at
// specular 1), a pure metal (none either), specular 0 (all of 1 - metallic).
TEST(BrdfLobesGlsl, CoverTheLimitsOfTheDiffuseWeight) {
  const std::vector<Case> all = cases();
  const std::vector<std::vector<glm::vec4>> gpu = probe(all);
  const std::size_t perMaterial = std::size(kCosines);
  EXPECT_NEAR(gpu[1][5 * perMaterial + 3].w, 0.0f, kTolerance);  // f0 clamped to 1
  EXPECT_NEAR(gpu[1][1 * perMaterial + 3].w, 0.0f, kTolerance);  // metal
  EXPECT_NEAR(gpu[1][3 * perMaterial + 3].w, 1.0f, kTolerance);  // specular 0
}

}  // namespace
}  // namespace iblkit
