#pragma once
// PCG32: the small, fast, statistically good random number generator of O'Neill 2014, "PCG: A
// Family of Simple Fast Space-Efficient Statistically Good Algorithms for Random Number
// Generation" (pcg32 = PCG-XSH-RR: 64-bit LCG state, 32-bit output by xorshift-high and a random
// rotation). A (seed, stream) pair names one reproducible sequence; different streams are
// independent sequences, which is how per-pixel or per-thread generators are made.

#include <cstdint>
#include <glm/glm.hpp>

namespace iblkit {

// The 24 high bits of `bits` as a float in [0, 1): exact, and never 1.0 (rounding 32 bits to a
// 24-bit mantissa could give 1.0f). Shared by the generator and the low-discrepancy sequences.
inline float unitFloatFromBits(std::uint32_t bits) { return static_cast<float>(bits >> 8) * 0x1p-24f; }

class PCG32 {
 public:
  // Same initialisation as pcg32_srandom_r in O'Neill's reference code, so the reference
  // outputs (seed 42, stream 54 -> 0xa15c02b7, 0x7b47f409, ...) are reproduced.
  explicit PCG32(std::uint64_t seed, std::uint64_t stream = 0) { setSequence(seed, stream); }

  void setSequence(std::uint64_t seed, std::uint64_t stream) {
    state_ = 0;
    increment_ = (stream << 1) | 1u;  // the LCG increment must be odd
    nextUInt32();
    state_ += seed;
    nextUInt32();
  }

  // Uniform 32-bit integer.
  std::uint32_t nextUInt32() {
    const std::uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + increment_;
    const auto xorShifted = static_cast<std::uint32_t>(((old >> 18) ^ old) >> 27);
    const auto rotation = static_cast<std::uint32_t>(old >> 59);
    return (xorShifted >> rotation) | (xorShifted << ((32u - rotation) & 31u));
  }

  // Uniform float in [0, 1), never 1.0.
  float uniformFloat() { return unitFloatFromBits(nextUInt32()); }
  // Two uniform floats in [0, 1), first x then y.
  glm::vec2 uniform2D() {
    const float x = uniformFloat();
    return {x, uniformFloat()};
  }

 private:
  std::uint64_t state_ = 0, increment_ = 1;
};

}  // namespace iblkit
