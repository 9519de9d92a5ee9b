#include "core/low_discrepancy.h"

#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <vector>

#include "core/rng.h"
#include "support/chi2.h"
#include "support/digital_nets.h"

namespace iblkit {
namespace {

constexpr int kChi2Tests = 2;  // chi-square runs in this file, for the Sidak correction

// The 2^m points first, first + 1, ... of a 2D sequence, as isNet takes them.
std::vector<std::vector<float>> points(std::uint32_t first, int m,
                                       const std::function<glm::vec2(std::uint32_t)>& point) {
  std::vector<std::vector<float>> result;
  for (std::uint32_t i = 0; i < (1u << m); ++i) {
    const glm::vec2 p = point(first + i);
    result.push_back({p.x, p.y});
  }
  return result;
}

// The net check itself fails on points that are not a net.
TEST(NetCheck, RejectsPointsThatAreNotANet) {
  std::vector<std::vector<float>> net = points(0, 6, [](std::uint32_t i) { return sobol02(i); });
  EXPECT_TRUE(test::isNet(net, 6, 0));
  net[5] = net[6];  // two points in every box that holds the 7th
  EXPECT_FALSE(test::isNet(net, 6, 0));
  PCG32 rng(5);
  const std::vector<std::vector<float>> random = points(0, 6, [&](std::uint32_t) { return rng.uniform2D(); });
  EXPECT_FALSE(test::isNet(random, 6, 2));
  EXPECT_TRUE(test::isNet(random, 6, 6));  // t = m: a single box, all the points
}

TEST(RadicalInverse, MirrorsTheBits) {
  EXPECT_EQ(radicalInverseBase2(0), 0.0f);
  EXPECT_EQ(radicalInverseBase2(1), 0.5f);
  EXPECT_EQ(radicalInverseBase2(2), 0.25f);
  EXPECT_EQ(radicalInverseBase2(3), 0.75f);
  EXPECT_EQ(radicalInverseBase2(4), 0.125f);
  EXPECT_EQ(radicalInverseBase2(6), 0.375f);
  EXPECT_LT(radicalInverseBase2(0xffffffffu), 1.0f);
}

TEST(Sobol02, FirstPoints) {
  // Second dimension: direction numbers 1/2, 3/4, 5/8, 15/16 (Pascal's triangle mod 2).
  const glm::vec2 expected[] = {{0.0f, 0.0f},     {0.5f, 0.5f},     {0.25f, 0.75f},
                                {0.75f, 0.25f},   {0.125f, 0.625f}, {0.625f, 0.125f},
                                {0.375f, 0.375f}, {0.875f, 0.875f}, {0.0625f, 0.9375f}};
  for (std::uint32_t i = 0; i < std::size(expected); ++i) EXPECT_EQ(sobol02(i), expected[i]) << "index " << i;
}

// The second dimension of full 32-bit indices (the reference tracer's shuffled indices) is the
// xor of the direction numbers v_1 = 0.1b, v_(k+1) = v_k xor (v_k >> 1) its bits select, taken
// here bit by bit.
TEST(Sobol02, SecondDimensionOfLargeIndicesFollowsTheRecurrence) {
  PCG32 rng(3, 5);
  for (int i = 0; i < 10000; ++i) {
    const std::uint32_t index = i < 32 ? (1u << i) | 1u : rng.nextUInt32();
    std::uint32_t bits = 0, v = 0x80000000u;
    for (std::uint32_t rest = index; rest != 0; rest >>= 1, v ^= v >> 1)
      if (rest & 1u) bits ^= v;
    ASSERT_EQ(sobol02(index).y, unitFloatFromBits(bits)) << "index " << index;
  }
}

TEST(Sobol02, EveryAlignedBlockIsANet) {
  for (int m = 1; m <= 10; ++m) {
    for (std::uint32_t block = 0; block < 3; ++block) {
      EXPECT_TRUE(test::isNet(points(block << m, m, [](std::uint32_t i) { return sobol02(i); }), m, 0))
          << "m = " << m << ", block " << block;
    }
  }
}

// The fast form (reversals cancelled, reversed table) is the defining one: the first coordinate is
// the scrambled radical inverse, the second owenScramble of the Sobol bits with the second
// dimension seed; and the seed-hashing overload gives the same points.
TEST(Sobol02, ScrambledPointsFollowTheirDefinition) {
  PCG32 rng(11, 2);
  for (int i = 0; i < 10000; ++i) {
    const std::uint32_t index = rng.nextUInt32() >> (i % 32), seed = rng.nextUInt32();
    const Sobol02Scramble scramble = sobol02Scramble(seed);
    const glm::vec2 p = owenScrambledSobol02(index, scramble);
    ASSERT_EQ(p, owenScrambledSobol02(index, seed));
    ASSERT_EQ(p.x, owenScrambledRadicalInverseBase2(index, seed)) << index;
    std::uint32_t bits = 0, v = 0x80000000u;
    for (std::uint32_t rest = index; rest != 0; rest >>= 1, v ^= v >> 1)
      if (rest & 1u) bits ^= v;
    ASSERT_EQ(p.y, unitFloatFromBits(owenScramble(bits, scramble.dimensionSeeds[1]))) << index;
  }
}

TEST(Sobol02, OwenScramblingKeepsTheNetsAndIsSeeded) {
  for (const std::uint32_t seed : {0u, 1u, 0xdeadbeefu}) {
    for (int m = 1; m <= 10; ++m) {
      EXPECT_TRUE(test::isNet(
          points(std::uint32_t{5} << m, m, [=](std::uint32_t i) { return owenScrambledSobol02(i, seed); }), m,
          0))
          << "seed " << seed << ", m = " << m;
    }
  }
  // Reproducible for a seed, different across seeds, and not the unscrambled points.
  EXPECT_EQ(owenScrambledSobol02(17, 4), owenScrambledSobol02(17, 4));
  EXPECT_NE(owenScrambledSobol02(17, 4), owenScrambledSobol02(17, 5));
  EXPECT_NE(owenScrambledSobol02(17, 4), sobol02(17));
}

TEST(Sobol02, AScrambledPointIsUniformOverSeeds) {
  // Owen scrambling makes every point of the set uniformly distributed over [0,1)^2, with
  // independent coordinates: check one point over consecutive seeds (as per-pixel seeds are) and
  // another over random seeds.
  test::Chi2Options options;
  options.testCount = kChi2Tests;
  options.name = "owen_sobol_index0_consecutive_seeds";
  std::uint32_t seed = 0;
  const test::Chi2Result consecutive =
      test::chi2TestSquare([&](PCG32&) { return std::optional(owenScrambledSobol02(0, seed++)); },
                           [](const glm::vec2&) { return 1.0; }, options);
  EXPECT_TRUE(consecutive.passed) << consecutive.message;
  options.name = "owen_sobol_index37_random_seeds";
  const test::Chi2Result random = test::chi2TestSquare(
      [](PCG32& rng) { return std::optional(owenScrambledSobol02(37, rng.nextUInt32())); },
      [](const glm::vec2&) { return 1.0; }, options);
  EXPECT_TRUE(random.passed) << random.message;
  EXPECT_EQ(owenScrambledRadicalInverseBase2(37, 5), owenScrambledSobol02(37, 5).x);
}

TEST(OwenScramble, FlipsEachBitByTheBitsAboveItOnly) {
  // Fractions that share their top k bits still share them after scrambling (the nested
  // property that keeps elementary intervals together).
  PCG32 rng(11u);
  for (int i = 0; i < 10000; ++i) {
    const std::uint32_t a = rng.nextUInt32(), seed = rng.nextUInt32();
    const int k = static_cast<int>(rng.nextUInt32() % 32u);
    const std::uint32_t topMask = k == 0 ? 0u : ~0u << (32 - k);
    const std::uint32_t b = (a & topMask) | (rng.nextUInt32() & ~topMask);
    ASSERT_EQ(owenScramble(a, seed) & topMask, owenScramble(b, seed) & topMask) << "k = " << k;
  }
}

// Random valid columns: bit j set, random bits below it.
std::vector<std::uint32_t> randomTriangularColumns(PCG32& rng, int count) {
  std::vector<std::uint32_t> columns;
  for (int j = 0; j < count; ++j) columns.push_back((1u << j) | (rng.nextUInt32() & ((1u << j) - 1u)));
  return columns;
}

TEST(LinearIndexPermutation, IsTheXorOfTheColumnsOfTheIndexBits) {
  PCG32 rng(21, 4);
  for (int count : {0, 5, 16, 32}) {
    const std::vector<std::uint32_t> columns = randomTriangularColumns(rng, count);
    const LinearIndexPermutation permutation(columns);
    for (int i = 0; i < 2000; ++i) {
      const std::uint32_t index = rng.nextUInt32() >> (i % 32);
      std::uint32_t expected = 0;
      for (int bit = 0; bit < 32; ++bit)
        if ((index >> bit) & 1u) expected ^= bit < count ? columns[static_cast<std::size_t>(bit)] : 1u << bit;
      ASSERT_EQ(permutation(index), expected) << "index " << index << ", " << count << " columns";
    }
  }
}

TEST(LinearIndexPermutation, MapsEachAlignedBlockOntoAnAlignedBlock) {
  PCG32 rng(8, 1);
  const LinearIndexPermutation permutation(randomTriangularColumns(rng, 32));
  for (int m = 0; m <= 12; ++m)
    for (const std::uint32_t block : {0u, 1u, 7u, 0xfffffu >> m}) {
      std::vector<bool> seen(std::size_t{1} << m, false);
      const std::uint32_t imageBlock = block == 0 ? 0u : permutation(block << m) >> m;  // the first: itself
      for (std::uint32_t i = 0; i < (1u << m); ++i) {
        const std::uint32_t image = permutation((block << m) | i);
        ASSERT_EQ(image >> m, imageBlock) << "m = " << m;
        ASSERT_FALSE(seen[image & ((1u << m) - 1u)]) << "m = " << m;
        seen[image & ((1u << m) - 1u)] = true;
      }
    }
}

TEST(LinearIndexPermutation, RefusesColumnsThatAreNotTriangular) {
  // Column 1 without bit 1; column 0 with bit 1; more columns than index bits.
  EXPECT_THROW(LinearIndexPermutation(std::vector<std::uint32_t>{1u, 1u}), std::invalid_argument);
  EXPECT_THROW(LinearIndexPermutation(std::vector<std::uint32_t>{3u}), std::invalid_argument);
  EXPECT_THROW(LinearIndexPermutation(std::vector<std::uint32_t>(33, 1u)), std::invalid_argument);
  EXPECT_NO_THROW(LinearIndexPermutation(std::vector<std::uint32_t>{1u, 3u, 6u}));
}

TEST(Hammersley, IsANetForPowersOfTwo) {
  for (int m = 1; m <= 10; ++m) {
    const std::uint32_t count = 1u << m;
    EXPECT_TRUE(test::isNet(points(0, m, [=](std::uint32_t i) { return hammersley(i, count); }), m, 0)) << m;
  }
  EXPECT_EQ(hammersley(3, 8), glm::vec2(0.375f, 0.75f));
  EXPECT_LT(hammersley((1u << 25) - 1u, 1u << 25).x, 1.0f);
}

}  // namespace
}  // namespace iblkit
