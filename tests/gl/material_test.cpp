// shaders/material.glsl, the GLSL twin of core/surface_material.h, against the C++ on the same
// generated textures (uploaded by MaterialTextures, the renderer's own upload, with the uniforms of
// setMaterialUniforms): every slot's channel use and factor product, the slot switches, the
// normal-map perturbation, KHR_texture_transform, the wrap modes at the edges and the sRGB decode
// of the texture unit (shaders/material_probe.frag).
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/constants.hpp>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/surface_material.h"
#include "core/texture_sampling.h"
#include "engine/gl/material_textures.h"
#include "gl/fragment_probe.h"

namespace iblkit {
namespace {

constexpr int kProbes = 48;

TextureImage randomImage(int width, int height, unsigned seed) {
  std::mt19937 rng(seed);
  TextureImage image;
  image.name = "random " + std::to_string(seed);
  image.mimeType = "image/png";
  image.width = width;
  image.height = height;
  image.rgba.resize(std::size_t(width) * height * 4);
  for (std::uint8_t& value : image.rgba) value = std::uint8_t(rng() & 255u);
  return image;
}

// Five 4 x 4 random textures, one per slot, with `sampler`; a material reading each (occlusion
// through TEXCOORD_1), with factors away from 1.
Scene materialScene(const TextureSampler& sampler) {
  Scene scene;
  for (int slot = 0; slot < 5; ++slot) {
    scene.images.push_back(randomImage(4, 4, 17u + unsigned(slot)));
    scene.textures.push_back(Texture{.name = "", .image = slot, .sampler = sampler});
  }
  Material m;
  m.baseColor = {0.8f, 0.6f, 0.4f};
  m.alpha = 0.9f;
  m.metallic = 0.7f;
  m.roughness = 0.9f;
  m.emissive = {2.0f, 1.0f, 0.5f};
  m.normalScale = 0.8f;
  m.occlusionStrength = 0.6f;
  m.baseColorTexture.texture = 0;
  m.metallicRoughnessTexture.texture = 1;
  m.normalTexture.texture = 2;
  m.occlusionTexture.texture = 3;
  m.occlusionTexture.texCoord = 1;
  m.emissiveTexture.texture = 4;
  scene.materials.push_back(m);
  return scene;
}

struct ProbePoints {
  Image uvs{kProbes, 1}, normals{kProbes, 1}, tangents{kProbes, 1}, colors{kProbes, 1};
  std::vector<SurfaceInputs> inputs;
};

// Random unit normals and tangents (orthogonal to them, w = +-1); uvs at texel centres of the 4 x 4
// textures (so that NEAREST cannot fall on a texel edge), or anywhere in [-1.5, 2.5] when `anywhere`.
ProbePoints probePoints(bool anywhere) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  ProbePoints p;
  for (int i = 0; i < kProbes; ++i) {
    SurfaceInputs in;
    for (glm::vec2& uv : in.texcoords)
      uv = anywhere ? glm::vec2(0.5f + 2.0f * unit(rng), 0.5f + 2.0f * unit(rng))
                    : (glm::vec2(float(rng() % 4u), float(rng() % 4u)) + 0.5f) / 4.0f;
    glm::vec3 n;
    do n = glm::vec3(unit(rng), unit(rng), unit(rng));
    while (glm::length(n) < 0.2f);
    in.normal = glm::normalize(n);
    const glm::vec3 t = glm::normalize(glm::cross(in.normal, glm::vec3(unit(rng), unit(rng), unit(rng))));
    in.tangent = glm::vec4(t, i % 2 ? -1.0f : 1.0f);
    // A vertex colour (COLOR_0) on every other point, white elsewhere (a mesh without one).
    if (i % 2 == 0)
      in.vertexColor = 0.5f + 0.5f * glm::vec4(unit(rng), unit(rng), unit(rng), unit(rng));
    p.inputs.push_back(in);
    p.colors.at(i, 0) = in.vertexColor;
    p.uvs.at(i, 0) = glm::vec4(in.texcoords[0], in.texcoords[1]);
    p.normals.at(i, 0) = glm::vec4(in.normal, 0.0f);
    p.tangents.at(i, 0) = in.tangent;
  }
  return p;
}

std::vector<glm::vec4> probe(const ProbePoints& p, const MaterialTextures& textures, const Material& material,
                             unsigned slots, int quantity) {
  return test::runFragmentProbe(
      "material_probe.frag", {{"uvs", &p.uvs}, {"normals", &p.normals}, {"tangents", &p.tangents}, {"colors", &p.colors}},
      [&](const ShaderProgram& program) {
        const unsigned bound = textures.bind(material, slots);
        setMaterialUniforms(program, material, bound);
        program.set("probeSlots", int(bound));
        program.set("quantity", quantity);
      });
}

float maxDifference(glm::vec4 a, glm::vec4 b) {
  const glm::vec4 d = glm::abs(a - b);
  return std::max(std::max(d.x, d.y), std::max(d.z, d.w));
}

// llvmpipe's SRGB8_ALPHA8 decode is an approximation of the IEC 61966-2-1 curve, within 1.2e-3 of
// srgbToLinear (measured by TextureUnitDecodesSrgbAsTheCore; GL 4.5 section 8.24 gives the curve
// but no precision): the sRGB slots (base colour, emissive) are compared within it.
constexpr float kSrgbDecodeTolerance = 1.5e-3f;

// Every output of the GPU evaluation against evaluateSurfaceMaterial, for the slot set `slots`:
// `tolerance` for what linear textures give, plus kSrgbDecodeTolerance where an sRGB one enters.
void compareWithCpu(const Scene& scene, const ProbePoints& p, unsigned slots, float tolerance) {
  test::glContext();
  const MaterialTextures gpuTextures(scene, 1.0f);
  const SceneTextures cpuTextures(scene.textures, scene.images, scene.materials);
  const Material& material = scene.materials[0];
  const std::vector<glm::vec4> base = probe(p, gpuTextures, material, slots, 0);
  const std::vector<glm::vec4> factors = probe(p, gpuTextures, material, slots, 1);
  const std::vector<glm::vec4> emissive = probe(p, gpuTextures, material, slots, 2);
  const std::vector<glm::vec4> normal = probe(p, gpuTextures, material, slots, 3);
  for (int i = 0; i < kProbes; ++i) {
    SurfaceInputs in = p.inputs[std::size_t(i)];
    in.slots = slots;
    const SurfaceMaterial cpu = evaluateSurfaceMaterial(material, cpuTextures, in);
    const std::string where = "slots " + std::to_string(slots) + ", point " + std::to_string(i);
    const float srgb = tolerance + kSrgbDecodeTolerance;
    EXPECT_LE(maxDifference(base[i], glm::vec4(cpu.baseColor, cpu.alpha)), srgb) << where;
    EXPECT_LE(maxDifference(factors[i], glm::vec4(cpu.metallic, cpu.roughness, cpu.occlusion, 0.0f)),
              tolerance)
        << where;
    EXPECT_LE(maxDifference(emissive[i], glm::vec4(cpu.emissive, 0.0f)), 2.0f * srgb) << where;
    EXPECT_LE(maxDifference(normal[i], glm::vec4(cpu.normal, 0.0f)), 4.0f * tolerance) << where;
  }
}

TEST(MaterialGlsl, EverySlotMatchesTheCppEvaluation) {
  TextureSampler nearest;
  nearest.magFilter = nearest.minFilter = TextureFilter::Nearest;
  nearest.mipmaps = false;
  const Scene scene = materialScene(nearest);
  const ProbePoints points = probePoints(false);
  compareWithCpu(scene, points, kAllTextureSlots, 2e-5f);
}

// Each slot switched off alone, and all of them: the factor alone where the slot is off.
TEST(MaterialGlsl, SlotSwitchesMatchTheCppEvaluation) {
  TextureSampler nearest;
  nearest.magFilter = nearest.minFilter = TextureFilter::Nearest;
  nearest.mipmaps = false;
  const Scene scene = materialScene(nearest);
  const ProbePoints points = probePoints(false);
  for (unsigned off : {unsigned(kSlotBaseColor), unsigned(kSlotMetallicRoughness), unsigned(kSlotNormal),
                       unsigned(kSlotOcclusion), unsigned(kSlotEmissive), unsigned(kAllTextureSlots)})
    compareWithCpu(scene, points, kAllTextureSlots & ~off, 2e-5f);
}

// Bilinear lookups anywhere in [-1.5, 2.5]^2 through each wrap mode on each axis and a
// KHR_texture_transform per slot: the GPU's filter weights have 8 fractional bits (llvmpipe),
// hence the tolerance.
TEST(MaterialGlsl, WrapModesAndTransformsMatchTheCppEvaluation) {
  const TextureWrap wraps[] = {TextureWrap::Repeat, TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat};
  const ProbePoints points = probePoints(true);
  for (TextureWrap s : wraps)
    for (TextureWrap t : wraps) {
      TextureSampler linear;
      linear.wrapS = s;
      linear.wrapT = t;
      linear.mipmaps = false;
      Scene scene = materialScene(linear);
      Material& m = scene.materials[0];
      m.baseColorTexture.transform = {.offset = {0.25f, -0.5f}, .rotation = 0.3f, .scale = {2.0f, 3.0f}};
      m.occlusionTexture.transform = {.offset = {0.0f, 0.1f}, .rotation = -1.2f, .scale = {0.5f, 0.5f}};
      m.emissiveTexture.transform = {.offset = {1.0f, 0.0f}, .rotation = 0.0f, .scale = {-1.0f, 1.0f}};
      compareWithCpu(scene, points, kAllTextureSlots, 1.0f / 64.0f);
    }
}

TEST(MaterialGlsl, TextureTransformMatchesTheCpp) {
  test::glContext();
  TextureSampler sampler;
  Scene scene = materialScene(sampler);
  Material& m = scene.materials[0];
  m.baseColorTexture.transform = {.offset = {0.25f, -0.5f}, .rotation = 0.3f, .scale = {2.0f, 3.0f}};
  m.occlusionTexture.transform = {.offset = {-1.0f, 0.1f}, .rotation = -1.2f, .scale = {0.5f, 4.0f}};
  const MaterialTextures textures(scene, 1.0f);
  const ProbePoints points = probePoints(true);
  const std::vector<glm::vec4> gpu = probe(points, textures, m, kAllTextureSlots, 4);
  for (int i = 0; i < kProbes; ++i) {
    const SurfaceInputs& in = points.inputs[std::size_t(i)];
    const glm::vec2 base = m.baseColorTexture.transform.apply(in.texcoords[0]);
    const glm::vec2 occlusion = m.occlusionTexture.transform.apply(in.texcoords[1]);
    EXPECT_LE(maxDifference(gpu[i], glm::vec4(base, occlusion)), 1e-5f) << i;
  }
  // A hand-computed case of the extension: rotation 90 degrees takes (1, 0) to (0, -1) in uv.
  const TextureTransform quarter{.rotation = glm::half_pi<float>()};
  const glm::vec2 turned = quarter.apply({1.0f, 0.0f});
  EXPECT_NEAR(turned.x, 0.0f, 1e-6f);
  EXPECT_NEAR(turned.y, -1.0f, 1e-6f);
}

// SRGB8_ALPHA8 decodes every 8-bit value as srgbToLinear (IEC 61966-2-1): 188 -> 0.5029; the
// alpha (and a GL_RGBA8 texture) reads value / 255.
TEST(MaterialGlsl, TextureUnitDecodesSrgbAsTheCore) {
  test::glContext();
  Scene scene;
  TextureImage ramp;
  ramp.width = 256;
  ramp.height = 1;
  for (int i = 0; i < 256; ++i)
    for (int c = 0; c < 4; ++c) ramp.rgba.push_back(std::uint8_t(i));
  scene.images.push_back(ramp);
  TextureSampler nearest;
  nearest.magFilter = nearest.minFilter = TextureFilter::Nearest;
  nearest.mipmaps = false;
  scene.textures.push_back(Texture{.name = "ramp", .image = 0, .sampler = nearest});
  Material m;
  m.baseColorTexture.texture = 0;
  scene.materials.push_back(m);
  const MaterialTextures textures(scene, 1.0f);
  ProbePoints points;
  points.uvs = points.normals = points.tangents = Image(256, 1);
  const std::vector<glm::vec4> gpu = test::runFragmentProbe(
      "material_probe.frag", {{"uvs", &points.uvs}, {"normals", &points.normals}, {"tangents", &points.tangents}},
      [&](const ShaderProgram& program) {
        textures.bind(m, kAllTextureSlots);
        program.set("quantity", 5);
      });
  float maxError = 0.0f;
  for (int i = 0; i < 256; ++i) {
    maxError = std::max(maxError, std::abs(gpu[i].r - srgbDecodeTable()[i]));
    EXPECT_NEAR(gpu[i].r, srgbToLinear(std::uint8_t(i)), kSrgbDecodeTolerance) << i;
    EXPECT_NEAR(gpu[i].a, float(i) / 255.0f, 1e-6f) << i;
  }
  EXPECT_NEAR(srgbToLinear(188), 0.5029f, 1e-4f);
  EXPECT_NEAR(gpu[188].g, 0.5029f, kSrgbDecodeTolerance);
  std::cout << "sRGB decode: GPU against srgbToLinear, max |difference| " << maxError << '\n';
}

// shadingNormalFacingViewer in GLSL against the C++: random normals, half of them facing away from
// a random viewer direction or nearly (the turned case), with a fixed geometric normal.
TEST(MaterialGlsl, ShadingNormalFacingViewerMatchesTheCpp) {
  test::glContext();
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  const auto randomUnit = [&] {
    glm::vec3 v;
    do v = glm::vec3(unit(rng), unit(rng), unit(rng));
    while (glm::length(v) < 0.2f);
    return glm::normalize(v);
  };
  ProbePoints points;
  std::vector<glm::vec3> n(kProbes), wo(kProbes), geometric(kProbes);
  int turned = 0;
  for (int i = 0; i < kProbes; ++i) {
    n[i] = randomUnit();
    wo[i] = randomUnit();
    geometric[i] = randomUnit();
    if (glm::dot(geometric[i], wo[i]) < 0.0f) geometric[i] = -geometric[i];
    if (i % 8 == 0) wo[i] = glm::normalize(wo[i] - glm::dot(wo[i], n[i]) * n[i]);  // n . wo = 0
    if (glm::dot(n[i], wo[i]) < kMinShadingCosine) ++turned;
    points.normals.at(i, 0) = glm::vec4(n[i], 0.0f);
    points.tangents.at(i, 0) = glm::vec4(wo[i], 1.0f);
    points.uvs.at(i, 0) = glm::vec4(geometric[i], 0.0f);
  }
  ASSERT_GT(turned, kProbes / 4);
  Scene scene = materialScene(TextureSampler{});
  const MaterialTextures textures(scene, 1.0f);
  const std::vector<glm::vec4> gpu = probe(points, textures, scene.materials[0], kAllTextureSlots, 6);
  for (int i = 0; i < kProbes; ++i)
    EXPECT_LE(maxDifference(gpu[i], glm::vec4(shadingNormalFacingViewer(n[i], wo[i], geometric[i]), 0.0f)),
              1e-5f)
        << "point " << i;
}

}  // namespace
}  // namespace iblkit
