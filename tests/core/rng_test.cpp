#include "core/rng.h"

#include <gtest/gtest.h>

#include "support/chi2.h"

namespace iblkit {
namespace {

TEST(PCG32, MatchesOneillsReferenceOutputsForSeed42Stream54) {
  // pcg32-demo (pcg-c-basic) output for pcg32_srandom_r(&rng, 42u, 54u).
  PCG32 rng(42u, 54u);
  const std::uint32_t expected[] = {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u,
                                    0x83d2f293u, 0xbfa4784bu, 0xcbed606eu};
  for (const std::uint32_t value : expected) EXPECT_EQ(rng.nextUInt32(), value);
}

TEST(PCG32, SeedAndStreamReproduceAndStreamsDiffer) {
  PCG32 a(7u, 1u), b(7u, 1u), otherStream(7u, 2u), otherSeed(8u, 1u);
  int sameStream = 0, sameSeed = 0;
  for (int i = 0; i < 1000; ++i) {
    const std::uint32_t x = a.nextUInt32();
    ASSERT_EQ(x, b.nextUInt32());
    sameStream += x == otherStream.nextUInt32();
    sameSeed += x == otherSeed.nextUInt32();
  }
  EXPECT_EQ(sameStream, 0);
  EXPECT_EQ(sameSeed, 0);
  // setSequence restarts the sequence.
  PCG32 c(9u, 9u);
  c.setSequence(42u, 54u);
  EXPECT_EQ(c.nextUInt32(), 0xa15c02b7u);
}

TEST(PCG32, UniformFloatIsBelowOne) {
  EXPECT_EQ(unitFloatFromBits(0u), 0.0f);
  EXPECT_LT(unitFloatFromBits(0xffffffffu), 1.0f);
  EXPECT_EQ(unitFloatFromBits(0xffffffffu), 0x1.fffffep-1f);
  EXPECT_EQ(unitFloatFromBits(0x80000000u), 0.5f);
  PCG32 rng(1u);
  for (int i = 0; i < 100000; ++i) {
    const float u = rng.uniformFloat();
    ASSERT_TRUE(u >= 0.0f && u < 1.0f) << u;
  }
}

TEST(PCG32, PairsAreUniformOnTheSquare) {
  test::Chi2Options options;
  options.name = "pcg32_pairs";
  const test::Chi2Result r = test::chi2TestSquare([](PCG32& rng) { return std::optional(rng.uniform2D()); },
                                                  [](const glm::vec2&) { return 1.0; }, options);
  EXPECT_TRUE(r.passed) << r.message;
}

}  // namespace
}  // namespace iblkit
