#include "core/texture_sampling.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

namespace iblkit {
namespace {

// A width x height image whose texel (x, y) is texel(x, y) (RGBA bytes).
TextureImage makeImage(int width, int height, const std::function<glm::u8vec4(int, int)>& texel) {
  TextureImage image;
  image.width = width;
  image.height = height;
  image.rgba.resize(static_cast<std::size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::u8vec4 value = texel(x, y);
      for (int c = 0; c < 4; ++c) image.rgba[(static_cast<std::size_t>(y) * width + x) * 4 + c] = value[c];
    }
  return image;
}

TextureImage greyRamp(const std::vector<std::uint8_t>& values) {
  return makeImage(static_cast<int>(values.size()), 1,
                   [&](int x, int) { return glm::u8vec4(values[x], values[x], values[x], 255); });
}

// IEC 61966-2-1, written out here independently of the implementation's table.
double iecDecode(int value) {
  const double c = value / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

TEST(SrgbToLinear, MatchesIec61966Curve) {
  EXPECT_NEAR(srgbToLinear(188), 0.5029f, 5e-5f);
  EXPECT_EQ(srgbToLinear(0), 0.0f);
  EXPECT_FLOAT_EQ(srgbToLinear(255), 1.0f);
  for (int i = 0; i < 256; ++i) {
    EXPECT_NEAR(srgbToLinear(static_cast<std::uint8_t>(i)), iecDecode(i), 1e-6) << i;
    EXPECT_EQ(srgbDecodeTable()[i], srgbToLinear(static_cast<std::uint8_t>(i)));
    if (i > 0) {
      EXPECT_GT(srgbToLinear(static_cast<std::uint8_t>(i)), srgbToLinear(static_cast<std::uint8_t>(i - 1)));
    }
  }
}

std::vector<glm::ivec2> levelSizes(const MipChain& chain) {
  std::vector<glm::ivec2> sizes;
  for (const MipLevel& level : chain.levels) {
    sizes.emplace_back(level.width, level.height);
    EXPECT_EQ(level.rgba.size(), static_cast<std::size_t>(level.width) * level.height * 4);
  }
  return sizes;
}

TEST(BuildMipChain, LevelSizesFollowGlFloorRule) {
  const auto constant = [](int, int) { return glm::u8vec4(7); };
  using Sizes = std::vector<glm::ivec2>;
  EXPECT_EQ(levelSizes(buildMipChain(makeImage(8, 4, constant), ColorSpace::Linear)),
            (Sizes{{8, 4}, {4, 2}, {2, 1}, {1, 1}}));
  EXPECT_EQ(levelSizes(buildMipChain(makeImage(5, 3, constant), ColorSpace::Linear)),
            (Sizes{{5, 3}, {2, 1}, {1, 1}}));
  EXPECT_EQ(levelSizes(buildMipChain(makeImage(7, 1, constant), ColorSpace::Srgb)),
            (Sizes{{7, 1}, {3, 1}, {1, 1}}));
  EXPECT_EQ(levelSizes(buildMipChain(makeImage(1, 1, constant), ColorSpace::Linear)), (Sizes{{1, 1}}));
  // A constant image stays constant at every level.
  for (const MipLevel& level : buildMipChain(makeImage(5, 3, constant), ColorSpace::Srgb).levels)
    for (std::uint8_t byte : level.rgba) EXPECT_EQ(byte, 7);
  // No image, no levels.
  EXPECT_TRUE(buildMipChain(TextureImage{}, ColorSpace::Linear).levels.empty());
}

TEST(BuildMipChain, AveragesSrgbInLinearSpace) {
  // A black and white checker: its mean is linear 0.5, which is sRGB 188 (0.5029), not 128.
  const TextureImage checker = makeImage(2, 2, [](int x, int y) {
    const std::uint8_t v = (x + y) % 2 ? 255 : 0;
    return glm::u8vec4(v, v, v, v);
  });
  const MipChain srgb = buildMipChain(checker, ColorSpace::Srgb);
  ASSERT_EQ(srgb.levels.size(), 2u);
  EXPECT_EQ(srgb.levels[1].rgba, (std::vector<std::uint8_t>{188, 188, 188, 128}));  // alpha is linear
  const MipChain linear = buildMipChain(checker, ColorSpace::Linear);
  EXPECT_EQ(linear.levels[1].rgba, (std::vector<std::uint8_t>{128, 128, 128, 128}));
}

TEST(BuildMipChain, OddSizesAreBoxFilteredKeepingTheMean) {
  // 5 -> 2 texels: each covers 2.5 source texels, the middle one shared by halves.
  const MipChain chain = buildMipChain(greyRamp({0, 50, 100, 150, 200}), ColorSpace::Linear);
  ASSERT_EQ(chain.levels.size(), 3u);
  EXPECT_EQ(chain.levels[1].rgba[0], 40);   // (0 + 50 + 50) / 2.5
  EXPECT_EQ(chain.levels[1].rgba[4], 160);  // (50 + 150 + 200) / 2.5
  EXPECT_EQ(chain.levels[2].rgba[0], 100);
  // 3 -> 1: all three equally.
  EXPECT_EQ(buildMipChain(greyRamp({0, 90, 180}), ColorSpace::Linear).levels[1].rgba[0], 90);
}

TEST(WrapTexel, FollowsGlTable) {
  const int size = 4;
  std::vector<int> repeat, clamp, mirrored;
  for (int i = -5; i <= 8; ++i) {
    repeat.push_back(wrapTexel(i, size, TextureWrap::Repeat));
    clamp.push_back(wrapTexel(i, size, TextureWrap::ClampToEdge));
    mirrored.push_back(wrapTexel(i, size, TextureWrap::MirroredRepeat));
  }
  //                               -5 -4 -3 -2 -1  0  1  2  3  4  5  6  7  8
  EXPECT_EQ(repeat, (std::vector<int>{3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0}));
  EXPECT_EQ(clamp, (std::vector<int>{0, 0, 0, 0, 0, 0, 1, 2, 3, 3, 3, 3, 3, 3}));
  EXPECT_EQ(mirrored, (std::vector<int>{3, 3, 2, 1, 0, 0, 1, 2, 3, 3, 2, 1, 0, 0}));
}

TextureSampler samplerWith(TextureWrap wrap, TextureFilter filter) {
  TextureSampler sampler;
  sampler.wrapS = sampler.wrapT = wrap;
  sampler.magFilter = sampler.minFilter = filter;
  return sampler;
}

// Texels 0, 85, 170, 255 (linear 0, 1/3, 2/3, 1) along u.
float rampAt(TextureWrap wrap, TextureFilter filter, float u) {
  static const MipChain chain = buildMipChain(greyRamp({0, 85, 170, 255}), ColorSpace::Linear);
  return sampleMipChain(chain, samplerWith(wrap, filter), glm::vec2(u, 0.5f), -1.0f).r;
}

TEST(SampleMipChain, NearestWrapsAtTheEdges) {
  using enum TextureWrap;
  const float t0 = 0.0f, t1 = 85 / 255.0f, t2 = 170 / 255.0f, t3 = 1.0f;
  const TextureFilter nearest = TextureFilter::Nearest;
  EXPECT_FLOAT_EQ(rampAt(Repeat, nearest, -0.25f), t3);
  EXPECT_FLOAT_EQ(rampAt(ClampToEdge, nearest, -0.25f), t0);
  EXPECT_FLOAT_EQ(rampAt(MirroredRepeat, nearest, -0.25f), t0);
  for (TextureWrap wrap : {Repeat, ClampToEdge, MirroredRepeat})
    EXPECT_FLOAT_EQ(rampAt(wrap, nearest, 0.0f), t0);
  EXPECT_FLOAT_EQ(rampAt(Repeat, nearest, 1.0f), t0);
  EXPECT_FLOAT_EQ(rampAt(ClampToEdge, nearest, 1.0f), t3);
  EXPECT_FLOAT_EQ(rampAt(MirroredRepeat, nearest, 1.0f), t3);
  EXPECT_FLOAT_EQ(rampAt(Repeat, nearest, 1.25f), t1);
  EXPECT_FLOAT_EQ(rampAt(ClampToEdge, nearest, 1.25f), t3);
  EXPECT_FLOAT_EQ(rampAt(MirroredRepeat, nearest, 1.25f), t2);
  EXPECT_FLOAT_EQ(rampAt(MirroredRepeat, nearest, -1.1f), t3);  // texel -5 mirrors twice
}

TEST(SampleMipChain, LinearWrapsAtTheEdges) {
  using enum TextureWrap;
  const float t0 = 0.0f, t1 = 85 / 255.0f, t2 = 170 / 255.0f, t3 = 1.0f;
  const TextureFilter linear = TextureFilter::Linear;
  // u = 0 is the left edge of texel 0: halfway between texel -1 and texel 0.
  EXPECT_FLOAT_EQ(rampAt(Repeat, linear, 0.0f), 0.5f * (t3 + t0));
  EXPECT_FLOAT_EQ(rampAt(ClampToEdge, linear, 0.0f), t0);
  EXPECT_FLOAT_EQ(rampAt(MirroredRepeat, linear, 0.0f), t0);
  EXPECT_FLOAT_EQ(rampAt(Repeat, linear, 1.0f), 0.5f * (t3 + t0));
  EXPECT_FLOAT_EQ(rampAt(ClampToEdge, linear, 1.0f), t3);
  EXPECT_FLOAT_EQ(rampAt(MirroredRepeat, linear, 1.0f), t3);
  // u = -0.25 is the left edge of texel -1: between texels -2 and -1.
  EXPECT_FLOAT_EQ(rampAt(Repeat, linear, -0.25f), 0.5f * (t2 + t3));
  EXPECT_FLOAT_EQ(rampAt(ClampToEdge, linear, -0.25f), t0);
  EXPECT_FLOAT_EQ(rampAt(MirroredRepeat, linear, -0.25f), 0.5f * (t1 + t0));
  EXPECT_FLOAT_EQ(rampAt(Repeat, linear, 1.25f), 0.5f * (t0 + t1));
  EXPECT_FLOAT_EQ(rampAt(ClampToEdge, linear, 1.25f), t3);
  EXPECT_FLOAT_EQ(rampAt(MirroredRepeat, linear, 1.25f), 0.5f * (t3 + t2));
}

TEST(SampleMipChain, WrapModesArePerAxis) {
  const TextureImage image =
      makeImage(2, 2, [](int x, int y) { return glm::u8vec4(100 * x, 100 * y, 0, 255); });
  const MipChain chain = buildMipChain(image, ColorSpace::Linear);
  TextureSampler sampler = samplerWith(TextureWrap::ClampToEdge, TextureFilter::Nearest);
  sampler.wrapT = TextureWrap::Repeat;
  // (1.25, 1.25) is texel (2, 2) before wrapping: s clamps to 1, t repeats to 0.
  const glm::vec4 value = sampleMipChain(chain, sampler, glm::vec2(1.25f, 1.25f), 0.0f);
  EXPECT_FLOAT_EQ(value.r, 100 / 255.0f);
  EXPECT_FLOAT_EQ(value.g, 0.0f);
}

TEST(SampleMipChain, BilinearMatchesHandComputedValue) {
  // Red: 0 at (0, 0), 100 at (1, 0), 200 at (0, 1), 255 at (1, 1).
  const std::uint8_t red[2][2] = {{0, 100}, {200, 255}};
  const TextureImage image = makeImage(2, 2, [&](int x, int y) { return glm::u8vec4(red[y][x], 0, 0, 255); });
  const MipChain chain = buildMipChain(image, ColorSpace::Linear);
  const TextureSampler sampler = samplerWith(TextureWrap::ClampToEdge, TextureFilter::Linear);
  // uv (0.375, 0.625): texel space (0.75, 1.25), minus the half texel (0.25, 0.75).
  const float expected = (0.25f * (0.75f * 0 + 0.25f * 100) + 0.75f * (0.75f * 200 + 0.25f * 255)) / 255.0f;
  EXPECT_NEAR(sampleMipChain(chain, sampler, glm::vec2(0.375f, 0.625f), -1.0f).r, expected, 1e-6f);
  EXPECT_NEAR(sampleMipChain(chain, sampler, glm::vec2(0.5f, 0.5f), -1.0f).r,
              (0 + 100 + 200 + 255) / 4.0f / 255.0f, 1e-6f);
  // sRGB chains filter the decoded values.
  const MipChain srgb = buildMipChain(image, ColorSpace::Srgb);
  EXPECT_NEAR(sampleMipChain(srgb, sampler, glm::vec2(0.5f, 0.5f), -1.0f).r,
              (srgbToLinear(0) + srgbToLinear(100) + srgbToLinear(200) + srgbToLinear(255)) / 4.0f, 1e-6f);
}

// A chain whose levels are constant 0, 100 and 200 (not a box-filtered one), to see the levels.
MipChain levelsChain() {
  MipChain chain;
  for (int i = 0; i < 3; ++i) {
    MipLevel level;
    level.width = level.height = 4 >> i;
    level.rgba.assign(static_cast<std::size_t>(level.width) * level.height * 4,
                      static_cast<std::uint8_t>(100 * i));
    chain.levels.push_back(level);
  }
  return chain;
}

TEST(SampleMipChain, SelectsMipLevelsByLod) {
  const MipChain chain = levelsChain();
  TextureSampler trilinear;  // LINEAR_MIPMAP_LINEAR
  const auto at = [&](const TextureSampler& sampler, float lod) {
    return sampleMipChain(chain, sampler, glm::vec2(0.3f, 0.6f), lod).r * 255.0f;
  };
  EXPECT_NEAR(at(trilinear, -2.0f), 0.0f, 1e-4f);
  EXPECT_NEAR(at(trilinear, 0.5f), 50.0f, 1e-4f);
  EXPECT_NEAR(at(trilinear, 1.0f), 100.0f, 1e-4f);
  EXPECT_NEAR(at(trilinear, 1.25f), 125.0f, 1e-4f);
  EXPECT_NEAR(at(trilinear, 7.0f), 200.0f, 1e-4f);  // beyond the last level
  TextureSampler nearestMip;                        // LINEAR_MIPMAP_NEAREST
  nearestMip.mipFilter = TextureFilter::Nearest;
  EXPECT_NEAR(at(nearestMip, 0.4f), 0.0f, 1e-4f);
  EXPECT_NEAR(at(nearestMip, 0.6f), 100.0f, 1e-4f);
  EXPECT_NEAR(at(nearestMip, 1.5f), 100.0f, 1e-4f);
  EXPECT_NEAR(at(nearestMip, 1.6f), 200.0f, 1e-4f);
  TextureSampler noMips;
  noMips.mipmaps = false;
  EXPECT_NEAR(at(noMips, 2.0f), 0.0f, 1e-4f);
}

TEST(SampleMipChain, MagnificationAndMinificationUseTheirFilters) {
  const MipChain chain = buildMipChain(greyRamp({0, 255}), ColorSpace::Linear);
  TextureSampler sampler = samplerWith(TextureWrap::ClampToEdge, TextureFilter::Linear);
  sampler.minFilter = TextureFilter::Nearest;
  sampler.mipmaps = false;
  // At u = 0.5 LINEAR averages the two texels, NEAREST takes texel 1.
  EXPECT_FLOAT_EQ(sampleMipChain(chain, sampler, glm::vec2(0.5f, 0.5f), -1.0f).r, 0.5f);
  EXPECT_FLOAT_EQ(sampleMipChain(chain, sampler, glm::vec2(0.5f, 0.5f), 0.0f).r,
                  0.5f);  // lambda <= 0 magnifies
  EXPECT_FLOAT_EQ(sampleMipChain(chain, sampler, glm::vec2(0.5f, 0.5f), 1.0f).r, 1.0f);
}

TEST(TextureLod, IsLog2OfTheFootprintInTexels) {
  const auto constant = [](int, int) { return glm::u8vec4(0); };
  const MipChain square = buildMipChain(makeImage(256, 256, constant), ColorSpace::Linear);
  EXPECT_NEAR(textureLod(square, 1.0f / 256.0f), 0.0f, 1e-6f);
  EXPECT_NEAR(textureLod(square, 4.0f / 256.0f), 2.0f, 1e-6f);
  EXPECT_NEAR(textureLod(square, 1.0f / 1024.0f), -2.0f, 1e-6f);
  EXPECT_LT(textureLod(square, 0.0f), -100.0f);  // a zero footprint is the sharpest level
  const MipChain wide = buildMipChain(makeImage(64, 16, constant), ColorSpace::Linear);
  EXPECT_NEAR(textureLod(wide, 1.0f / 32.0f), 0.0f, 1e-6f);  // sqrt(64 * 16) = 32 texels per uv
}

TEST(TextureTransform, MatchesHandComputedUvs) {
  const glm::vec2 uv(0.25f, 0.75f);
  TextureTransform offset;
  offset.offset = glm::vec2(0.5f, -0.25f);
  EXPECT_NEAR(glm::distance(offset.apply(uv), glm::vec2(0.75f, 0.5f)), 0.0f, 1e-6f);
  TextureTransform scale;
  scale.scale = glm::vec2(2.0f, 3.0f);
  EXPECT_NEAR(glm::distance(scale.apply(uv), glm::vec2(0.5f, 2.25f)), 0.0f, 1e-6f);
  // Rotation pi/2: u' = cos u + sin v = v, v' = -sin u + cos v = -u.
  TextureTransform rotation;
  rotation.rotation = std::numbers::pi_v<float> / 2.0f;
  EXPECT_NEAR(glm::distance(rotation.apply(uv), glm::vec2(0.75f, -0.25f)), 0.0f, 1e-6f);
  // The extension README's example: offset [0, 1], rotation pi/2, scale 0.5 maps the unit square
  // onto the lower-left quadrant u in [0, 0.5], v in [0.5, 1] (v points down the image).
  TextureTransform readme;
  readme.offset = glm::vec2(0.0f, 1.0f);
  readme.rotation = std::numbers::pi_v<float> / 2.0f;
  readme.scale = glm::vec2(0.5f);
  EXPECT_NEAR(glm::distance(readme.apply(glm::vec2(0, 0)), glm::vec2(0.0f, 1.0f)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(readme.apply(glm::vec2(1, 0)), glm::vec2(0.0f, 0.5f)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(readme.apply(glm::vec2(0, 1)), glm::vec2(0.5f, 1.0f)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(readme.apply(glm::vec2(1, 1)), glm::vec2(0.5f, 0.5f)), 0.0f, 1e-6f);
}

// Quadrants of a 2 x 2 image: red 10 top-left, 20 top-right, 30 bottom-left, 40 bottom-right.
TextureImage quadrants() {
  return makeImage(2, 2, [](int x, int y) { return glm::u8vec4(10 + 10 * x + 20 * y, 0, 0, 255); });
}

TEST(SceneTextures, SamplesThroughTheSlotsTransform) {
  Material material;
  material.occlusionTexture.texture = 0;
  material.occlusionTexture.transform.offset = glm::vec2(0.0f, 1.0f);
  material.occlusionTexture.transform.rotation = std::numbers::pi_v<float> / 2.0f;
  material.occlusionTexture.transform.scale = glm::vec2(0.5f);
  Texture texture;
  texture.image = 0;
  texture.sampler = samplerWith(TextureWrap::ClampToEdge, TextureFilter::Nearest);
  const SceneTextures textures({texture}, {quadrants()}, {material});
  for (glm::vec2 uv :
       {glm::vec2(0.1f, 0.1f), glm::vec2(0.9f, 0.2f), glm::vec2(0.5f, 0.5f), glm::vec2(0.2f, 0.9f)})
    EXPECT_FLOAT_EQ(textures.sample(material.occlusionTexture, ColorSpace::Linear, uv, 0.0f).r, 30 / 255.0f)
        << uv.x << " " << uv.y;
}

TEST(SceneTextures, OneChainPerImageAndColourSpaceTheSlotsUse) {
  Material first, second;
  first.baseColorTexture.texture = 0;  // sRGB
  first.occlusionTexture.texture = 0;  // linear
  second.normalTexture.texture = 1;    // linear only, same image as texture 0
  second.emissiveTexture.texture = 7;  // out of range: ignored
  Texture texture;
  texture.image = 0;
  const SceneTextures textures({texture, texture}, {quadrants()}, {first, second});
  ASSERT_NE(textures.chain(0, ColorSpace::Srgb), nullptr);
  ASSERT_NE(textures.chain(0, ColorSpace::Linear), nullptr);
  EXPECT_EQ(textures.chain(0, ColorSpace::Srgb)->colorSpace, ColorSpace::Srgb);
  EXPECT_EQ(textures.chain(0, ColorSpace::Linear)->colorSpace, ColorSpace::Linear);
  EXPECT_EQ(textures.chain(1, ColorSpace::Srgb), nullptr);
  EXPECT_EQ(textures.chain(1, ColorSpace::Linear), textures.chain(0, ColorSpace::Linear));
  EXPECT_EQ(textures.chain(7, ColorSpace::Srgb), nullptr);
  EXPECT_EQ(textures.chain(-1, ColorSpace::Linear), nullptr);
  EXPECT_FALSE(textures.empty());
  EXPECT_TRUE(SceneTextures().empty());
}

TEST(SceneTextures, FootprintSelectsTheLevelAndScalesWithTheTransform) {
  Material material;
  material.occlusionTexture.texture = 0;
  Texture texture;
  texture.image = 0;
  texture.sampler.mipFilter = TextureFilter::Nearest;
  const SceneTextures textures({texture}, {quadrants()}, {material});
  const glm::vec2 uv(0.25f, 0.25f);  // the top-left texel's centre
  // Footprint 1/2 uv is one texel of the 2 x 2 level (lambda 0); 2 is four (lambda 2: the 1 x 1 mean).
  EXPECT_FLOAT_EQ(textures.sample(material.occlusionTexture, ColorSpace::Linear, uv, 0.5f).r, 10 / 255.0f);
  EXPECT_FLOAT_EQ(textures.sample(material.occlusionTexture, ColorSpace::Linear, uv, 2.0f).r, 25 / 255.0f);
  // Scale 4 (offset back onto the same texel) makes footprint 1/2 cover four texels' width.
  TextureRef scaled = material.occlusionTexture;
  scaled.transform.scale = glm::vec2(4.0f);
  scaled.transform.offset = glm::vec2(-0.75f);
  EXPECT_FLOAT_EQ(textures.sample(scaled, ColorSpace::Linear, uv, 0.5f).r, 25 / 255.0f);
}

// A channel mask reads the same values of its channels as the full lookup, at every lod (the
// trilinear REPEAT power-of-two fast path, magnification, the coarsest level), and on that path
// skips the others (0, their texels not loaded).
TEST(SceneTextures, ChannelMaskReadsItsChannelsAsTheFullLookup) {
  Material material;
  material.baseColorTexture.texture = 0;  // sRGB chain
  material.occlusionTexture.texture = 0;  // linear chain
  Texture texture;
  texture.image = 0;
  const TextureImage image = makeImage(16, 16, [](int x, int y) {
    return glm::u8vec4((x * 37 + y * 11) % 256, (x * 5 + y * 71) % 256, (x * 93 + y * 29) % 256,
                       (x * y * 13) % 256);
  });
  const SceneTextures textures({texture}, {image}, {material});
  for (ColorSpace space : {ColorSpace::Srgb, ColorSpace::Linear})
    for (unsigned mask :
         {SceneTextures::kRed, SceneTextures::kGreenBlue, SceneTextures::kRgb, SceneTextures::kAlpha})
      for (float footprint : {0.0f, 0.01f, 0.09f, 0.3f, 2.0f})
        for (glm::vec2 uv : {glm::vec2(0.13f, 0.71f), glm::vec2(-1.37f, 2.2f), glm::vec2(0.5f, 0.03f)}) {
          const float lf = SceneTextures::log2Footprint(footprint);
          glm::vec4 full(-1.0f), masked(-1.0f);
          ASSERT_TRUE(textures.trySample(material.baseColorTexture, space, uv, lf, full));
          ASSERT_TRUE(textures.trySample(material.baseColorTexture, space, uv, lf, masked, mask));
          for (int c = 0; c < 4; ++c) {
            if (mask & (1u << c))
              EXPECT_EQ(masked[c], full[c])
                  << "mask " << mask << " channel " << c << " footprint " << footprint;
            else
              EXPECT_EQ(masked[c], 0.0f) << "mask " << mask << " channel " << c << " footprint " << footprint;
          }
        }
}

// A size x size image of pseudo-random bytes (alpha included), for lookups that must agree bit
// for bit.
TextureImage noiseImage(int width, int height, unsigned seed) {
  std::mt19937 random(seed);
  return makeImage(width, height, [&](int, int) {
    return glm::u8vec4(random() & 255u, random() & 255u, random() & 255u, random() & 255u);
  });
}

// Decoded levels (decodeSmallLevels) hold the tables' decodings, and a lookup reads the same
// values from them as from the bytes, bit for bit, on every path: REPEAT power-of-two (the SSE
// blend), CLAMP and MIRRORED_REPEAT, a size that is not a power of two, NEAREST, magnification,
// trilinear, mip NEAREST and beyond the last level.
TEST(DecodeSmallLevels, LookupsReadTheSameValuesAsFromTheBytes) {
  std::mt19937 random(3);
  std::uniform_real_distribution<float> uv(-2.0f, 3.0f), lod(-1.0f, 7.0f);
  for (const glm::ivec2 size : {glm::ivec2(32, 32), glm::ivec2(64, 16), glm::ivec2(24, 10)})
    for (ColorSpace space : {ColorSpace::Srgb, ColorSpace::Linear}) {
      const MipChain bytes = buildMipChain(noiseImage(size.x, size.y, 11), space);
      MipChain decoded = bytes;
      decodeSmallLevels(decoded);
      for (const MipLevel& level : decoded.levels) {
        ASSERT_EQ(level.decoded.size(), level.rgba.size());
        for (std::size_t i = 0; i < level.rgba.size(); ++i)
          ASSERT_EQ(level.decoded[i], i % 4 == 3 || space == ColorSpace::Linear
                                          ? static_cast<float>(level.rgba[i] / 255.0)
                                          : srgbToLinear(level.rgba[i]));
      }
      for (TextureWrap wrap : {TextureWrap::Repeat, TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat})
        for (TextureFilter filter : {TextureFilter::Linear, TextureFilter::Nearest})
          for (TextureFilter mip : {TextureFilter::Linear, TextureFilter::Nearest}) {
            TextureSampler sampler = samplerWith(wrap, filter);
            sampler.mipFilter = mip;
            for (int i = 0; i < 200; ++i) {
              const glm::vec2 at(uv(random), uv(random));
              const float lambda = lod(random);
              const glm::vec4 a = sampleMipChain(bytes, sampler, at, lambda);
              const glm::vec4 b = sampleMipChain(decoded, sampler, at, lambda);
              for (int c = 0; c < 4; ++c)
                ASSERT_EQ(a[c], b[c]) << size.x << "x" << size.y << " uv " << at.x << " " << at.y << " lod "
                                      << lambda << " channel " << c;
            }
          }
    }
}

// Only levels of at most kDecodedLevelTexels texels are decoded; SceneTextures decodes its chains.
TEST(DecodeSmallLevels, DecodesOnlyTheSmallLevels) {
  MipChain chain =
      buildMipChain(makeImage(512, 256, [](int, int) { return glm::u8vec4(9); }), ColorSpace::Linear);
  decodeSmallLevels(chain);
  ASSERT_EQ(chain.levels.size(), 10u);
  EXPECT_TRUE(chain.levels[0].decoded.empty()) << "512 x 256 is 131072 texels";
  EXPECT_EQ(chain.decodedFrom, 1) << "the lookups' test for decoded texels";
  for (std::size_t i = 1; i < chain.levels.size(); ++i)
    EXPECT_EQ(chain.levels[i].decoded.size(), chain.levels[i].rgba.size());
  Material material;
  material.baseColorTexture.texture = 0;
  Texture texture;
  texture.image = 0;
  const SceneTextures textures({texture}, {quadrants()}, {material});
  EXPECT_EQ(textures.chain(0, ColorSpace::Srgb)->levels[0].decoded.size(), 16u);
  EXPECT_EQ(textures.chain(0, ColorSpace::Srgb)->decodedFrom, 0);
  EXPECT_GT(buildMipChain(quadrants(), ColorSpace::Linear).decodedFrom, 100) << "not decoded: none";
}

// The reason alphaAllOne means alpha 1: a lookup's weights 1 - f and f sum to exactly 1 in float,
// checked on every 7th float in [0, 1) (the exhaustive check takes seconds).
TEST(BuildMipChain, LinearWeightsSumToExactlyOne) {
  for (std::uint32_t bits = 0; bits < 0x3f800000u; bits += 7) {
    const float f = std::bit_cast<float>(bits);
    ASSERT_EQ((1.0f - f) * 1.0f + 1.0f * f, 1.0f) << f;
  }
}

// alphaAllOne holds exactly when every texel's alpha is 255, and then every lookup's alpha is
// exactly 1, whatever the weights.
TEST(BuildMipChain, AlphaAllOneWhenEveryAlphaIs255) {
  const TextureImage opaque =
      makeImage(16, 8, [](int x, int y) { return glm::u8vec4(x * 16, y * 30, 7, 255); });
  TextureImage nearly = opaque;
  nearly.rgba[4 * 37 + 3] = 254;
  EXPECT_FALSE(buildMipChain(nearly, ColorSpace::Srgb).alphaAllOne);
  const MipChain chain = buildMipChain(opaque, ColorSpace::Srgb);
  ASSERT_TRUE(chain.alphaAllOne);
  std::mt19937 random(5);
  std::uniform_real_distribution<float> uv(-2.0f, 3.0f), lod(-1.0f, 6.0f);
  for (TextureWrap wrap : {TextureWrap::Repeat, TextureWrap::MirroredRepeat})
    for (int i = 0; i < 2000; ++i)
      ASSERT_EQ(sampleMipChain(chain, samplerWith(wrap, TextureFilter::Linear),
                               glm::vec2(uv(random), uv(random)), lod(random))
                    .a,
                1.0f);
}

// sampleSlots reads each slot's trySample value, bit for bit, whether its lookup shares the plan
// of an earlier one (same size, sampler, uv set and transform) or not (another size, sampler, uv
// set or transform), and reports a slot without a chain as not found.
TEST(SceneTextures, SampleSlotsReadsWhatTrySampleReads) {
  Material material;
  std::vector<Texture> textures(5);
  for (int t = 0; t < 5; ++t) textures[t].image = t;
  textures[3].sampler.wrapS = TextureWrap::MirroredRepeat;
  // Images 0, 1 and 3 are 32 x 32, image 2 is 16 x 16, image 4 is 32 x 32.
  const std::vector<TextureImage> images = {noiseImage(32, 32, 1), noiseImage(32, 32, 2),
                                            noiseImage(16, 16, 3), noiseImage(32, 32, 4),
                                            noiseImage(32, 32, 5)};
  material.baseColorTexture.texture = 0;
  material.metallicRoughnessTexture.texture = 1;  // shares 0's plan
  material.normalTexture.texture = 2;             // another size
  material.occlusionTexture.texture = 3;          // another sampler
  material.emissiveTexture.texture = 4;
  material.emissiveTexture.transform.scale = glm::vec2(2.0f, 3.0f);  // another transform
  const SceneTextures scene(textures, images, {material});
  TextureRef onSet1 = material.metallicRoughnessTexture;
  onSet1.texCoord = 1;
  TextureRef missing = material.baseColorTexture;
  missing.texture = 9;
  const TextureRef* refs[] = {&material.baseColorTexture,
                              &material.metallicRoughnessTexture,
                              &material.normalTexture,
                              &material.occlusionTexture,
                              &material.emissiveTexture,
                              &onSet1,
                              &missing,
                              &material.baseColorTexture};  // the last shares the first's plan
  const ColorSpace spaces[] = {ColorSpace::Srgb, ColorSpace::Linear, ColorSpace::Linear, ColorSpace::Linear,
                               ColorSpace::Srgb, ColorSpace::Linear, ColorSpace::Srgb,   ColorSpace::Srgb};
  const unsigned masks[] = {SceneTextures::kRgba, SceneTextures::kGreenBlue, SceneTextures::kRgb,
                            SceneTextures::kRed,  SceneTextures::kRgb,       SceneTextures::kRgba,
                            SceneTextures::kRgba, SceneTextures::kAlpha};
  constexpr int n = 8;
  std::mt19937 random(9);
  std::uniform_real_distribution<float> uv(-2.0f, 3.0f), footprint(0.0f, 0.3f);
  for (int i = 0; i < 300; ++i) {
    const glm::vec2 texcoords[2] = {{uv(random), uv(random)}, {uv(random), uv(random)}};
    const float footprints[2] = {i % 7 == 0 ? 0.0f : footprint(random), footprint(random)};
    SceneTextures::SlotLookup lookups[n];
    for (int l = 0; l < n; ++l) {
      lookups[l].ref = refs[l];
      lookups[l].colorSpace = spaces[l];
      lookups[l].channels = masks[l];
    }
    scene.sampleSlots(lookups, n, texcoords, footprints);
    for (int l = 0; l < n; ++l) {
      const int set = refs[l]->texCoord;
      glm::vec4 expected(1.0f);
      const bool found = scene.trySample(*refs[l], spaces[l], texcoords[set],
                                         SceneTextures::log2Footprint(footprints[set]), expected, masks[l]);
      ASSERT_EQ(lookups[l].found, found) << "lookup " << l;
      for (int c = 0; c < 4; ++c)
        ASSERT_EQ(lookups[l].value[c], expected[c]) << "lookup " << l << " channel " << c;
    }
    EXPECT_FALSE(lookups[6].found);
  }
}

}  // namespace
}  // namespace iblkit
