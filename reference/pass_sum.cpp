#include "reference/pass_sum.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "core/content_hash.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/input_file.h"
#include "core/usage_error.h"

#if defined(__x86_64__)
#include <emmintrin.h>
#endif

namespace iblkit {

namespace {

constexpr char kMagic[8] = {'I', 'B', 'L', 'K', 'S', 'U', 'M', '\n'};
constexpr std::uint32_t kVersion = 1;
constexpr std::size_t kHeaderBytes = 48, kRangeBytes = 8, kChecksumBytes = 8;
constexpr std::size_t kPixelBytes = kPassSumChannels * 16;
// The clamp of a sample value (pass_sum.h): 2^35.
constexpr double kMaxSampleValue = 34359738368.0;
constexpr double kScale = 4294967296.0;  // 2^kPassSumFractionBits
// The largest sum one sample adds: |round(v 2^32)| <= 2^67 and round(v^2 2^32) <= 2^102.
constexpr int kMaxRadianceBitsPerSample = 67, kMaxSquaredBitsPerSample = 102;

static_assert(kPassSumFractionBits == 32, "kScale is 2^32");

std::string rangeText(const SampleRange& r) {
  return std::to_string(r.first) + ".." + std::to_string(r.end() - 1);
}

void putU32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}
void putU64(std::vector<std::uint8_t>& out, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}
std::uint32_t getU32(const std::uint8_t* p) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}
std::uint64_t getU64(const std::uint8_t* p) {
  std::uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}
void putSum(std::vector<std::uint8_t>& out, FixedPointSum v) {
  __extension__ typedef unsigned __int128 Unsigned;
  const auto u = static_cast<Unsigned>(v);
  putU64(out, static_cast<std::uint64_t>(u));
  putU64(out, static_cast<std::uint64_t>(u >> 64));
}
FixedPointSum getSum(const std::uint8_t* p) {
  __extension__ typedef unsigned __int128 Unsigned;
  const Unsigned u = (Unsigned{getU64(p + 8)} << 64) | getU64(p);
  return static_cast<FixedPointSum>(u);  // two's complement (C++20)
}

// Joins ranges that touch; `ranges` sorted and disjoint.
std::vector<SampleRange> joined(std::vector<SampleRange> ranges) {
  std::vector<SampleRange> out;
  for (const SampleRange& r : ranges) {
    if (!out.empty() && out.back().end() == r.first)
      out.back().count += r.count;
    else
      out.push_back(r);
  }
  return out;
}

// The ranges of `a` and `b` (each sorted, disjoint from the other), sorted and joined.
std::vector<SampleRange> unitedRanges(const std::vector<SampleRange>& a, const std::vector<SampleRange>& b) {
  std::vector<SampleRange> all(a);
  all.insert(all.end(), b.begin(), b.end());
  std::sort(all.begin(), all.end(), [](const SampleRange& x, const SampleRange& y) { return x.first < y.first; });
  return joined(std::move(all));
}

std::string checkRanges(const std::vector<SampleRange>& ranges) {
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    const SampleRange& r = ranges[i];
    if (r.count == 0) return "sample range " + std::to_string(i) + " is empty";
    if (r.end() > std::uint64_t(kMaxSamplesPerPixel))
      return "sample range " + std::to_string(i) + " ends beyond " + std::to_string(kMaxSamplesPerPixel);
    if (i > 0 && r.first <= ranges[i - 1].end())
      return "sample ranges " + std::to_string(i - 1) + " and " + std::to_string(i) +
             " are out of order, overlap or touch";
  }
  return {};
}

}  // namespace

SampleRange passSamples(int samplesPerPixel, int pass, int passes) {
  if (passes < 1 || passes > samplesPerPixel)
    failUsage("--passes", "must be in 1.." + std::to_string(samplesPerPixel) + " (the --spp), not " +
                              std::to_string(passes));
  if (pass < 0 || pass >= passes)
    failUsage("--pass", "must be in 0.." + std::to_string(passes - 1) + ", not " + std::to_string(pass));
  const auto boundary = [&](int i) {
    return static_cast<std::uint32_t>(std::int64_t{samplesPerPixel} * i / passes);
  };
  return {boundary(pass), boundary(pass + 1) - boundary(pass)};
}

