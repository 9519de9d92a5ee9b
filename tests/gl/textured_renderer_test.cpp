// The renderer with textured materials, on a quad with generated textures (docs/engine.md
// "Textures", "Alpha"): unlit head-on it shows the CPU's evaluateSurfaceMaterial base colour; a
// masked hole shows the sky; a single-sided quad seen from behind is culled and a double-sided one
// shaded facing the viewer; switching a slot off changes the frame to the factor; BLEND covers
// alpha of the samples; the glTF occlusion modes read the occlusion texture.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <optional>
#include <string>

#include "core/surface_material.h"
#include "core/texture_sampling.h"
#include "engine/gl/render_target.h"
#include "engine/gl/renderer.h"
#include "gl/test_context.h"
#include "support/bake_fixture.h"

namespace iblkit {
namespace {

constexpr int kSize = 64;

// A 4 x 4 image, texel (x, y) = texel(x, y) (RGBA bytes), row 0 at the top (uv v = 0).
TextureImage image4x4(const std::function<glm::u8vec4(int, int)>& texel) {
  TextureImage image;
  image.name = "generated";
  image.mimeType = "image/png";
  image.width = image.height = 4;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const glm::u8vec4 t = texel(x, y);
      image.rgba.insert(image.rgba.end(), {t.r, t.g, t.b, t.a});
    }
  return image;
}

TextureSampler nearestSampler() {
  TextureSampler s;
  s.magFilter = s.minFilter = TextureFilter::Nearest;
  s.mipmaps = false;
  return s;
}

// The quad z = 0, [-1, 1]^2, facing +Z (counter-clockwise seen from +Z), uv (0, 0) at its top left
// (-1, 1), material 0; baked (no occluder: AO about 1) under testSky.
BakedScene quadBake(const Material& material, std::vector<TextureImage> images, std::vector<Texture> textures,
                    float eyeZ = 2.5f) {
  BakedScene bake;
  Scene& scene = bake.scene;
  Mesh quad;
  quad.name = "quad";
  quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  quad.normals.assign(4, glm::vec3(0, 0, 1));
  quad.texcoords = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  quad.tangents.assign(4, glm::vec4(1, 0, 0, 1));
  quad.indices = {0, 1, 2, 0, 2, 3};
  scene.meshes.push_back(quad);
  scene.materials.push_back(material);
  scene.images = std::move(images);
  scene.textures = std::move(textures);
  scene.bounds = objectBounds(scene.meshes);
  scene.camera = Camera::lookAt(glm::vec3(0, 0, eyeZ), glm::vec3(0), glm::vec3(0, 1, 0), glm::radians(60.0f), 0.1f, 50.0f);
  VisibilitySettings settings;
  settings.rayCount = 8;
  attachVisibilityAttributes(scene.meshes, bakeVertexVisibility(scene.meshes, settings));
  bake.env = computeEnvironmentStages(test::testSky(), {.shWindowCutoff = std::nullopt,
                                                        .specularSamples = 16,
                                                        .lutSize = 16,
                                                        .lutSamples = 16,
                                                        .irradianceCubeSize = 0});
  return bake;
}

struct Frame {
  Image image;
  Camera camera;
};

Frame render(Renderer& renderer, const FrameSettings& settings, int samples = 1) {
  test::glContext();
  RenderTarget target(kSize, kSize, samples);
  const Camera camera = sceneCamera(renderer.scene(), 1.0f);
  renderer.render(camera, settings, target.framebuffer(), kSize, kSize);
  Frame frame{target.readColor(), camera};
  checkGlErrors("textured frame");
  return frame;
}

// The quad's uv under pixel (x, y)'s centre (row 0 at the top), if the camera ray meets the quad.
std::optional<glm::vec2> quadUv(const Camera& camera, int x, int y) {
  const Ray ray = camera.primaryRay(glm::vec2(x, y) + 0.5f, kSize, kSize);
  if (ray.direction.z == 0.0f) return std::nullopt;
  const float t = -ray.origin.z / ray.direction.z;
  const glm::vec3 p = ray.origin + t * ray.direction;
  if (t <= 0.0f || std::abs(p.x) > 1.0f || std::abs(p.y) > 1.0f) return std::nullopt;
  return glm::vec2((p.x + 1.0f) / 2.0f, (1.0f - p.y) / 2.0f);
}

// Whether uv is at least `margin` (uv units) inside one texel of a 4 x 4 texture.
bool insideTexel(glm::vec2 uv, float margin = 0.03f) {
  const glm::vec2 f = glm::fract(uv * 4.0f) / 4.0f;
  return f.x > margin && f.x < 0.25f - margin && f.y > margin && f.y < 0.25f - margin;
}

glm::u8vec4 checker(int x, int y) {
  return (x + y) % 2 ? glm::u8vec4(230, 40, 20, 255) : glm::u8vec4(30, 120, 250, 255);
}

Material texturedMaterial() {
  Material m;
  m.baseColor = {0.9f, 0.8f, 0.7f};
  m.metallic = 0.0f;
  m.roughness = 0.6f;
  m.baseColorTexture.texture = 0;
  return m;
}

TEST(TexturedRenderer, UnlitQuadShowsTheCpuBaseColor) {
  test::glContext();
  const BakedScene bake = quadBake(texturedMaterial(), {image4x4(checker)}, {{"checker", 0, nearestSampler()}});
  Renderer renderer(bake);
  FrameSettings settings;
  settings.mode = ShadingMode::Unlit;
  const Frame frame = render(renderer, settings);
  const SceneTextures textures(bake.scene.textures, bake.scene.images, bake.scene.materials);
  int compared = 0;
  float maxError = 0.0f;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const std::optional<glm::vec2> uv = quadUv(frame.camera, x, y);
      if (!uv || !insideTexel(*uv)) continue;
      SurfaceInputs in;
      in.texcoords[0] = *uv;
      const glm::vec3 expected = evaluateSurfaceMaterial(bake.scene.materials[0], textures, in).baseColor;
      const glm::vec4 p = frame.image.at(x, y);
      maxError = std::max(maxError, glm::length(glm::vec3(p) - expected));
      EXPECT_NEAR(p.a, 1.0f, 0.0f) << x << ", " << y;
      ++compared;
    }
  EXPECT_GT(compared, 500);
  // llvmpipe's sRGB decode (tests/gl/material_test.cpp) and nothing else.
  EXPECT_LT(maxError, 3e-3f);
  std::cout << "unlit textured quad: " << compared << " pixels, max |GPU - CPU| " << maxError << '\n';
}

