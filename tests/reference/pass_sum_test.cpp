// The exact sums of split reference renders (reference/pass_sum.h): passes over disjoint sample
// ranges merge into exactly one run of all their samples, in any order, weighted by their sample
// counts; their files refuse what does not belong to the same render, and every damaged file.
#include "reference/pass_sum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <numeric>
#include <vector>

#include "core/error.h"
#include "core/usage_error.h"
#include "reference/test_scenes.h"
#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

constexpr int kSize = 20;

// A glossy sphere on a ground under a sky with a hot spot: high-variance, multi-bounce pixels.
Scene groundedScene() {
  Scene scene = test::sphereScene(test::lambert(0.7f));
  scene.materials[0].roughness = 0.3f;
  scene.materials[0].specular = 1.0f;
  scene.materials.push_back(test::lambert(0.4f));
  scene.meshes.push_back(test::meshFrom(plane(glm::vec3(0.0f, -1.0f, 0.0f), 20.0f), 1, true));
  return scene;
}

const EnvironmentMap& sky() {
  static const EnvironmentMap map = [] {
    Image image(32, 16);
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 32; ++x) image.at(x, y) = glm::vec4(glm::vec3(y < 8 ? 2.0f + x % 3 : 0.3f), 1.0f);
    image.at(5, 3) = glm::vec4(500.0f, 450.0f, 400.0f, 1.0f);
    return EnvironmentMap::fromImage(std::move(image), "sky.exr");
  }();
  return map;
}

// Samples first .. first + count - 1 of the test render (seed 7), threads as given.
RenderResult renderSamples(int first, int count, int threads = 2) {
  return test::renderWith(groundedScene(), sky(), test::integratorOf(IntegratorKind::Path), kSize, count, 7,
                          threads, 6, first);
}

PassSum sumOf(int first, int count) {
  PassSum sum = renderSamples(first, count).sum;
  sum.renderKey = 42;
  return sum;
}