PassSum::PassSum(int width_, int height_, SampleRange range, std::uint64_t key)
    : width(width_),
      height(height_),
      renderKey(key),
      samples{range},
      pixels(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_)) {}

std::uint64_t PassSum::sampleCount() const {
  std::uint64_t n = 0;
  for (const SampleRange& r : samples) n += r.count;
  return n;
}

namespace {
// round(x) (to nearest, ties to even: nearbyint in the default rounding mode) as a 128-bit integer.
// Below 2^62 through one instruction: SSE2's cvtsd2si rounds by the current mode, which is
// nearbyint's. Both nearbyint and the 128-bit conversion are library calls (the latter was 2% of a
// render, nearbyint another 1-2%, six of each per sample). The same value either way.
FixedPointSum roundToFixed(double x) {
  constexpr double kSixtyTwo = 4611686018427387904.0;  // 2^62
  if (std::abs(x) < kSixtyTwo) {
#if defined(__x86_64__)
    return static_cast<FixedPointSum>(_mm_cvtsd_si64(_mm_set_sd(x)));
#else
    return static_cast<FixedPointSum>(static_cast<std::int64_t>(std::nearbyint(x)));
#endif
  }
  return static_cast<FixedPointSum>(std::nearbyint(x));
}
}  // namespace

FixedPointSum PassSum::toFixedPoint(float value) {
  if (std::isnan(value)) return 0;
  const double v = std::clamp(double(value), -kMaxSampleValue, kMaxSampleValue);
  return roundToFixed(v * kScale);
}

FixedPointSum PassSum::toFixedPointSquare(float value) {
  if (std::isnan(value)) return 0;
  const double v = std::min(std::abs(double(value)), kMaxSampleValue);
  return roundToFixed(v * v * kScale);  // v * v is exact in double
}

std::string sampleRangesText(const std::vector<SampleRange>& samples) {
  std::string text;
  for (const SampleRange& r : samples) text += (text.empty() ? "" : ", ") + rangeText(r);
  return text;
}

std::string mergeConflict(const PassSum& a, const PassSum& b) {
  if (a.width != b.width || a.height != b.height)
    return "is " + std::to_string(b.width) + "x" + std::to_string(b.height) + ", the others " +
           std::to_string(a.width) + "x" + std::to_string(a.height);
  if (a.renderKey != b.renderKey) {
    const auto hex = [](std::uint64_t key) {
      char text[17];
      std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(key));
      return std::string(text);
    };
    return "is a pass of another render (key " + hex(b.renderKey) + ", the others " + hex(a.renderKey) +
           "): another scene, map, setting or build";
  }
  for (const SampleRange& rb : b.samples)
    for (const SampleRange& ra : a.samples)
      if (rb.first < ra.end() && ra.first < rb.end())
        return "samples " + rangeText(rb) + " overlap samples " + rangeText(ra) +
               " already merged (the same pass twice?)";
  if (a.sampleCount() + b.sampleCount() > std::uint64_t(kMaxSamplesPerPixel))
    return "takes the sample count beyond " + std::to_string(kMaxSamplesPerPixel);
  if (unitedRanges(a.samples, b.samples).size() > std::size_t(kMaxPassSumRanges))
    return "leaves more than " + std::to_string(kMaxPassSumRanges) + " separate sample ranges";
  return {};
}

void addPassSum(PassSum& a, const PassSum& b) {
  if (const std::string conflict = mergeConflict(a, b); !conflict.empty())
    throw std::invalid_argument(conflict);
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      a.pixels[i].radiance[c] += b.pixels[i].radiance[c];
      a.pixels[i].squared[c] += b.pixels[i].squared[c];
    }
  a.samples = unitedRanges(a.samples, b.samples);
}

