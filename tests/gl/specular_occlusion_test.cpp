// specularOcclusionCone (shaders/brdf.glsl), evaluated by the GPU over a table of inputs
// (shaders/brdf_probe.frag) and checked against the cone geometry it stands for.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/image.h"
#include "gl/fragment_probe.h"

namespace iblkit {
namespace {

struct Input {
  glm::vec3 bent;
  float ao;
  glm::vec3 reflection;
  float alpha;
};

std::vector<float> specularOcclusion(const std::vector<Input>& inputs) {
  const int n = int(inputs.size());
  Image a(n, 1), b(n, 1);
  for (int i = 0; i < n; ++i) {
    a.at(i, 0) = glm::vec4(inputs[i].bent, inputs[i].ao);
    b.at(i, 0) = glm::vec4(inputs[i].reflection, inputs[i].alpha);
  }
  std::vector<float> values;
  for (const glm::vec4& out : test::runFragmentProbe("brdf_probe.frag", {{"inputA", &a}, {"inputB", &b}}))
    values.push_back(out.r);
  return values;
}

glm::vec3 tilted(float degrees) {
  const float t = glm::radians(degrees);
  return {std::sin(t), 0.0f, std::cos(t)};
}

TEST(SpecularOcclusionCone, MatchesTheConeGeometry) {
  const glm::vec3 up(0.0f, 0.0f, 1.0f);
  const std::vector<float> so = specularOcclusion({
      {up, 1.0f, up, 0.1f},                  // open hemisphere, narrow lobe along it: unoccluded
      {up, 1.0f, -up, 0.1f},                 // the lobe points into the blocked half: occluded
      {up, 0.0f, up, 0.5f},                  // nothing visible
      {up, 0.19f, up, 1.0f},                 // visibility cone (cos 0.9) inside the lobe (cos 0.1)
      {up, 0.75f, tilted(20.0f), 0.01f},     // a 12.3-degree lobe 20 degrees off a 60-degree cone
      {up, 0.75f, tilted(80.0f), 0.01f},     // ...and 80 degrees off: outside (60 + 12.3 < 80)
  });
  EXPECT_NEAR(so[0], 1.0f, 1e-4f);
  EXPECT_NEAR(so[1], 0.0f, 1e-6f);
  EXPECT_NEAR(so[2], 0.0f, 1e-6f);
  EXPECT_NEAR(so[3], (1.0f - 0.9f) / (1.0f - 0.1f), 2e-3f);
  EXPECT_NEAR(so[4], 1.0f, 1e-4f);
  EXPECT_NEAR(so[5], 0.0f, 1e-6f);
}

TEST(SpecularOcclusionCone, FallsAsTheLobeTurnsAwayFromTheBentNormal) {
  std::vector<Input> inputs;
  for (int degrees = 0; degrees <= 120; degrees += 5) inputs.push_back({{0, 0, 1}, 0.5f, tilted(float(degrees)), 0.3f});
  const std::vector<float> so = specularOcclusion(inputs);
  // ao 0.5: a 45-degree visibility cone; alpha 0.3: a 60-degree lobe, so at most (1 - cos 45) / (1 - cos 60).
  EXPECT_NEAR(so.front(), (1.0f - std::sqrt(0.5f)) / (1.0f - std::pow(0.1f, 0.3f)), 2e-3f);
  for (std::size_t i = 1; i < so.size(); ++i) EXPECT_LE(so[i], so[i - 1] + 1e-6f) << i * 5 << " degrees";
  EXPECT_EQ(so.back(), 0.0f);  // 120 > 45 + 60 degrees apart
}

}  // namespace
}  // namespace iblkit
