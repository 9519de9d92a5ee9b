#pragma once
// Low-discrepancy points in base 2 for integrating over [0,1)^2: the van der Corput radical
// inverse, the (0,2)-sequence formed by the first two dimensions of Sobol's sequence, and the
// Hammersley point set; with optional Owen scrambling keyed by a seed, so that each seed gives a
// different, reproducible, randomised point set that keeps the stratification.
//
// Stratification: the first 2^m points of the (0,2)-sequence (and any aligned block of 2^m
// consecutive ones), and the Hammersley set of 2^m points, are (0,m,2)-nets: every elementary
// interval [a 2^-j, (a+1) 2^-j) x [b 2^-(m-j), (b+1) 2^-(m-j)) holds exactly one point.
// Owen scrambling preserves this (Owen 1995, "Randomly Permuted (t,m,s)-Nets and (t,s)-Sequences").
//
// Values are returned as floats with 24 bits (unitFloatFromBits in rng.h), so they are < 1 and
// nets of up to 2^24 points stay exact.

#include <cstdint>
#include <glm/glm.hpp>
#include <span>

namespace iblkit {

// Van der Corput: the bits of `index` mirrored about the binary point (1 -> 0.5, 2 -> 0.25, ...).
float radicalInverseBase2(std::uint32_t index);

// Owen's nested uniform scramble of a 32-bit binary fraction: each bit is flipped or not by a
// random function of the bits above it, the random functions chosen by `seed` (which should be
// well mixed: the sequences below hash theirs). Implemented as a
// hash that only lets lower bits affect higher ones (Laine & Karras 2011, "Stratified Sampling for
// Stochastic Transparency") applied to the bit-reversed fraction, with the improved constants of
// Vegdahl 2021, "Building a Better LK Hash" (see also Burley 2020, "Practical Hash-based Owen
// Scrambling", JCGT 9(4)).
std::uint32_t owenScramble(std::uint32_t fractionBits, std::uint32_t seed);

// The radical inverse, Owen-scrambled with a hash of `seed` (the same as owenScrambledSobol02's
// first coordinate). Any seeds, consecutive ones too, give independent scrambles.
float owenScrambledRadicalInverseBase2(std::uint32_t index, std::uint32_t seed);

// Point `index` of the (0,2)-sequence: (radical inverse, Sobol's second dimension). The second
// dimension's generator matrix is the upper-triangular Pascal matrix mod 2 (direction numbers
// v_1 = 1/2, v_(k+1) = v_k xor v_k / 2).
glm::vec2 sobol02(std::uint32_t index);
// The same point with both coordinates Owen-scrambled by independent hashes of (seed, dimension).
glm::vec2 owenScrambledSobol02(std::uint32_t index, std::uint32_t seed);
// The two per-dimension scrambling seeds owenScrambledSobol02 hashes out of `seed`, for callers
// that draw many points with one seed: owenScrambledSobol02(i, sobol02Scramble(seed)) ==
// owenScrambledSobol02(i, seed), without hashing the seed again for every point.
struct Sobol02Scramble {
  std::uint32_t dimensionSeeds[2] = {0, 0};
};
Sobol02Scramble sobol02Scramble(std::uint32_t seed);
glm::vec2 owenScrambledSobol02(std::uint32_t index, const Sobol02Scramble& scramble);

// A linear bijection of 32-bit sample indices (over GF(2)) that maps every aligned block of 2^m
// indices, k 2^m .. (k+1) 2^m - 1, onto an aligned block of 2^m, the first block onto itself: index
// bit j contributes columns[j], which has bit j set and no higher bit (an upper triangular matrix
// with a unit diagonal); bits past the given columns map to themselves. Drawing a digital sequence
// at permuted indices multiplies its generator matrices on the right by this matrix (Faure and
// Tezuka 2002, "Another Random Scrambling of Digital (t,s)-Sequences"), which keeps the t of its
// nets: the first 2^m points are the same points in another order, any other aligned block a
// digital shift of them. What changes is which points of two sequences share an index: two
// (0,2)-sequences drawn at differently permuted indices form a 4D sequence whose t depends on the
// permutations.
class LinearIndexPermutation {
 public:
  // columns.size() <= 32; columns[j] must have bit j set and no bit above j.
  explicit LinearIndexPermutation(std::span<const std::uint32_t> columns);
  std::uint32_t operator()(std::uint32_t index) const {
    return byByte_[0][index & 0xffu] ^ byByte_[1][(index >> 8) & 0xffu] ^ byByte_[2][(index >> 16) & 0xffu] ^
           byByte_[3][index >> 24];
  }

 private:
  // The map is linear, so it is taken a byte of the index at a time.
  std::uint32_t byByte_[4][256];
};

// Point `index` of the Hammersley set of `count` points: (index / count, radical inverse).
glm::vec2 hammersley(std::uint32_t index, std::uint32_t count);

}  // namespace iblkit
