#include "score/flip.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include <tbb/task_arena.h>

#include "core/image_io.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

double meanError(const FlipErrorMap& map) {
  return std::accumulate(map.error.begin(), map.error.end(), 0.0) / double(map.error.size());
}

// A smooth colourful LDR pattern with edges, values in [0,1].
Image pattern(int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float u = float(x) / float(width), v = float(y) / float(height);
      const float stripe = (x / 8 + y / 8) % 2 ? 0.8f : 0.2f;
      image.at(x, y) = glm::vec4(0.5f + 0.4f * std::sin(6.0f * u), stripe * v, 0.3f + 0.5f * u * v, 1.0f);
    }
  return image;
}

// Deterministic pseudo-random noise in [-amplitude, amplitude], clamped to [0,1].
Image withNoise(const Image& image, float amplitude) {
  Image out = image;
  std::uint32_t state = 12345u;
  for (glm::vec4& p : out.pixels())
    for (int c = 0; c < 3; ++c) {
      state = state * 1664525u + 1013904223u;
      const float r = float(state >> 8) / float(1u << 24) * 2.0f - 1.0f;
      p[c] = std::clamp(p[c] + amplitude * r, 0.0f, 1.0f);
    }
  return out;
}

// Box blur of the given radius (clamped borders).
Image withBlur(const Image& image, int radius) {
  Image out = image;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      glm::vec4 sum(0.0f);
      for (int j = -radius; j <= radius; ++j)
        for (int i = -radius; i <= radius; ++i)
          sum += image.at(std::clamp(x + i, 0, image.width() - 1), std::clamp(y + j, 0, image.height() - 1));
      out.at(x, y) = sum / float((2 * radius + 1) * (2 * radius + 1));
    }
  return out;
}

TEST(Flip, IdenticalImagesScoreZero) {
  const Image image = pattern(64, 48);
  const FlipErrorMap ldr = ldrFlip(image, image);
  ASSERT_EQ(ldr.width, 64);
  ASSERT_EQ(ldr.height, 48);
  for (float e : ldr.error) ASSERT_EQ(e, 0.0f);
  Image hdr = image;
  for (glm::vec4& p : hdr.pixels()) p *= 40.0f;
  for (float e : hdrFlip(hdr, hdr, {-3.0f, 2.0f, 5}).error) ASSERT_EQ(e, 0.0f);
}

TEST(Flip, BlackAgainstWhiteIsTheLargestError) {
  const Image black(16, 16, glm::vec4(0, 0, 0, 1)), white(16, 16, glm::vec4(1.0f));
  // Uniform images have no features, so the error is the mapped colour error of black vs white,
  // which lies above the knee pt = 0.95.
  const FlipErrorMap map = ldrFlip(black, white);
  for (float e : map.error) {
    ASSERT_GT(e, 0.95f);
    ASSERT_LE(e, 1.0f);
  }
}

TEST(Flip, ErrorGrowsWithNoiseAmplitude) {
  const Image reference = pattern(64, 48);
  double previous = 0.0;
  for (float amplitude : {0.02f, 0.05f, 0.1f, 0.2f, 0.4f}) {
    const double error = meanError(ldrFlip(reference, withNoise(reference, amplitude)));
    EXPECT_GT(error, previous) << "amplitude " << amplitude;
    previous = error;
  }
}

TEST(Flip, ErrorGrowsWithBlurRadius) {
  const Image reference = pattern(64, 48);
  double previous = 0.0;
  for (int radius : {1, 2, 3, 5}) {
    const double error = meanError(ldrFlip(reference, withBlur(reference, radius)));
    EXPECT_GT(error, previous) << "radius " << radius;
    previous = error;
  }
}

TEST(Flip, AcesIsTheChaptersFitOfPointSixX) {
  EXPECT_EQ(flipAces(0.0f), 0.0f);
  const double v = 0.6;  // x = 1
  EXPECT_NEAR(flipAces(1.0f), v * (2.51 * v + 0.03) / (v * (2.43 * v + 0.59) + 0.14), 1e-6);
  EXPECT_EQ(flipAces(1e6f), 1.0f);
  EXPECT_EQ(flipAces(NAN), 0.0f);
  // As written, the rational function is positive for large negative input (see flip.cpp).
  EXPECT_GT(flipAces(-10.0f), 0.9f);
}

