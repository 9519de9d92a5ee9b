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

// Point `index` of the Hammersley set of `count` points: (index / count, radical inverse).
glm::vec2 hammersley(std::uint32_t index, std::uint32_t count);

}  // namespace iblkit