// Trilinear (the default sampler) on a 64 x 64 checker seen head-on: the GPU's level of detail
// against the CPU's from the pixel's uv footprint, on average over the quad.
TEST(TexturedRenderer, TrilinearQuadMatchesTheCpuOnAverage) {
  test::glContext();
  TextureImage fine;
  fine.width = fine.height = 64;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const glm::u8vec4 t = checker(x / 2, y / 2);
      fine.rgba.insert(fine.rgba.end(), {t.r, t.g, t.b, t.a});
    }
  const BakedScene bake = quadBake(texturedMaterial(), {fine}, {{"fine", 0, TextureSampler{}}});
  const SceneTextures textures(bake.scene.textures, bake.scene.images, bake.scene.materials);
  // Isotropic (anisotropy 1) is the CPU's rule; the default anisotropy is measured only: llvmpipe's
  // anisotropic path selects about one level coarser on an isotropic footprint (docs/engine.md).
  for (float anisotropy : {1.0f, kDefaultTextureAnisotropy}) {
  Renderer renderer(bake, anisotropy);
  FrameSettings settings;
  settings.mode = ShadingMode::Unlit;
  const Frame frame = render(renderer, settings);
  double error = 0.0;
  int compared = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const std::optional<glm::vec2> uv = quadUv(frame.camera, x, y), right = quadUv(frame.camera, x + 1, y);
      if (!uv || !right || !insideTexel(*uv, 0.01f)) continue;
      SurfaceInputs in;
      in.texcoords[0] = *uv;
      in.footprintUv[0] = glm::length(*right - *uv);
      const glm::vec3 expected = evaluateSurfaceMaterial(bake.scene.materials[0], textures, in).baseColor;
      error += glm::length(glm::vec3(frame.image.at(x, y)) - expected);
      ++compared;
    }
  ASSERT_GT(compared, 500);
  const double meanError = error / compared;
  if (anisotropy == 1.0f) {
    EXPECT_LT(meanError, 5e-3);
  }
  std::cout << "trilinear textured quad, anisotropy " << renderer.textureAnisotropy() << ": " << compared
            << " pixels, mean |GPU - CPU| " << meanError << '\n';
  }
}

glm::u8vec4 holeAt11(int x, int y) {
  glm::u8vec4 t = checker(x, y);
  t.a = x == 1 && y == 1 ? 0 : 255;
  return t;
}

