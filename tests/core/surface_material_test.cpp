#include "core/surface_material.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/tangent_frames.h"

namespace iblkit {
namespace {

constexpr float kDegrees = 180.0f / std::numbers::pi_v<float>;

float angleDegrees(const glm::vec3& a, const glm::vec3& b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)) * kDegrees;
}

// Two distinct texels side by side: left (x 0) and right (x 1), each with its own R, G, B, A.
constexpr std::uint8_t kTexels[2][4] = {{40, 128, 200, 230}, {220, 30, 90, 60}};

struct Fixture {
  std::vector<Texture> textures;
  std::vector<TextureImage> images;
  Material material;
  SceneTextures sceneTextures;

  Fixture() {
    TextureImage image;
    image.width = 2;
    image.height = 1;
    for (const auto& texel : kTexels)
      for (std::uint8_t channel : texel) image.rgba.push_back(channel);
    images.push_back(image);
    Texture texture;
    texture.image = 0;
    texture.sampler.magFilter = texture.sampler.minFilter = TextureFilter::Nearest;
    texture.sampler.wrapS = texture.sampler.wrapT = TextureWrap::ClampToEdge;
    textures.push_back(texture);
    material.baseColor = glm::vec3(0.5f, 0.8f, 1.0f);
    material.alpha = 0.9f;
    material.metallic = 0.7f;
    material.roughness = 0.6f;
    material.emissive = glm::vec3(2.0f, 3.0f, 4.0f);
    material.occlusionStrength = 0.75f;
    for (TextureRef* ref : {&material.baseColorTexture, &material.metallicRoughnessTexture,
                            &material.occlusionTexture, &material.emissiveTexture})
      ref->texture = 0;
    sceneTextures = SceneTextures(textures, images, {material});
  }
};

float linear(std::uint8_t value) { return value / 255.0f; }

SurfaceInputs at(glm::vec2 uv0, glm::vec2 uv1 = glm::vec2(0.0f)) {
  SurfaceInputs inputs;
  inputs.texcoords[0] = uv0;
  inputs.texcoords[1] = uv1;
  return inputs;
}

TEST(EvaluateSurfaceMaterial, EachSlotReadsItsChannelsTimesItsFactors) {
  const Fixture f;
  for (int x = 0; x < 2; ++x) {
    const auto& t = kTexels[x];
    const SurfaceMaterial s = evaluateSurfaceMaterial(f.material, f.sceneTextures, at(glm::vec2(0.25f + 0.5f * x, 0.5f)));
    const glm::vec3 srgbRgb(srgbToLinear(t[0]), srgbToLinear(t[1]), srgbToLinear(t[2]));
    EXPECT_NEAR(glm::distance(s.baseColor, f.material.baseColor * srgbRgb), 0.0f, 1e-6f) << x;
    EXPECT_NEAR(s.alpha, 0.9f * linear(t[3]), 1e-6f) << x;
    EXPECT_NEAR(s.alpha, s.alpha, 1e-6f);
    EXPECT_NEAR(s.roughness, 0.6f * linear(t[1]), 1e-6f) << x;  // G
    EXPECT_NEAR(s.metallic, 0.7f * linear(t[2]), 1e-6f) << x;   // B
    EXPECT_NEAR(s.occlusion, 1.0f + 0.75f * (linear(t[0]) - 1.0f), 1e-6f) << x;  // R
    EXPECT_NEAR(glm::distance(s.emissive, f.material.emissive * srgbRgb), 0.0f, 1e-5f) << x;
    EXPECT_EQ(s.normal, glm::vec3(0.0f, 0.0f, 1.0f));
    EXPECT_NEAR(surfaceAlpha(f.material, f.sceneTextures, at(glm::vec2(0.25f + 0.5f * x, 0.5f))), s.alpha, 1e-6f);
  }
}

TEST(EvaluateSurfaceMaterial, SlotBitsSwitchSlotsOff) {
  const Fixture f;
  SurfaceInputs inputs = at(glm::vec2(0.25f, 0.5f));
  inputs.slots = 0;
  const SurfaceMaterial none = evaluateSurfaceMaterial(f.material, f.sceneTextures, inputs);
  EXPECT_EQ(none.baseColor, f.material.baseColor);
  EXPECT_EQ(none.alpha, f.material.alpha);
  EXPECT_EQ(none.roughness, f.material.roughness);
  EXPECT_EQ(none.metallic, f.material.metallic);
  EXPECT_EQ(none.emissive, f.material.emissive);
  EXPECT_EQ(none.occlusion, 1.0f);
  EXPECT_EQ(surfaceAlpha(f.material, f.sceneTextures, inputs), f.material.alpha);
  // Only metallic-roughness on: the others keep their factors.
  inputs.slots = kSlotMetallicRoughness;
  const SurfaceMaterial mr = evaluateSurfaceMaterial(f.material, f.sceneTextures, inputs);
  EXPECT_EQ(mr.baseColor, f.material.baseColor);
  EXPECT_EQ(mr.occlusion, 1.0f);
  EXPECT_NEAR(mr.roughness, 0.6f * linear(kTexels[0][1]), 1e-6f);
}

