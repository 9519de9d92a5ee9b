#include "reference/pixel_sampler.h"

#include "engine/core/low_discrepancy.h"

namespace iblkit {

namespace {
std::uint32_t lowbias32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}
}  // namespace

std::uint32_t hashCombine(std::uint32_t a, std::uint32_t b) {
  return lowbias32(a ^ lowbias32(b + 0x9e3779b9U));
}

PixelSeeds::PixelSeeds(std::uint32_t seed, std::uint32_t pixelIndex)
    : pixelIndex_(pixelIndex), pixelSeed_(hashCombine(seed, pixelIndex)) {
  for (int pair = 0; pair < kPixelSobolPairs; ++pair) {
    const std::uint32_t pairSeed = hashCombine(pixelSeed_, 0x50b01u + static_cast<std::uint32_t>(pair));
    shuffleSeeds_[pair] = hashCombine(pairSeed, 1u);
    scrambles_[pair] = sobol02Scramble(pairSeed);
  }
}

PixelSampler::PixelSampler(const PixelSeeds& pixel, std::uint32_t sampleIndex)
    : pixel_(pixel),
      sampleIndex_(sampleIndex),
      rng_(hashCombine(pixel.pixelSeed_, sampleIndex), pixel.pixelIndex_) {}

glm::vec2 PixelSampler::next2D() {
  if (pair_ < kSobolPairs) {
    // Burley 2020, "Practical Hash-based Owen Scrambling" (JCGT 9(4)), section 4: each pair
    // shuffles the index by its own nested uniform scramble. With one index for all pairs they are
    // correlated: the samples landing in one part of the pixel would all get their light
    // directions from one part of the sphere.
    const int pair = pair_++;
    const std::uint32_t shuffledIndex = owenScramble(sampleIndex_, pixel_.shuffleSeeds_[pair]);
    return owenScrambledSobol02(shuffledIndex, pixel_.scrambles_[pair]);
  }
  return rng_.uniform2D();
}

}  // namespace iblkit