TEST(TexturedRenderer, MaskedHoleShowsTheSky) {
  test::glContext();
  Material m = texturedMaterial();
  m.alphaMode = AlphaMode::Mask;
  m.alphaCutoff = 0.5f;
  const BakedScene bake = quadBake(m, {image4x4(holeAt11)}, {{"hole", 0, nearestSampler()}});
  Renderer renderer(bake);
  const FrameSettings settings;  // full
  const Frame frame = render(renderer, settings);
  Material gone = m;
  gone.alpha = 0.0f;  // every texel below the cutoff: the sky alone
  renderer.setMaterial(0, gone);
  const Frame sky = render(renderer, settings);
  int hole = 0, solid = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const std::optional<glm::vec2> uv = quadUv(frame.camera, x, y);
      if (!uv || !insideTexel(*uv)) continue;
      const glm::ivec2 texel(glm::floor(*uv * 4.0f));
      const glm::vec4 p = frame.image.at(x, y), s = sky.image.at(x, y);
      if (texel == glm::ivec2(1, 1)) {
        EXPECT_EQ(p, s) << x << ", " << y;
        EXPECT_EQ(p.a, 0.0f);
        ++hole;
      } else {
        EXPECT_EQ(p.a, 1.0f) << x << ", " << y;
        EXPECT_GT(glm::length(glm::vec3(p - s)), 1e-3f) << x << ", " << y;
        ++solid;
      }
    }
  EXPECT_GT(hole, 30);
  EXPECT_GT(solid, 300);
}

int coveredPixels(const Image& image) {
  int covered = 0;
  for (const glm::vec4& p : image.pixels()) covered += p.a > 0.0f;
  return covered;
}

TEST(TexturedRenderer, SingleSidedBackFaceIsCulledDoubleSidedIsShadedTowardsTheViewer) {
  test::glContext();
  Material m = texturedMaterial();
  const BakedScene front = quadBake(m, {image4x4(checker)}, {{"checker", 0, nearestSampler()}});
  const BakedScene behind = quadBake(m, {image4x4(checker)}, {{"checker", 0, nearestSampler()}}, -2.5f);
  Renderer frontRenderer(front), behindRenderer(behind);
  FrameSettings settings;
  settings.layer = FrameLayer::Normal;
  EXPECT_GT(coveredPixels(render(frontRenderer, settings).image), 1000);
  EXPECT_EQ(coveredPixels(render(behindRenderer, settings).image), 0);
  m.doubleSided = true;
  behindRenderer.setMaterial(0, m);
  const Image normals = render(behindRenderer, settings).image;
  EXPECT_GT(coveredPixels(normals), 1000);
  const glm::vec4 centre = normals.at(kSize / 2, kSize / 2);
  EXPECT_NEAR(centre.z, -1.0f, 1e-5f);  // the back face's normal, towards the camera at z < 0
}

TEST(TexturedRenderer, SlotSwitchesChangeTheFrame) {
  test::glContext();
  Material m = texturedMaterial();
  m.emissive = glm::vec3(0.5f);
  m.emissiveTexture.texture = 0;
  const BakedScene bake = quadBake(m, {image4x4(checker)}, {{"checker", 0, nearestSampler()}});
  Renderer renderer(bake);
  FrameSettings settings;
  settings.mode = ShadingMode::Unlit;
  const glm::vec4 on = render(renderer, settings).image.at(kSize / 2 + 5, kSize / 2 + 5);
  settings.textureSlots = kAllTextureSlots & ~kSlotBaseColor;
  const glm::vec4 off = render(renderer, settings).image.at(kSize / 2 + 5, kSize / 2 + 5);
  EXPECT_GT(glm::length(glm::vec3(on - off)), 0.05f);
  EXPECT_NEAR(off.r, m.baseColor.r, 1e-6f);  // the factor alone
  EXPECT_NEAR(off.g, m.baseColor.g, 1e-6f);
  EXPECT_NEAR(off.b, m.baseColor.b, 1e-6f);
  // Emission: the full frame with and without the emissive slot.
  settings.mode = ShadingMode::Full;
  settings.textureSlots = kAllTextureSlots;
  const glm::vec4 emissiveOn = render(renderer, settings).image.at(kSize / 2 + 5, kSize / 2 + 5);
  settings.textureSlots = kAllTextureSlots & ~kSlotEmissive;
  const glm::vec4 emissiveOff = render(renderer, settings).image.at(kSize / 2 + 5, kSize / 2 + 5);
  EXPECT_GT(glm::length(glm::vec3(emissiveOn - emissiveOff)), 0.05f);
}

// BLEND: alpha as coverage (docs/engine.md "Alpha"): alpha 0.3 covers about 30% of the pixels of a
// single-sample frame and 30% of each pixel's 4 samples on average.
TEST(TexturedRenderer, BlendAlphaIsCoverage) {
  test::glContext();
  Material m;
  m.baseColor = glm::vec3(0.5f);
  m.alpha = 0.3f;
  m.alphaMode = AlphaMode::Blend;
  const BakedScene bake = quadBake(m, {}, {});
  Renderer renderer(bake);
  FrameSettings settings;
  settings.drawSky = false;
  for (int samples : {1, 4}) {
    const Frame frame = render(renderer, settings, samples);
    double coverage = 0.0;
    int pixels = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const std::optional<glm::vec2> uv = quadUv(frame.camera, x, y);
        if (!uv || glm::any(glm::lessThan(*uv, glm::vec2(0.05f))) || glm::any(glm::greaterThan(*uv, glm::vec2(0.95f))))
          continue;
        coverage += frame.image.at(x, y).a;
        ++pixels;
      }
    ASSERT_GT(pixels, 1000);
    EXPECT_NEAR(coverage / pixels, 0.3, 0.03) << samples << " samples";
  }
}