TEST(EvaluateSurfaceMaterial, SlotsReadTheirTexCoordSet) {
  Fixture f;
  f.material.occlusionTexture.texCoord = 1;
  // TEXCOORD_0 on the left texel, TEXCOORD_1 on the right one.
  const SurfaceMaterial s =
      evaluateSurfaceMaterial(f.material, f.sceneTextures, at(glm::vec2(0.25f, 0.5f), glm::vec2(0.75f, 0.5f)));
  EXPECT_NEAR(s.occlusion, 1.0f + 0.75f * (linear(kTexels[1][0]) - 1.0f), 1e-6f);
  EXPECT_NEAR(s.roughness, 0.6f * linear(kTexels[0][1]), 1e-6f);
}

TEST(EvaluateSurfaceMaterial, TextureWithoutAnImageLeavesTheFactors) {
  Fixture f;
  f.textures[0].image = 3;  // no such image
  const SceneTextures broken(f.textures, f.images, {f.material});
  const SurfaceMaterial s = evaluateSurfaceMaterial(f.material, broken, at(glm::vec2(0.25f, 0.5f)));
  EXPECT_EQ(s.baseColor, f.material.baseColor);
  EXPECT_EQ(s.occlusion, 1.0f);
}

TEST(SurfacePresent, FollowsTheAlphaMode) {
  Material material;
  EXPECT_TRUE(surfacePresent(material, 0.0f, 0.99f));  // OPAQUE ignores alpha
  material.alphaMode = AlphaMode::Mask;
  material.alphaCutoff = 0.5f;
  EXPECT_TRUE(surfacePresent(material, 0.5f, 0.99f));
  EXPECT_FALSE(surfacePresent(material, 0.49f, 0.0f));
  material.alphaMode = AlphaMode::Blend;
  EXPECT_TRUE(surfacePresent(material, 0.3f, 0.29f));
  EXPECT_FALSE(surfacePresent(material, 0.3f, 0.3f));
  EXPECT_FALSE(surfacePresent(material, 0.0f, 0.0f));
  EXPECT_TRUE(surfacePresent(material, 1.0f, 0.999f));
}

glm::vec3 encode(const glm::vec3& unitNormal) { return 0.5f * unitNormal + 0.5f; }

TEST(PerturbNormal, TiltsAlongTangentAndBitangent) {
  const float a = 30.0f / kDegrees;
  const glm::vec3 n(0.0f, 0.0f, 1.0f);
  const glm::vec4 t(1.0f, 0.0f, 0.0f, 1.0f);
  EXPECT_LT(angleDegrees(perturbNormal(n, t, glm::vec3(0.5f, 0.5f, 1.0f), 1.0f), n), 1e-4f);
  EXPECT_LT(angleDegrees(perturbNormal(n, t, encode({std::sin(a), 0, std::cos(a)}), 1.0f),
                         glm::vec3(std::sin(a), 0, std::cos(a))),
            1e-3f);
  // Green tilts towards the bitangent w cross(n, t): +y for w = +1, -y for w = -1.
  EXPECT_LT(angleDegrees(perturbNormal(n, t, encode({0, std::sin(a), std::cos(a)}), 1.0f),
                         glm::vec3(0, std::sin(a), std::cos(a))),
            1e-3f);
  EXPECT_LT(angleDegrees(perturbNormal(n, glm::vec4(1, 0, 0, -1), encode({0, std::sin(a), std::cos(a)}), 1.0f),
                         glm::vec3(0, -std::sin(a), std::cos(a))),
            1e-3f);
  // scale multiplies x and y before normalising.
  EXPECT_LT(angleDegrees(perturbNormal(n, t, encode({std::sin(a), 0, std::cos(a)}), 2.0f),
                         glm::vec3(2 * std::sin(a), 0, std::cos(a))),
            1e-3f);
  // Another frame: n = +y, t = +x, so b = cross(y, x) = -z.
  EXPECT_LT(angleDegrees(perturbNormal(glm::vec3(0, 1, 0), t, encode({0, std::sin(a), std::cos(a)}), 1.0f),
                         glm::vec3(0, std::cos(a), -std::sin(a))),
            1e-3f);
  // A zero tangent leaves n.
  EXPECT_EQ(perturbNormal(n, glm::vec4(0.0f), encode({1, 0, 0}), 1.0f), n);
}

// The normal of the height field z = 0.03 (sin 2 pi x + cos 2 pi y) + 0.02 x over the unit square.
glm::vec3 heightNormal(float x, float y) {
  const float k = 2.0f * std::numbers::pi_v<float>;
  const float hx = 0.03f * k * std::cos(k * x) + 0.02f, hy = -0.03f * k * std::sin(k * y);
  return glm::normalize(glm::vec3(-hx, -hy, 1.0f));
}