Image meanRadiance(const PassSum& sum) {
  Image image(sum.width, sum.height);
  const double n = double(sum.sampleCount()) * kScale;
  for (std::size_t i = 0; i < sum.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      image.pixels()[i][c] = static_cast<float>(static_cast<double>(sum.pixels[i].radiance[c]) / n);
  return image;
}

Image meanVariance(const PassSum& sum) {
  Image image(sum.width, sum.height);
  const double n = double(sum.sampleCount());
  if (n < 2.0) return image;
  for (std::size_t i = 0; i < sum.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double mean = static_cast<double>(sum.pixels[i].radiance[c]) / kScale / n;
      const double squares = static_cast<double>(sum.pixels[i].squared[c]) / kScale;
      const double sampleVariance = std::max(squares - n * mean * mean, 0.0) / (n - 1.0);
      image.pixels()[i][c] = static_cast<float>(sampleVariance / n);
    }
  return image;
}

void writePassSum(const std::filesystem::path& file, const PassSum& sum) {
  std::vector<std::uint8_t> bytes(std::begin(kMagic), std::end(kMagic));
  bytes.reserve(kHeaderBytes + kRangeBytes * sum.samples.size() + kPixelBytes * sum.pixels.size() +
                kChecksumBytes);
  putU32(bytes, kVersion);
  putU32(bytes, static_cast<std::uint32_t>(sum.width));
  putU32(bytes, static_cast<std::uint32_t>(sum.height));
  putU32(bytes, kPassSumChannels);
  putU32(bytes, kPassSumFractionBits);
  putU32(bytes, static_cast<std::uint32_t>(sum.samples.size()));
  putU64(bytes, sum.renderKey);
  putU64(bytes, sum.sampleCount());
  for (const SampleRange& r : sum.samples) {
    putU32(bytes, r.first);
    putU32(bytes, r.count);
  }
  for (const PixelRadianceSum& p : sum.pixels) {
    for (int c = 0; c < 3; ++c) putSum(bytes, p.radiance[c]);
    for (int c = 0; c < 3; ++c) putSum(bytes, p.squared[c]);
  }
  putU64(bytes, ContentHash().add({reinterpret_cast<const char*>(bytes.data()), bytes.size()}).value());
  writeAtomically(file, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    out.close();
    if (!out) fail(file, "cannot write the pass sum");
  });
}

