#include "core/image_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

TEST(ReadImage, DispatchesOnTheExtensionIgnoringCase) {
  const std::filesystem::path dir = test::scratchDir();
  Image image(2, 1, glm::vec4(0.25f, 0.5f, 1.0f, 1.0f));
  writeExr(dir / "a.EXR", image);
  EXPECT_EQ(readImage(dir / "a.EXR").pixels(), image.pixels());
  writePng(dir / "a.Png", image, {0.0f, ToneCurve::Clamp});
  EXPECT_EQ(readImage(dir / "a.Png").at(1, 0).b, 1.0f);
  const std::filesystem::path tga = dir / "a.tga";
  EXPECT_EQ(test::errorMessage([&] { readImage(tga); }),
            tga.string() + ": unknown image format \".tga\" (expected .exr, .hdr, .pic or .png)");
}

TEST(RepairPixels, SetsBadComponentsToZeroWithOneWarning) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  std::vector<Image> levels = {Image(2, 1), Image(1, 1)};
  levels[0].at(0, 0) = glm::vec4(nan, -1.0f, 2.0f, 1.0f);
  levels[0].at(1, 0) = glm::vec4(-inf, 0.5f, nan, -0.0f);
  levels[1].at(0, 0) = glm::vec4(inf, 3.0f, -2.0f, nan);
  test::WarningCapture capture;
  const PixelRepairCounts counts = repairPixels("f.exr", levels);
  EXPECT_EQ(counts.nan, 3u);
  EXPECT_EQ(counts.inf, 2u);  // -Inf counts as Inf
  EXPECT_EQ(counts.negative, 2u);
  EXPECT_EQ(capture.lines(),
            std::vector<std::string>{"f.exr: warning: 3 NaN, 2 Inf and 2 negative pixel values set to 0"});
  EXPECT_EQ(levels[0].at(0, 0), glm::vec4(0.0f, 0.0f, 2.0f, 1.0f));
  EXPECT_EQ(levels[0].at(1, 0), glm::vec4(0.0f, 0.5f, 0.0f, 0.0f));
  EXPECT_EQ(levels[1].at(0, 0), glm::vec4(0.0f, 3.0f, 0.0f, 0.0f));
}

TEST(RepairPixels, MessageListsOnlyWhatWasFound) {
  test::WarningCapture capture;
  Image clean(2, 2, glm::vec4(1.0f));
  repairPixels("clean.exr", {&clean, 1});
  EXPECT_TRUE(capture.lines().empty());
  Image one(1, 1, glm::vec4(1.0f, -1.0f, 1.0f, 1.0f));
  repairPixels("one.exr", {&one, 1});
  Image two(
      1, 1,
      glm::vec4(std::numeric_limits<float>::quiet_NaN(), 1.0f, std::numeric_limits<float>::infinity(), 1.0f));
  repairPixels("two.exr", {&two, 1});
  EXPECT_EQ(capture.lines(),
            (std::vector<std::string>{"one.exr: warning: 1 negative pixel value set to 0",
                                      "two.exr: warning: 1 NaN and 1 Inf pixel values set to 0"}));
}

TEST(CheckImageSize, RejectsEmptyAndHugeImages) {
  EXPECT_EQ(test::errorMessage([] { checkImageSize("a.hdr", 0, 5); }), "a.hdr: zero-size image (0 x 5)");
  EXPECT_EQ(test::errorMessage([] { checkImageSize("a.hdr", 70000, 70000); }),
            "a.hdr: image too large (70000 x 70000, more than 268435456 pixels)");
  EXPECT_EQ(test::errorMessage([] { checkImageSize("a.hdr", 16384, 16384); }), "(no error)");
}

// The committed corpus of broken files (tests/data/bad), made once by hand:
//   truncated.exr     the first half (3000 bytes) of a 32 x 32 half RGB ZIP file written by writeExr
//   garbage.exr, garbage.hdr   300 pseudo-random bytes each (Python random.Random(7))
//   empty.exr         0 bytes
//   truncated_rle.hdr a 16 x 4 run-length encoded file (27 bytes per scanline) cut after 64 bytes
//                     of pixel data, in the middle of scanline 2
//   truncated.png     the first half (1586 bytes) of a 32 x 32 RGB PNG written by writePng
TEST(BadImageCorpus, EachFileGivesItsMessage) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"truncated.exr", "truncated file (unexpected end of data)"},
      {"garbage.exr", "not an OpenEXR file (bad magic number)"},
      {"empty.exr", "empty file (0 bytes)"},
      {"truncated_rle.hdr", "truncated pixel data (scanline 2 is incomplete)"},
      {"garbage.hdr", "not a Radiance HDR file (no \"#?RADIANCE\" signature)"},
      {"truncated.png", "truncated file (unexpected end of data)"},
      {"missing.exr", "cannot open: No such file or directory"},
  };
  for (const auto& [name, problem] : cases) {
    const std::filesystem::path file = test::dataDir() / "bad" / name;
    EXPECT_EQ(test::errorMessage([&] { readImage(file); }), file.string() + ": " + problem);
  }
}

// nan_pixels.exr: 4 x 2 float RGB (no compression) written with OpenEXR directly, row 0 =
// (NaN, 1, 1) (1, NaN, NaN) (+Inf, 0.5, 0.5) (-1, 0.25, -0.5), row 1 = (1, 1, 1) ... (4, 4, 4).
TEST(BadImageCorpus, NanPixelsAreRepairedWithOneWarning) {
  const std::filesystem::path file = test::dataDir() / "bad" / "nan_pixels.exr";
  test::WarningCapture capture;
  const Image image = readImage(file);
  EXPECT_EQ(capture.lines(),
            std::vector<std::string>{file.string() +
                                     ": warning: 3 NaN, 1 Inf and 2 negative pixel values set to 0"});
  ASSERT_EQ(image.width(), 4);
  ASSERT_EQ(image.height(), 2);
  EXPECT_EQ(image.at(0, 0), glm::vec4(0.0f, 1.0f, 1.0f, 1.0f));
  EXPECT_EQ(image.at(1, 0), glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
  EXPECT_EQ(image.at(2, 0), glm::vec4(0.0f, 0.5f, 0.5f, 1.0f));
  EXPECT_EQ(image.at(3, 0), glm::vec4(0.0f, 0.25f, 0.0f, 1.0f));
  EXPECT_EQ(image.at(3, 1), glm::vec4(4.0f, 4.0f, 4.0f, 1.0f));
}

TEST(BadImageCorpus, KeepReadsInvalidValuesAsStoredWithoutWarning) {
  const std::filesystem::path file = test::dataDir() / "bad" / "nan_pixels.exr";
  test::WarningCapture capture;
  const Image image = readImage(file, PixelRepair::Keep);
  EXPECT_TRUE(capture.lines().empty());
  EXPECT_TRUE(std::isnan(image.at(0, 0).r));
  EXPECT_EQ(image.at(3, 0).r, -1.0f);
  const PixelRepairCounts counts = countInvalidPixels(image);
  EXPECT_EQ(counts.nan, 3u);
  EXPECT_EQ(counts.inf, 1u);
  EXPECT_EQ(counts.negative, 2u);
}

}  // namespace
}  // namespace iblkit