struct FlipCase {
  std::string name, reference, test, kind;
  float ppd = 0.0f, start = 0.0f, stop = 0.0f;
  int count = 0;
  double meanFlip = 0.0;
};

std::vector<FlipCase> readCases() {
  std::ifstream in(test::dataDir() / "flip" / "cases.tsv");
  std::string line;
  std::getline(in, line);  // header
  std::vector<FlipCase> cases;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    FlipCase c;
    std::string toneMapper, start, stop, count;
    fields >> c.name >> c.reference >> c.test >> c.kind >> c.ppd >> toneMapper >> start >> stop >> count >>
        c.meanFlip;
    if (c.kind == "HDR") {
      c.start = std::stof(start);
      c.stop = std::stof(stop);
      c.count = std::stoi(count);
    }
    cases.push_back(c);
  }
  return cases;
}

// NVIDIA's FLIP v1.6 means for five image pairs (tests/data/flip/README.md).
TEST(Flip, MatchesTheReferenceImplementationWithinTwoPercent) {
  const std::vector<FlipCase> cases = readCases();
  ASSERT_EQ(cases.size(), 5u);
  for (const FlipCase& c : cases) {
    const std::filesystem::path dir = test::dataDir() / "flip";
    const Image reference = readImage(dir / c.reference, PixelRepair::Keep);
    const Image test = readImage(dir / c.test, PixelRepair::Keep);
    const FlipErrorMap map = c.kind == "LDR" ? ldrFlip(reference, test, c.ppd)
                                             : hdrFlip(reference, test, {c.start, c.stop, c.count}, c.ppd);
    EXPECT_NEAR(meanError(map), c.meanFlip, 0.02 * c.meanFlip) << c.name;
  }
}

TEST(Flip, AutomaticExposureRangeMatchesTheReferenceImplementation) {
  for (const FlipCase& c : readCases()) {
    if (c.kind != "HDR") continue;
    const ExposureRange range = automaticExposureRange(readImage(test::dataDir() / "flip" / c.reference));
    EXPECT_NEAR(range.start, c.start, 1e-3) << c.name;
    EXPECT_NEAR(range.stop, c.stop, 1e-3) << c.name;
    EXPECT_EQ(range.count, c.count) << c.name;
  }
}

// HDR-FLIP scores its exposures in parallel: the same map bit for bit on one thread and on four,
// and the maximum over the exposures scored one at a time (each exposure's LDR-FLIP, as the
// chapter defines it), on HDR images with a few pixels far above the rest.
TEST(Flip, HdrFlipIsTheSameOnAnyNumberOfThreads) {
  Image reference = pattern(64, 48), test = withNoise(pattern(64, 48), 0.1f);
  for (Image* image : {&reference, &test})
    for (int k = 0; k < 40; ++k) image->at((k * 37) % 64, (k * 11) % 48) *= glm::vec4(glm::vec3(200.0f), 1.0f);
  const ExposureRange range = automaticExposureRange(reference);
  ASSERT_GE(range.count, 4);
  const auto onThreads = [&](int threads) {
    tbb::task_arena arena(threads);
    return arena.execute([&] { return hdrFlip(reference, test, range, 67.0f); });
  };
  const FlipErrorMap one = onThreads(1), four = onThreads(4);
  EXPECT_TRUE(one.error == four.error);

  std::vector<float> maximum(reference.pixelCount(), 0.0f);
  for (int e = 0; e < range.count; ++e) {
    const float exposure = range.start + (range.stop - range.start) * e / float(range.count - 1);
    const FlipErrorMap ldr = hdrFlip(reference, test, {exposure, exposure, 1}, 67.0f);
    for (std::size_t i = 0; i < maximum.size(); ++i) maximum[i] = std::max(maximum[i], ldr.error[i]);
  }
  EXPECT_TRUE(four.error == maximum);
  EXPECT_GT(meanError(four), 0.0);
}

}  // namespace
}  // namespace iblkit
