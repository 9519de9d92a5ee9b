#pragma once
// PixelSampler: the random numbers of one camera sample, a pure function of (seed, pixel, sample
// index). Nothing depends on which thread renders a pixel or in which order, so an image is the
// same for a given seed whatever the thread count, and --time passes continue the sequence.
//
// The first kSobolPairs 2D draws (pixel position, then the first bounce's light and BRDF
// directions, where stratification pays most) are points of the Sobol (0,2)-sequence
// (low_discrepancy.h), each pair at its own fixed linear permutation of the sample index
// (none for the pixel position) and each dimension Owen-scrambled per pixel. Each pair on its own
// is a (0,2)-sequence; the pixel position with the light or the BRDF draw is a 4D sequence whose
// aligned blocks of 2^m samples are (t,m,4)-nets with t <= 3 up to 4096 samples and t <= 4 up to
// 65536 (pixel_sampler.cpp), so the samples that land on one side of an edge inside the pixel still
// cover the light and BRDF squares evenly. The next kPaddedPairs 2D draws (the second and third
// vertices' light and BRDF directions) are Sobol (0,2)-points too, each at its own per-pixel
// random shuffle of the sample index (Burley 2020's padding: a nested uniform scramble of the index
// bits, which maps every aligned block of 2^m indices onto an aligned block, so each of these draws
// is still a (0,m,2)-net over any aligned block of a pixel's samples, matched at random with the
// other draws). Everything else comes from a PCG32 stream keyed by the pixel and the sample index.
//
// Splitting (IntegratorSettings::cameraLightSamples K): the first vertex's K light draws are the
// light pair's points at indices K l(i) .. K l(i) + K - 1, l(i) the light draw's permuted index of
// sample i (splitLight2D). For K a power of 2 each sample's K points are an aligned block of the
// (0,2)-sequence, a (0,log2 K,2)-net, and the K 2^m points of an aligned block of 2^m samples are
// one too: the light directions stay stratified within a sample and across the pixel's samples.

#include <cstdint>
#include <glm/glm.hpp>

#include "core/low_discrepancy.h"
#include "core/rng.h"

namespace iblkit {

// Mixes two 32-bit values into a well-distributed 32-bit hash ("lowbias32" finaliser by Chris
// Wellons, "Prospecting for Hash Functions", 2018, applied to a ^ mixed(b)). Used to derive
// per-pixel and per-dimension seeds.
std::uint32_t hashCombine(std::uint32_t a, std::uint32_t b);

// Number of leading 2D draws of a camera sample taken from the scrambled Sobol sequence at fixed
// index permutations (pixel position, the first vertex's light and BRDF draws).
inline constexpr int kPixelSobolPairs = 3;
// The Sobol draws after those, each at a per-pixel random shuffle of the index (the second and
// third vertices' light and BRDF draws).
inline constexpr int kPixelPaddedPairs = 4;
// The most light draws PixelSampler::splitLight2D splits the first vertex's into (indices stay
// below 2^32 for kMaxSamplesPerPixel = 2^24 samples).
inline constexpr int kMaxSplitLightDraws = 64;

// The part of a PixelSampler's keys that depends only on (seed, pixel): the hashes that scramble
// each Sobol pair. The renderer computes it once per pixel instead of once per sample.
class PixelSeeds {
 public:
  PixelSeeds(std::uint32_t seed, std::uint32_t pixelIndex);

 private:
  friend class PixelSampler;
  std::uint32_t pixelIndex_, pixelSeed_;
  Sobol02Scramble scrambles_[kPixelSobolPairs + kPixelPaddedPairs];
  std::uint32_t shuffles_[kPixelPaddedPairs];  // the padded pairs' index shuffles
};

class PixelSampler {
 public:
  static constexpr int kSobolPairs = kPixelSobolPairs;
  static constexpr int kPaddedPairs = kPixelPaddedPairs;

  PixelSampler(std::uint32_t seed, std::uint32_t pixelIndex, std::uint32_t sampleIndex)
      : PixelSampler(PixelSeeds(seed, pixelIndex), sampleIndex) {}
  // The same numbers as PixelSampler(seed, pixelIndex, sampleIndex) for the seeds of (seed, pixelIndex).
  PixelSampler(const PixelSeeds& pixel, std::uint32_t sampleIndex);

  // The next point in [0,1)^2.
  glm::vec2 next2D();
  // The next number in [0,1) (always from PCG32: 1D choices such as lobe selection and Russian
  // roulette gain little from stratification).
  float next1D() { return rng_.uniformFloat(); }
  // The j-th of `count` light draws of the first vertex (0 <= j < count <= kMaxSplitLightDraws),
  // above. It does not advance the sequence; splitLight2D(0, 1) is the light pair's own draw,
  // the second next2D().
  glm::vec2 splitLight2D(int j, int count) const;

 private:
  PixelSeeds pixel_;
  std::uint32_t sampleIndex_;
  int pair_ = 0;
  PCG32 rng_;
};

}  // namespace iblkit
