#include "reference/pixel_sampler.h"

#include <gtest/gtest.h>

#include <set>

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

// The Sobol draws of one pixel's first 2^m samples form a (0,m,2)-net: with 16 samples, each of
// the 4 x 4 cells holds exactly one pixel position (what makes the jitter stratified).
TEST(PixelSampler, FirstDrawsOfAPixelAreStratified) {
  for (int pair = 0; pair < PixelSampler::kSobolPairs; ++pair) {
    std::set<int> cells;
    for (std::uint32_t sample = 0; sample < 16; ++sample) {
      PixelSampler sampler(3, 40, sample);
      glm::vec2 u{};
      for (int i = 0; i <= pair; ++i) u = sampler.next2D();
      cells.insert(static_cast<int>(u.x * 4.0f) + 4 * static_cast<int>(u.y * 4.0f));
    }
    EXPECT_EQ(cells.size(), 16u) << "pair " << pair;
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