std::vector<std::uint8_t> bytesOf(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const fs::path& file, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(file, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

TEST(PassSamples, SplitsTheSamplesIntoDisjointRangesThatCoverThemAll) {
  for (const auto& [spp, passes] : {std::pair{8, 3}, {64, 64}, {7, 1}, {1000, 7}}) {
    std::uint32_t next = 0;
    for (int pass = 0; pass < passes; ++pass) {
      const SampleRange range = passSamples(spp, pass, passes);
      EXPECT_EQ(range.first, next);
      EXPECT_GE(range.count, std::uint32_t(spp / passes));
      EXPECT_LE(range.count, std::uint32_t(spp / passes + 1));
      next = static_cast<std::uint32_t>(range.end());
    }
    EXPECT_EQ(next, std::uint32_t(spp));
  }
  EXPECT_THROW(passSamples(8, 0, 9), UsageError);  // a pass without samples
  EXPECT_THROW(passSamples(8, 3, 3), UsageError);
  EXPECT_THROW(passSamples(8, -1, 3), UsageError);
  EXPECT_THROW(passSamples(8, 0, 0), UsageError);
}

// The claim: three passes of 2, 3 and 3 samples merged are the 8-sample render, bit for bit
// (beauty and variance), and so are the sums themselves.
TEST(PassSum, MergedPassesAreExactlyOneRunOfAllTheirSamples) {
  const RenderResult single = renderSamples(0, 8, 1);
  PassSum merged = renderSamples(0, 2).sum;
  addPassSum(merged, renderSamples(2, 3).sum);
  addPassSum(merged, renderSamples(5, 3).sum);
  EXPECT_EQ(merged.samples, (std::vector<SampleRange>{SampleRange{0, 8}}));
  EXPECT_EQ(meanRadiance(merged).pixels(), single.beauty.pixels());
  EXPECT_EQ(meanVariance(merged).pixels(), single.variance.pixels());
  EXPECT_EQ(0, std::memcmp(merged.pixels.data(), single.sum.pixels.data(),
                           merged.pixels.size() * sizeof(PixelRadianceSum)));
  // Not a vacuous test: a render of other samples is another image.
  EXPECT_NE(renderSamples(8, 8).beauty.pixels(), single.beauty.pixels());
}

TEST(PassSum, MergeOrderDoesNotMatterThroughFilesEither) {
  const fs::path dir = test::scratchDir();
  std::vector<fs::path> files;
  for (const auto& [first, count] : {std::pair{0, 1}, {1, 4}, {5, 2}, {7, 1}}) {
    files.push_back(dir / ("pass_" + std::to_string(first) + ".sum"));
    writePassSum(files.back(), sumOf(first, count));
  }
  const PassSum forward = mergePassSumFiles(files);
  std::vector<fs::path> backward(files.rbegin(), files.rend());
  std::swap(backward[1], backward[2]);
  const PassSum shuffled = mergePassSumFiles(backward);
  writePassSum(dir / "forward.sum", forward);
  writePassSum(dir / "shuffled.sum", shuffled);
  EXPECT_EQ(bytesOf(dir / "forward.sum"), bytesOf(dir / "shuffled.sum"));
  PassSum single = sumOf(0, 8);
  writePassSum(dir / "single.sum", single);
  EXPECT_EQ(bytesOf(dir / "forward.sum"), bytesOf(dir / "single.sum"));
}

// The merged mean is the mean of every sample: a 1-sample pass counts a quarter next to a
// 3-sample pass, not half as the plain average of the two images would have it.
TEST(PassSum, MergeWeighsPassesByTheirSampleCounts) {
  PassSum merged = sumOf(0, 1);
  const Image one = meanRadiance(merged);
  const PassSum three = sumOf(1, 3);
  const Image threeMean = meanRadiance(three);
  addPassSum(merged, three);
  const Image four = meanRadiance(merged);
  EXPECT_EQ(merged.sampleCount(), 4u);
  int differing = 0;
  for (std::size_t i = 0; i < four.pixels().size(); ++i) {
    const glm::vec3 weighted = (glm::vec3(one.pixels()[i]) + 3.0f * glm::vec3(threeMean.pixels()[i])) / 4.0f;
    const glm::vec3 plain = (glm::vec3(one.pixels()[i]) + glm::vec3(threeMean.pixels()[i])) / 2.0f;
    EXPECT_NEAR(four.pixels()[i].r, weighted.r, 1e-5f * std::max(1.0f, weighted.r)) << i;
    if (std::abs(plain.r - weighted.r) > 1e-3f) ++differing;
  }
  EXPECT_GT(differing, 10);  // the weighting shows
}

TEST(PassSum, RefusesPassesOfAnotherRenderAndTheSameSamplesTwice) {
  const PassSum a = sumOf(0, 2);
  PassSum otherKey = sumOf(2, 2);
  otherKey.renderKey = 43;
  EXPECT_NE(mergeConflict(a, otherKey).find("another render"), std::string::npos);
  PassSum otherSize(kSize + 1, kSize, {2, 2}, 42);
  EXPECT_NE(mergeConflict(a, otherSize).find("21x20"), std::string::npos);
  const PassSum overlapping = sumOf(1, 2);
  EXPECT_NE(mergeConflict(a, overlapping).find("overlap"), std::string::npos);
  PassSum copy = a;
  EXPECT_THROW(addPassSum(copy, a), std::invalid_argument);
  EXPECT_EQ(mergeConflict(a, sumOf(5, 1)), "");  // a gap is fine: the mean of the samples there are
  PassSum gap = a;
  addPassSum(gap, sumOf(5, 1));
  addPassSum(gap, sumOf(2, 1));
  EXPECT_EQ(sampleRangesText(gap.samples), "0..2, 5..5");

  const fs::path dir = test::scratchDir();
  writePassSum(dir / "a.sum", a);
  writePassSum(dir / "other.sum", otherKey);
  const std::string message = test::errorMessage([&] {
    mergePassSumFiles({dir / "a.sum", dir / "other.sum"});
  });
  EXPECT_EQ(message.rfind((dir / "other.sum").string() + ": is a pass of another render", 0), 0u) << message;
}

// Every cut of a file, and flipped bytes, are refused with one line naming the file, after at
// most the header has been read.
TEST(PassSum, RefusesTruncatedAndDamagedFiles) {
  const fs::path dir = test::scratchDir(), good = dir / "good.sum", bad = dir / "bad.sum";
  writePassSum(good, sumOf(0, 1));
  const std::vector<std::uint8_t> bytes = bytesOf(good);
  ASSERT_EQ(bytes.size(), 48u + 8u + 96u * kSize * kSize + 8u);
  EXPECT_EQ(readPassSum(good).sampleCount(), 1u);
  const auto refusal = [&](const std::vector<std::uint8_t>& content) {
    writeBytes(bad, content);
    return test::errorMessage([&] { readPassSum(bad); });
  };
  for (std::size_t size : {std::size_t{0}, std::size_t{7}, std::size_t{47}, std::size_t{48},
                           std::size_t{1000}, bytes.size() - 1}) {
    const std::string message = refusal({bytes.begin(), bytes.begin() + std::ptrdiff_t(size)});
    EXPECT_EQ(message.rfind(bad.string() + ": ", 0), 0u) << size << ": " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
  EXPECT_NE(refusal({bytes.begin(), bytes.begin() + 1000}).find("truncated"), std::string::npos);
  std::vector<std::uint8_t> longer = bytes;
  longer.push_back(0);
  EXPECT_NE(refusal(longer).find("too long"), std::string::npos);
  std::vector<std::uint8_t> flipped = bytes;
  flipped[5000] ^= 1;
  EXPECT_NE(refusal(flipped).find("checksum"), std::string::npos);
  std::vector<std::uint8_t> magic = bytes;
  magic[0] = 'X';
  EXPECT_NE(refusal(magic).find("magic"), std::string::npos);
  // A hostile header claiming 16384 x 16384 pixels is refused by its length, not read.
  std::vector<std::uint8_t> huge = bytes;
  huge[13] = huge[17] = 0x40;  // width, height = 16384 + 20
  huge[12] = huge[16] = 0;
  EXPECT_NE(refusal(huge).find("the header's size needs 25769803"), std::string::npos) << refusal(huge);
}

TEST(PassSum, FixedPointKeepsTheSumsExactAndBounded) {
  EXPECT_EQ(PassSum::toFixedPoint(1.0f), FixedPointSum(1) << 32);
  EXPECT_EQ(PassSum::toFixedPoint(-0.5f), -(FixedPointSum(1) << 31));
  EXPECT_EQ(PassSum::toFixedPointSquare(-0.5f), FixedPointSum(1) << 30);
  EXPECT_EQ(PassSum::toFixedPoint(std::numeric_limits<float>::quiet_NaN()), 0);
  EXPECT_EQ(PassSum::toFixedPoint(std::numeric_limits<float>::infinity()), FixedPointSum(1) << 67);
  EXPECT_EQ(PassSum::toFixedPointSquare(1e30f), FixedPointSum(1) << 102);
}

// The conversion rounds to nearest with ties to even, as nearbyint does, on both sides of its
// 2^62 fast path: ties (k + 1/2) 2^-32, their negatives, the floats beside 2^30
// (where v 2^32 crosses 2^62), subnormals, and a sweep of floats over 75 octaves.
TEST(PassSum, FixedPointRoundsToNearestTiesToEven) {
  const auto expected = [](double scaled) { return static_cast<FixedPointSum>(std::nearbyint(scaled)); };
  std::vector<float> values = {0.0f, -0.0f, std::numeric_limits<float>::denorm_min(),
                               std::numeric_limits<float>::min(), 1.0f, 1073741824.0f,  // 2^30
                               std::nextafter(1073741824.0f, 0.0f), std::nextafter(1073741824.0f, 2e9f),
                               std::nextafter(2147483648.0f, 0.0f)};
  for (int k = 0; k < 8; ++k) values.push_back(std::ldexp(float(k) + 0.5f, -32));  // ties: 0.5, 1.5, ...
  for (float v = 1e-12f; v < 3e10f; v *= 1.37f) values.push_back(v);  // below the clamp, 2^35
  int ties = 0;
  for (const float value : values) {
    for (const float v : {value, -value}) {
      const double scaled = double(v) * 4294967296.0;
      ties += std::abs(scaled - std::trunc(scaled)) == 0.5;
      EXPECT_EQ(PassSum::toFixedPoint(v), expected(scaled)) << v;
      EXPECT_EQ(PassSum::toFixedPointSquare(v), expected(double(v) * double(v) * 4294967296.0)) << v;
    }
  }
  EXPECT_GE(ties, 16);  // the eight ties above with their negatives (the sweep meets a few more)
  // Ties go to the even neighbour: 0.5 and 2.5 down, 1.5 up.
  EXPECT_EQ(PassSum::toFixedPoint(std::ldexp(0.5f, -32)), 0);
  EXPECT_EQ(PassSum::toFixedPoint(std::ldexp(1.5f, -32)), 2);
  EXPECT_EQ(PassSum::toFixedPoint(std::ldexp(2.5f, -32)), 2);
  EXPECT_EQ(PassSum::toFixedPoint(-std::ldexp(2.5f, -32)), -2);
}

}  // namespace
}  // namespace iblkit