PassSum readPassSum(const std::filesystem::path& file) {
  requireRegularInputFile(file, std::numeric_limits<std::uintmax_t>::max());
  std::ifstream in(file, std::ios::binary);
  if (!in) fail(file, "cannot open");
  std::array<std::uint8_t, kHeaderBytes> header;
  in.read(reinterpret_cast<char*>(header.data()), std::streamsize(header.size()));
  if (std::size_t(in.gcount()) < kHeaderBytes)
    fail(file, "truncated: " + std::to_string(in.gcount()) + " bytes, shorter than a pass sum's header");
  if (std::memcmp(header.data(), kMagic, sizeof kMagic) != 0)
    fail(file, "not an iblkit pass sum (wrong magic)");
  const std::uint8_t* h = header.data();
  if (getU32(h + 8) != kVersion)
    fail(file,
         "pass sum version " + std::to_string(getU32(h + 8)) + ", expected " + std::to_string(kVersion));
  const std::uint32_t width = getU32(h + 12), height = getU32(h + 16), rangeCount = getU32(h + 28);
  if (width < 1 || width > std::uint32_t(kMaxImageSide) || height < 1 ||
      height > std::uint32_t(kMaxImageSide))
    fail(file, "image size " + std::to_string(width) + "x" + std::to_string(height) + " is outside 1.." +
                   std::to_string(kMaxImageSide));
  if (getU32(h + 20) != std::uint32_t(kPassSumChannels) ||
      getU32(h + 24) != std::uint32_t(kPassSumFractionBits))
    fail(file, std::to_string(getU32(h + 20)) + " channels of " + std::to_string(getU32(h + 24)) +
                   " fraction bits, expected " + std::to_string(kPassSumChannels) + " of " +
                   std::to_string(kPassSumFractionBits));
  if (rangeCount < 1 || rangeCount > std::uint32_t(kMaxPassSumRanges))
    fail(file,
         std::to_string(rangeCount) + " sample ranges, outside 1.." + std::to_string(kMaxPassSumRanges));
  const std::uint64_t pixelCount = std::uint64_t{width} * height;
  const std::uint64_t expected =
      kHeaderBytes + kRangeBytes * rangeCount + kPixelBytes * pixelCount + kChecksumBytes;
  std::error_code error;
  const std::uintmax_t actual = std::filesystem::file_size(file, error);
  if (error) fail(file, "cannot read its size: " + error.message());
  if (actual != expected)
    fail(file, std::string(actual < expected ? "truncated" : "too long") + ": " + std::to_string(actual) +
                   " bytes, the header's size needs " + std::to_string(expected));
  std::vector<std::uint8_t> bytes(expected);
  std::copy(header.begin(), header.end(), bytes.begin());
  in.read(reinterpret_cast<char*>(bytes.data() + kHeaderBytes), std::streamsize(expected - kHeaderBytes));
  if (std::uint64_t(in.gcount()) != expected - kHeaderBytes) fail(file, "truncated while reading");
  const std::uint64_t checksum =
      ContentHash().add({reinterpret_cast<const char*>(bytes.data()), expected - kChecksumBytes}).value();
#ifndef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
  if (checksum != getU64(bytes.data() + expected - kChecksumBytes))
    fail(file, "checksum mismatch (corrupt file)");
#else
  (void)checksum;
#endif

  PassSum sum;
  sum.width = int(width);
  sum.height = int(height);
  sum.renderKey = getU64(h + 32);
  const std::uint8_t* p = bytes.data() + kHeaderBytes;
  for (std::uint32_t i = 0; i < rangeCount; ++i, p += kRangeBytes)
    sum.samples.push_back({getU32(p), getU32(p + 4)});
  if (const std::string problem = checkRanges(sum.samples); !problem.empty()) fail(file, problem);
  const std::uint64_t n = sum.sampleCount();
  if (n != getU64(h + 40))
    fail(file, "sample count " + std::to_string(getU64(h + 40)) + " is not the ranges' " + std::to_string(n));
  if (n > std::uint64_t(kMaxSamplesPerPixel))
    fail(file, "sample count " + std::to_string(n) + " is beyond " + std::to_string(kMaxSamplesPerPixel));
  // No sum may exceed what its samples can add (so merges cannot overflow).
  const FixedPointSum radianceLimit = FixedPointSum(n) << kMaxRadianceBitsPerSample;
  const FixedPointSum squaredLimit = FixedPointSum(n) << kMaxSquaredBitsPerSample;
  sum.pixels.resize(pixelCount);
  for (std::uint64_t i = 0; i < pixelCount; ++i) {
    PixelRadianceSum& pixel = sum.pixels[i];
    for (int c = 0; c < 3; ++c, p += 16) pixel.radiance[c] = getSum(p);
    for (int c = 0; c < 3; ++c, p += 16) pixel.squared[c] = getSum(p);
    for (int c = 0; c < 3; ++c)
      if (pixel.radiance[c] > radianceLimit || pixel.radiance[c] < -radianceLimit || pixel.squared[c] < 0 ||
          pixel.squared[c] > squaredLimit)
        fail(file, "pixel " + std::to_string(i % width) + "," + std::to_string(i / width) +
                       " holds a sum its " + std::to_string(n) + " samples cannot reach");
  }
  return sum;
}

PassSum mergePassSumFiles(const std::vector<std::filesystem::path>& files) {
  if (files.empty()) throw std::invalid_argument("mergePassSumFiles: no files");
  PassSum total = readPassSum(files.front());
  for (std::size_t i = 1; i < files.size(); ++i) {
    const PassSum next = readPassSum(files[i]);
    if (const std::string conflict = mergeConflict(total, next); !conflict.empty()) fail(files[i], conflict);
    addPassSum(total, next);
  }
  return total;
}

std::uint64_t renderKey(const std::vector<std::filesystem::path>& inputs, std::string_view settings) {
  ContentHash hash;
  hash.addFile("/proc/self/exe");
  for (const std::filesystem::path& input : inputs) {
    std::error_code error;
    if (std::filesystem::is_regular_file(input, error))
      hash.addFile(input);
    else
      hash.add(input.string());  // a built-in model ("shape:sphere")
  }
  hash.add(settings);
  return hash.value();
}

}  // namespace iblkit
