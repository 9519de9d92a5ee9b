#pragma once
// PassSum: what a reference render has added up, per pixel, over a set of sample indices: the sums
// of each sample's radiance and of its square, in 128-bit fixed point, with the sample indices they
// cover. A sample's random numbers depend only on (seed, pixel, sample index) (pixel_sampler.h),
// and integer addition is exact, associative and commutative, so passes that cover disjoint
// sample ranges of one render add up to exactly the sums of one run of all their samples, in any
// order: a render split over the tasks of a Slurm array (`iblkit-trace --pass I --passes N --sum
// FILE`) and merged (`iblkit-trace --merge FILE... -o OUT.exr`) is the same image, byte for byte,
// as one run with the same seed (docs/cluster.md). The merged mean weighs each pass by its sample
// count because it is the sum of every sample over their total count (as Cycles' merge does).
//
// Fixed point: a sample value v (a radiance channel, W / (sr m^2)) counts as round(v * 2^32),
// rounded to nearest; its square as round(v^2 * 2^32). |v| is clamped to 2^35 and NaN counts as 0
// (neither occurs in a working render), so kMaxSamplesPerPixel samples stay below 2^127: no sum
// overflows, whatever a file claims (readPassSum checks every sum against its sample count).
// The resolution, 2^-32 per sample, is below a float's at 1e-3; the mean is rounded once to float.
//
// The file (".sum"), little-endian, version 1:
//   offset  bytes  field
//   0       8      magic "IBLKSUM\n"
//   8       4      version (1)
//   12      4      width, 1..kMaxImageSide
//   16      4      height, 1..kMaxImageSide
//   20      4      channels per pixel (6: radiance R G B, then their squares)
//   24      4      fraction bits (32)
//   28      4      number of sample ranges R, 1..kMaxPassSumRanges
//   32      8      render key (renderKey(): the program, its inputs' bytes, the sampling settings)
//   40      8      sample count: the sum of the ranges' counts, 1..kMaxSamplesPerPixel
//   48      8 R    sample ranges: first index, count (uint32 each), sorted, disjoint, not touching
//   ...     96 WH  per pixel (rows top to bottom), per channel: the sum as int128 (low 64 bits, then
//                  the high 64 bits, two's complement)
//   end-8   8      checksum: FNV-1a 64 (ContentHash::add) of every byte before it
// A file is written to a temporary name and renamed (writeAtomically), so a killed task never
// leaves half a file under the final name.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/image.h"

namespace iblkit {

// Largest accepted image side and sample count per pixel (Sobol indices stay exact in floats):
// the renderer's limits (renderer.h), and a pass sum file's.
inline constexpr int kMaxImageSide = 16384;
inline constexpr int kMaxSamplesPerPixel = 1 << 24;

__extension__ typedef __int128 FixedPointSum;  // GCC and Clang's 128-bit integer

inline constexpr int kPassSumFractionBits = 32;
inline constexpr int kPassSumChannels = 6;
inline constexpr int kMaxPassSumRanges = 4096;

// Sample indices first .. first + count - 1.
struct SampleRange {
  std::uint32_t first = 0, count = 0;
  std::uint64_t end() const { return std::uint64_t{first} + count; }
  bool operator==(const SampleRange&) const = default;
};

// Pass `pass` of `passes` (0-based) of a render of `samplesPerPixel` samples per pixel: the
// samples [pass spp / passes, (pass + 1) spp / passes) (rounded down), so the passes cover every
// sample once and differ in size by at most one. Throws UsageError("--pass: ...") or ("--passes:
// ...") unless 1 <= passes <= samplesPerPixel and 0 <= pass < passes.
SampleRange passSamples(int samplesPerPixel, int pass, int passes);

struct PixelRadianceSum {
  FixedPointSum radiance[3] = {0, 0, 0}, squared[3] = {0, 0, 0};
};

struct PassSum {
  int width = 0, height = 0;
  std::uint64_t renderKey = 0;
  std::vector<SampleRange> samples;  // sorted, disjoint and not touching
  std::vector<PixelRadianceSum> pixels;

  // An empty sum (every pixel 0) over `samples`.
  PassSum(int width, int height, SampleRange samples, std::uint64_t renderKey = 0);
  PassSum() = default;

  std::uint64_t sampleCount() const;
  // Adds one sample's radiance to `pixel` (y * width + x).
  void addSample(std::size_t pixel, const glm::vec3& radiance) {
    PixelRadianceSum& p = pixels[pixel];
    for (int c = 0; c < 3; ++c) {
      p.radiance[c] += toFixedPoint(radiance[c]);
      p.squared[c] += toFixedPointSquare(radiance[c]);
    }
  }

  static FixedPointSum toFixedPoint(float value);
  static FixedPointSum toFixedPointSquare(float value);
};

// The sample ranges as text, "0..3, 8..11".
std::string sampleRangesText(const std::vector<SampleRange>& samples);

// Why `b` cannot be added to `a` (different size or render key, or a sample index both cover, so
// the same pass merged twice), in words that follow a file name; empty when it can.
std::string mergeConflict(const PassSum& a, const PassSum& b);

// Adds `b` into `a`: the sums, and the sample ranges (joined where they touch). Throws
// std::invalid_argument with mergeConflict's words when they conflict.
void addPassSum(PassSum& a, const PassSum& b);

// The mean radiance per pixel (alpha 1): the sum over the sample count, rounded once to float.
Image meanRadiance(const PassSum& sum);
// Per channel, the unbiased sample variance over the sample count: the variance of each pixel's
// mean (RenderResult::variance); 0 for a single sample.
Image meanVariance(const PassSum& sum);

// Writes `sum` to `file` atomically. Throws Error naming the file on an I/O failure.
void writePassSum(const std::filesystem::path& file, const PassSum& sum);

// Reads a file of writePassSum's. Throws Error("<file>: <problem>") for anything but a whole,
// valid file (wrong magic or version, a size outside the limits, ranges out of order, a length
// other than the header's, a sum its sample count cannot reach, a wrong checksum), after reading
// at most the header when the file's length does not match it.
PassSum readPassSum(const std::filesystem::path& file);

// The files' sums added up (addPassSum) in the order given; a conflict throws Error naming the
// file that conflicts with those before it.
PassSum mergePassSumFiles(const std::vector<std::filesystem::path>& files);

// The key of a render, the same for every pass of it and different for another (a pass of another
// scene, map or setting must not merge): FNV-1a 64 (core/content_hash.h) of the running program
// (/proc/self/exe: another build may trace other samples), the bytes of `inputs` (the scene, its
// models and map; the name of one that is no file, a built-in shape) and `settings`, the text of
// every setting that changes a sample.
std::uint64_t renderKey(const std::vector<std::filesystem::path>& inputs, std::string_view settings);

}  // namespace iblkit