TEST(EvaluateSurfaceMaterial, NormalMapOfAHeightFieldGivesItsNormal) {
  // A unit quad in z = 0 with the image upright on it (glTF uv: v down the image, so v = 1 - y),
  // tangents generated, and a normal texture holding the height field's tangent-space normal,
  // which for this frame (t = +x, bitangent = up the image = +y) is its world normal. The
  // perturbed normal must be the height field's: this checks the channel convention (+Y up the
  // image, glTF 2.0 section 3.9.3), the handedness of generated tangents and the filtering.
  Mesh quad;
  quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  quad.normals.assign(4, glm::vec3(0, 0, 1));
  quad.texcoords = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  ASSERT_EQ(generateTangents(quad), 4u);

  const int size = 64;
  TextureImage image;
  image.width = image.height = size;
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const glm::vec3 n = heightNormal((i + 0.5f) / size, 1.0f - (j + 0.5f) / size);
      for (int c = 0; c < 3; ++c) image.rgba.push_back(static_cast<std::uint8_t>(std::lround((0.5f * n[c] + 0.5f) * 255)));
      image.rgba.push_back(255);
    }
  Texture texture;
  texture.image = 0;
  Material material;
  material.normalTexture.texture = 0;
  const SceneTextures textures({texture}, {image}, {material});

  float worst = 0.0f, worstFlat = 0.0f;
  for (int sample = 0; sample < 200; ++sample) {
    const float x = 0.05f + 0.9f * std::fmod(sample * 0.618034f, 1.0f), y = 0.05f + 0.9f * std::fmod(sample * 0.414214f, 1.0f);
    SurfaceInputs inputs;
    inputs.texcoords[0] = glm::vec2(x, 1.0f - y);
    inputs.normal = glm::vec3(0, 0, 1);
    inputs.tangent = quad.tangents[0];
    const glm::vec3 normal = evaluateSurfaceMaterial(material, textures, inputs).normal;
    EXPECT_NEAR(glm::length(normal), 1.0f, 1e-5f);
    worst = std::max(worst, angleDegrees(normal, heightNormal(x, y)));
    worstFlat = std::max(worstFlat, angleDegrees(glm::vec3(0, 0, 1), heightNormal(x, y)));
    // Switched off, or without a tangent, the normal is the input's.
    inputs.slots = kAllTextureSlots & ~kSlotNormal;
    EXPECT_EQ(evaluateSurfaceMaterial(material, textures, inputs).normal, inputs.normal);
  }
  EXPECT_LT(worst, 1.0f);
  EXPECT_GT(worstFlat, 8.0f);  // the map does tilt normals by much more than the tolerance
}

// A normal that faces the viewer by kMinShadingCosine or more is kept; one that faces it less or
// away is turned towards it in their common plane to exactly that cosine, the nearest normal that
// does; the rule is continuous across the threshold (no jump to the geometric normal).
TEST(ShadingNormalFacingViewer, TurnsANormalJustEnoughToFaceTheViewer) {
  const glm::vec3 wo(0.0f, 0.0f, 1.0f), geometric = glm::normalize(glm::vec3(0.0f, 0.1f, 1.0f));
  const glm::vec3 facing = glm::normalize(glm::vec3(1.0f, 0.0f, 0.5f));
  EXPECT_EQ(shadingNormalFacingViewer(facing, wo, geometric), facing);
  for (float z : {0.005f, 0.0f, -0.3f, -0.99f}) {
    const glm::vec3 n = glm::normalize(glm::vec3(0.6f, -0.8f, z));
    const glm::vec3 turned = shadingNormalFacingViewer(n, wo, geometric);
    EXPECT_NEAR(glm::length(turned), 1.0f, 1e-6f) << z;
    EXPECT_NEAR(glm::dot(turned, wo), kMinShadingCosine, 1e-6f) << z;
    EXPECT_NEAR(glm::dot(glm::cross(n, wo), turned), 0.0f, 1e-6f) << z << ": in the plane of n and wo";
    EXPECT_NEAR(turned.x / turned.y, n.x / n.y, 1e-5f) << z << ": the same azimuth about wo";
  }
  // Continuous: just below and just above the threshold the results are within the normals' step.
  const float c = kMinShadingCosine;
  const glm::vec3 above(std::sqrt(1.0f - (c + 1e-4f) * (c + 1e-4f)), 0.0f, c + 1e-4f);
  const glm::vec3 below(std::sqrt(1.0f - (c - 1e-4f) * (c - 1e-4f)), 0.0f, c - 1e-4f);
  EXPECT_LT(glm::length(shadingNormalFacingViewer(above, wo, geometric) -
                        shadingNormalFacingViewer(below, wo, geometric)),
            2e-4f);
  // Straight away from the viewer no plane is defined: the geometric normal.
  EXPECT_EQ(shadingNormalFacingViewer(-wo, wo, geometric), geometric);
}

}  // namespace
}  // namespace iblkit