// The normal layer of a normal-mapped quad (one texel, so every filter reads it) is core's
// perturbNormal of the vertex frame: the TANGENT attribute reaches the shader, w = -1 flips the
// bitangent, and the normal scale scales x and y.
TEST(TexturedRenderer, NormalMapPerturbsTheNormalLayerAsTheCpu) {
  test::glContext();
  Material m = texturedMaterial();
  m.baseColorTexture = TextureRef{};
  m.normalTexture.texture = 0;
  m.normalScale = 0.7f;
  const glm::u8vec4 texel(200, 100, 230, 255);
  TextureImage one;
  one.width = one.height = 1;
  one.rgba = {texel.r, texel.g, texel.b, texel.a};
  for (float w : {1.0f, -1.0f}) {
    BakedScene bake = quadBake(m, {one}, {{"normal", 0, TextureSampler{}}});
    for (glm::vec4& t : bake.scene.meshes[0].tangents) t.w = w;
    Renderer renderer(bake);
    FrameSettings settings;
    settings.layer = FrameLayer::Normal;
    const Image normals = render(renderer, settings).image;
    const glm::vec3 expected =
        perturbNormal(glm::vec3(0, 0, 1), glm::vec4(1, 0, 0, w), glm::vec3(texel) / 255.0f, m.normalScale);
    const glm::vec3 gpu(normals.at(kSize / 2, kSize / 2));
    EXPECT_LT(glm::length(gpu - expected), 1e-4f) << "w " << w;
    EXPECT_GT(std::abs(expected.y), 0.1f);  // the bitangent's part is there to be flipped
    settings.textureSlots = kAllTextureSlots & ~kSlotNormal;
    const glm::vec3 flat(render(renderer, settings).image.at(kSize / 2, kSize / 2));
    EXPECT_LT(glm::length(flat - glm::vec3(0, 0, 1)), 1e-6f);
  }
}

// full-gltf-ao and full-both-ao read the occlusion texture: R = 0 (strength 1) on the left half
// takes the environment's light away there; R = 1 on the right half changes nothing.
TEST(TexturedRenderer, GltfOcclusionModesReadTheOcclusionTexture) {
  test::glContext();
  Material m;
  m.baseColor = glm::vec3(0.8f);
  m.metallic = 0.0f;
  m.roughness = 0.5f;
  m.occlusionTexture.texture = 0;
  const BakedScene bake = quadBake(
      m, {image4x4([](int x, int) { return glm::u8vec4(x < 2 ? 0 : 255, 0, 0, 255); })}, {{"ao", 0, nearestSampler()}});
  Renderer renderer(bake);
  for (ShadingMode mode : {ShadingMode::FullGltfAo, ShadingMode::FullBothAo}) {
    FrameSettings settings;
    settings.mode = mode;
    const Frame on = render(renderer, settings);
    settings.textureSlots = kAllTextureSlots & ~kSlotOcclusion;
    const Frame off = render(renderer, settings);
    const glm::vec4 leftOn = on.image.at(kSize / 2 - 12, kSize / 2), leftOff = off.image.at(kSize / 2 - 12, kSize / 2);
    const glm::vec4 rightOn = on.image.at(kSize / 2 + 12, kSize / 2), rightOff = off.image.at(kSize / 2 + 12, kSize / 2);
    EXPECT_GT(leftOff.g, 0.1f) << shadingModeName(mode);
    EXPECT_LT(leftOn.g, 1e-4f) << shadingModeName(mode);
    EXPECT_NEAR(rightOn.g, rightOff.g, 1e-6f) << shadingModeName(mode);
  }
  // Without an occlusion texture full-both-ao is full.
  FrameSettings settings;
  settings.textureSlots = 0;
  settings.mode = ShadingMode::Full;
  const glm::vec4 full = render(renderer, settings).image.at(kSize / 2, kSize / 2);
  settings.mode = ShadingMode::FullBothAo;
  const glm::vec4 both = render(renderer, settings).image.at(kSize / 2, kSize / 2);
  EXPECT_NEAR(full.g, both.g, 1e-6f);
}

}  // namespace
}  // namespace iblkit
