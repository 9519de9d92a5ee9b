#include "reference/pixel_sampler.h"

#include <gtest/gtest.h>

#include <array>
#include <initializer_list>
#include <optional>
#include <set>
#include <vector>

#include "support/chi2.h"
#include "support/digital_nets.h"

namespace iblkit {
namespace {

std::vector<float> draws(std::uint32_t seed, std::uint32_t pixel, std::uint32_t sample) {
  PixelSampler sampler(seed, pixel, sample);
  std::vector<float> values;
  for (int i = 0; i < 6; ++i) {
    const glm::vec2 u = sampler.next2D();
    values.push_back(u.x);
    values.push_back(u.y);
    values.push_back(sampler.next1D());
  }
  return values;
}

TEST(PixelSampler, SameKeysGiveTheSameNumbers) { EXPECT_EQ(draws(7, 12, 3), draws(7, 12, 3)); }

TEST(PixelSampler, SeedPixelAndSampleEachChangeEveryDraw) {
  const std::vector<float> base = draws(7, 12, 3);
  for (const auto& other : {draws(8, 12, 3), draws(7, 13, 3), draws(7, 12, 4)})
    for (std::size_t i = 0; i < base.size(); ++i) EXPECT_NE(base[i], other[i]) << "draw " << i;
}

TEST(PixelSampler, ValuesLieInTheUnitInterval) {
  for (std::uint32_t sample = 0; sample < 256; ++sample)
    for (float value : draws(1, 5, sample)) {
      EXPECT_GE(value, 0.0f);
      EXPECT_LT(value, 1.0f);
    }
}

// The Sobol draws of one sample: pixel position, light, BRDF, then the padded ones (the second and
// third vertices' light and BRDF).
constexpr int kSobolDraws = PixelSampler::kSobolPairs + PixelSampler::kPaddedPairs;
std::array<glm::vec2, kSobolDraws> sobolDraws(std::uint32_t pixel, std::uint32_t sample) {
  PixelSampler sampler(3, pixel, sample);
  std::array<glm::vec2, kSobolDraws> result;
  for (glm::vec2& u : result) u = sampler.next2D();
  return result;
}

// The 2^m samples block 2^m .. (block + 1) 2^m - 1 of a pixel, each as the coordinates of the
// given draws (0: pixel position, 1: light, 2: BRDF) one after the other.
std::vector<std::vector<float>> blockOfDraws(std::uint32_t pixel, int m, std::uint32_t block,
                                             std::initializer_list<int> draws) {
  std::vector<std::vector<float>> points;
  for (std::uint32_t i = 0; i < (1u << m); ++i) {
    const auto u = sobolDraws(pixel, (block << m) | i);
    std::vector<float>& p = points.emplace_back();
    for (int draw : draws) {
      p.push_back(u[static_cast<std::size_t>(draw)].x);
      p.push_back(u[static_cast<std::size_t>(draw)].y);
    }
  }
  return points;
}

// Each Sobol draw of a pixel's aligned blocks of 2^m samples is a (0,m,2)-net: with 16 samples, each
// of the 4 x 4 cells (and 2 x 8, ...) holds exactly one pixel position, light or BRDF point. The
// padded draws too: their shuffle maps an aligned block of indices onto an aligned block.
TEST(PixelSampler, EachDrawOfEveryAlignedBlockIsStratified) {
  for (int draw = 0; draw < kSobolDraws; ++draw)
    for (int m = 1; m <= 10; ++m)
      for (std::uint32_t block : {0u, 1u, 5u})
        EXPECT_TRUE(test::isNet(blockOfDraws(40, m, block, {draw}), m, 0))
            << "draw " << draw << ", m = " << m << ", block " << block;
}

// The pixel position with the light draw, and with the BRDF draw, is a 4D (t,m,4)-net for the t of
// the permutations in pixel_sampler.cpp: the samples in a part of the pixel (one side of a
// silhouette) still cover the light and BRDF squares evenly. With independently shuffled draws
// (Burley's padding) the pairs are matched at random and these fail from m = 3 on. The light and
// BRDF draws together are a 4D net too (they are not one sequence used twice).
TEST(PixelSampler, PixelPositionAndFirstBounceDrawsFormFourDimensionalNets) {
  struct Projection {
    const char* name;
    std::initializer_list<int> draws;
    int t[12];  // for m = 1..12
  };
  const Projection projections[] = {
      {"pixel, light", {0, 1}, {0, 1, 1, 1, 2, 1, 2, 2, 2, 3, 3, 3}},
      {"pixel, BRDF", {0, 2}, {0, 1, 1, 1, 2, 2, 2, 3, 3, 2, 3, 3}},
      {"light, BRDF", {1, 2}, {0, 1, 2, 3, 2, 1, 2, 2, 3, 4, 5, 4}},
  };
  for (const Projection& projection : projections)
    for (int m = 1; m <= 12; ++m)
      for (std::uint32_t block : {0u, 3u}) {
        const int t = projection.t[m - 1];
        EXPECT_TRUE(test::isNet(blockOfDraws(7, m, block, projection.draws), m, t))
            << projection.name << ", m = " << m << ", block " << block;
      }
}

// Every Sobol coordinate of a given sample index is uniform over pixels, and coordinates of
// different draws are independent: each dimension has its own Owen scramble per pixel.
TEST(PixelSampler, DrawsOfOneSampleAreUniformAndIndependentOverPixels) {
  struct Pairing {
    const char* name;
    int xDraw, yDraw;  // x from one draw, y from another
    std::uint32_t sample;
  };
  const Pairing pairings[] = {{"pixel_x_light_y_sample_37", 0, 1, 37},
                              {"light_x_brdf_y_sample_0", 1, 2, 0},
                              {"brdf_x_second_light_y_sample_5", 2, 3, 5},
                              {"second_light_x_third_brdf_y_sample_0", 3, 6, 0}};
  for (const Pairing& pairing : pairings) {
    test::Chi2Options options;
    options.testCount = static_cast<int>(std::size(pairings));
    options.name = pairing.name;
    const test::Chi2Result result = test::chi2TestSquare(
        [&](PCG32& rng) {
          const auto u = sobolDraws(rng.nextUInt32(), pairing.sample);
          return std::optional(glm::vec2(u[static_cast<std::size_t>(pairing.xDraw)].x,
                                         u[static_cast<std::size_t>(pairing.yDraw)].y));
        },
        [](const glm::vec2&) { return 1.0; }, options);
    EXPECT_TRUE(result.passed) << result.message;
  }
}

// The padded draws are shuffled independently of each other: over one pixel's 256 samples, the
// first coordinates of two draws fill the 16 x 16 grid of their cells at random (about 162 cells
// in expectation). Two draws at one index, scrambled apart, would be a bijection of nested strips:
// exactly 16 cells, 16 points each (Burley 2020, section 4).
TEST(PixelSampler, PaddedDrawsAreShuffledIndependently) {
  for (const auto& [first, second] : {std::pair{3, 4}, std::pair{3, 5}, std::pair{4, 6}, std::pair{2, 3}}) {
    std::set<int> cells;
    for (std::uint32_t sample = 0; sample < 256; ++sample) {
      const auto u = sobolDraws(40, sample);
      cells.insert(int(u[std::size_t(first)].x * 16.0f) * 16 + int(u[std::size_t(second)].x * 16.0f));
    }
    EXPECT_GT(cells.size(), 120u) << "draws " << first << " and " << second;
  }
}

// Splitting: the K light draws of one sample are a (0,log2 K,2)-net, the K 2^m draws of an aligned
// block of 2^m samples one too, and K = 1 is the light draw itself (the plain estimator unchanged).
TEST(PixelSampler, SplitLightDrawsAreStratifiedWithinASampleAndAcrossSamples) {
  for (std::uint32_t sample : {0u, 5u, 1000u}) {
    PixelSampler sampler(3, 40, sample);
    sampler.next2D();
    EXPECT_EQ(sampler.splitLight2D(0, 1), sampler.next2D()) << "sample " << sample;
  }
  for (int k : {2, 4, 16})
    for (int m : {0, 3, 6})
      for (std::uint32_t block : {0u, 3u}) {
        std::vector<std::vector<float>> points;
        for (std::uint32_t i = 0; i < (1u << m); ++i) {
          const PixelSampler sampler(3, 40, (block << m) | i);
          for (int j = 0; j < k; ++j) {
            const glm::vec2 u = sampler.splitLight2D(j, k);
            points.push_back({u.x, u.y});
          }
        }
        const int bits = m + (k == 2 ? 1 : k == 4 ? 2 : 4);
        EXPECT_TRUE(test::isNet(points, bits, 0)) << "K = " << k << ", m = " << m << ", block " << block;
      }
}

TEST(HashCombine, IsOrderSensitiveAndSpreadsConsecutiveKeys) {
  EXPECT_NE(hashCombine(1, 2), hashCombine(2, 1));
  std::set<std::uint32_t> high;
  for (std::uint32_t b = 0; b < 64; ++b) high.insert(hashCombine(0, b) >> 26);
  EXPECT_GT(high.size(), 30u);  // 64 keys over 64 buckets of the top 6 bits: ~40 expected
}

}  // namespace
}  // namespace iblkit
