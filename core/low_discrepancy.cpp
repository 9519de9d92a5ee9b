#include "core/low_discrepancy.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/rng.h"

namespace iblkit {

namespace {

std::uint32_t reverseBits(std::uint32_t v) {
  v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
  v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
  v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
  v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
  return (v >> 16) | (v << 16);
}

// A seeded bijection in which bit k of the result is bit k of x flipped by a function of bits
// 0..k-1 only: adding the seed, multiplying by an odd number, and xor-ing x with x times an even
// number all carry information upwards only. On bit-reversed fractions that is exactly a nested
// uniform scramble. Constants from Vegdahl 2021.
std::uint32_t laineKarrasPermutation(std::uint32_t x, std::uint32_t seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

// The scrambling seed of one dimension: MurmurHash3's 64-bit finaliser (Appleby) of (seed,
// dimension) together, so that consecutive seeds and the two dimensions get unrelated scrambles
// (the permutation above passes low seed bits to the output's top digits almost unmixed).
std::uint32_t dimensionSeed(std::uint32_t seed, std::uint32_t dimension) {
  std::uint64_t h = (static_cast<std::uint64_t>(seed) << 32) | dimension;
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdull;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ull;
  h ^= h >> 33;
  return static_cast<std::uint32_t>(h >> 32);
}

// A linear map of 32-bit values over GF(2), given by the images of the 32 bits, tabulated a byte at
// a time: the image of x is the xor of byByte[k][byte k of x] over the four bytes.
void tabulateByBytes(const std::uint32_t (&images)[32], std::uint32_t (&byByte)[4][256]) {
  for (int byte = 0; byte < 4; ++byte)
    for (std::uint32_t value = 0; value < 256; ++value) {
      std::uint32_t result = 0;
      for (int bit = 0; bit < 8; ++bit)
        if (value & (1u << bit)) result ^= images[8 * byte + bit];
      byByte[byte][value] = result;
    }
}

// Sobol's second dimension as a 32-bit binary fraction: the xor of the direction numbers selected
// by the bits of index, with v_1 = 0.1b and v_(k+1) = v_k xor (v_k >> 1) (Pascal's triangle mod 2).
// The xor is linear, so it is taken a byte of the index at a time from four 256-entry tables (the
// reference tracer draws scrambled, hence full 32-bit, indices for every camera sample: a loop
// over 32 bits cost more than the rest of the point). A second set of tables holds the same
// fractions bit-reversed (xor commutes with reversal), which is what the Owen scramble takes.
struct SobolSecondDimensionTables {
  std::uint32_t byByte[4][256];
  std::uint32_t reversedByByte[4][256];
  SobolSecondDimensionTables() {
    std::uint32_t directions[32];
    std::uint32_t v = 0x80000000u;
    for (int bit = 0; bit < 32; ++bit, v ^= v >> 1) directions[bit] = v;
    tabulateByBytes(directions, byByte);
    for (int byte = 0; byte < 4; ++byte)
      for (int value = 0; value < 256; ++value)
        reversedByByte[byte][value] = reverseBits(byByte[byte][value]);
  }
  static std::uint32_t lookup(const std::uint32_t (&table)[4][256], std::uint32_t index) {
    return table[0][index & 0xffu] ^ table[1][(index >> 8) & 0xffu] ^ table[2][(index >> 16) & 0xffu] ^
           table[3][index >> 24];
  }
};

const SobolSecondDimensionTables& sobolTables() {
  static const SobolSecondDimensionTables tables;
  return tables;
}

std::uint32_t sobolSecondDimensionBits(std::uint32_t index) {
  return SobolSecondDimensionTables::lookup(sobolTables().byByte, index);
}

}  // namespace

float radicalInverseBase2(std::uint32_t index) { return unitFloatFromBits(reverseBits(index)); }

std::uint32_t owenScramble(std::uint32_t fractionBits, std::uint32_t seed) {
  return reverseBits(laineKarrasPermutation(reverseBits(fractionBits), seed));
}

float owenScrambledRadicalInverseBase2(std::uint32_t index, std::uint32_t seed) {
  return unitFloatFromBits(owenScramble(reverseBits(index), dimensionSeed(seed, 0)));
}

glm::vec2 sobol02(std::uint32_t index) {
  return {radicalInverseBase2(index), unitFloatFromBits(sobolSecondDimensionBits(index))};
}

glm::vec2 owenScrambledSobol02(std::uint32_t index, std::uint32_t seed) {
  return owenScrambledSobol02(index, sobol02Scramble(seed));
}

Sobol02Scramble sobol02Scramble(std::uint32_t seed) {
  return {{dimensionSeed(seed, 0), dimensionSeed(seed, 1)}};
}

// owenScramble(bits, s) is reverseBits(laineKarrasPermutation(reverseBits(bits), s)); the first
// coordinate's bits are reverseBits(index) and the second's reversal comes from its own table, so
// the inner reversals cancel.
glm::vec2 owenScrambledSobol02(std::uint32_t index, const Sobol02Scramble& scramble) {
  const std::uint32_t reversedSecond =
      SobolSecondDimensionTables::lookup(sobolTables().reversedByByte, index);
  return {unitFloatFromBits(reverseBits(laineKarrasPermutation(index, scramble.dimensionSeeds[0]))),
          unitFloatFromBits(reverseBits(laineKarrasPermutation(reversedSecond, scramble.dimensionSeeds[1])))};
}

LinearIndexPermutation::LinearIndexPermutation(std::span<const std::uint32_t> columns) {
  if (columns.size() > 32) throw std::invalid_argument("LinearIndexPermutation: more than 32 columns");
  std::uint32_t images[32];
  for (std::size_t bit = 0; bit < 32; ++bit) {
    images[bit] = bit < columns.size() ? columns[bit] : 1u << bit;
    // Bit `bit` set and nothing above: the matrix is triangular with a unit diagonal.
    if (images[bit] >> bit != 1u)
      throw std::invalid_argument("LinearIndexPermutation: column " + std::to_string(bit) +
                                  " must have bit " + std::to_string(bit) + " as its highest bit");
  }
  tabulateByBytes(images, byByte_);
}

glm::vec2 hammersley(std::uint32_t index, std::uint32_t count) {
  // index / count in double, then rounded down below 1 (float(2^25 - 1) would round up to 2^25).
  const double x = static_cast<double>(index) / static_cast<double>(count);
  return {std::min(static_cast<float>(x), 0x1.fffffep-1f), radicalInverseBase2(index)};
}

}  // namespace iblkit
