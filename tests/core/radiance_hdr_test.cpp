#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "core/image_io.h"
#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

// Writes a .hdr file from its header text (up to and including the resolution line) and pixel bytes.
std::filesystem::path writeHdr(const std::filesystem::path& file, const std::string& header,
                               const std::vector<int>& bytes) {
  std::ofstream out(file, std::ios::binary);
  out << header;
  for (int byte : bytes) out.put(static_cast<char>(byte));
  return file;
}

const std::string kHeader = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n";

// RGBE decodes to (mantissa + 0.5) * 2^(exponent - 136), as Radiance's colr_color does.
float rgbe(int mantissa, int exponent) { return std::ldexp(mantissa + 0.5f, exponent - 136); }

TEST(RadianceHdr, FlatScanlines) {
  const std::filesystem::path dir = test::scratchDir();
  // 2 x 2, narrower than 8 so always flat; the "#?RGBE" signature, EXPOSURE and comments are
  // accepted (EXPOSURE is ignored: values are read as stored).
  const auto file =
      writeHdr(dir / "flat.hdr", "#?RGBE\n# made by hand\nEXPOSURE=4\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 2\n",
               {128, 64, 32, 129, 200, 100, 50, 131, 0, 0, 0, 0, 255, 1, 0, 140});
  const Image image = readRadianceHdr(file);
  ASSERT_EQ(image.width(), 2);
  ASSERT_EQ(image.height(), 2);
  EXPECT_EQ(image.at(0, 0), glm::vec4(1.00390625f, 0.50390625f, 0.25390625f, 1.0f));
  EXPECT_EQ(image.at(1, 0), glm::vec4(6.265625f, 3.140625f, 1.578125f, 1.0f));
  EXPECT_EQ(image.at(0, 1), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));  // exponent 0 is black
  EXPECT_EQ(image.at(1, 1), glm::vec4(4088.0f, rgbe(1, 140), rgbe(0, 140), 1.0f));
}

TEST(RadianceHdr, FlatScanlinesWideEnoughForRunLengthEncoding) {
  const std::filesystem::path dir = test::scratchDir();
  // Width 8 could be run-length encoded, but a scanline not starting with 2, 2 is flat.
  std::vector<int> bytes;
  for (int x = 0; x < 8; ++x) bytes.insert(bytes.end(), {128 + x, 128, 128, 129});
  const Image image = readRadianceHdr(writeHdr(dir / "wide_flat.hdr", kHeader + "-Y 1 +X 8\n", bytes));
  ASSERT_EQ(image.width(), 8);
  for (int x = 0; x < 8; ++x) EXPECT_EQ(image.at(x, 0).r, rgbe(128 + x, 129)) << x;
}

TEST(RadianceHdr, RunLengthEncodedScanlines) {
  const std::filesystem::path dir = test::scratchDir();
  // 8 x 2. Each scanline: 2, 2, width (high, low), then R, G, B, E each as runs (128 + n, byte)
  // and literal spans (n, n bytes).
  const std::vector<int> bytes = {
      2,   2,   0,   8,                             // scanline 0
      136, 128,                                     //   R: 8 x 128
      8,   0,   16,  32,  48,  64,  80,  96,  112,  //   G: 8 literals
      131, 10,  5,   1,   2,   3,   4,   5,         //   B: 3 x 10, then 5 literals
      136, 129,                                     //   E: 8 x 129
      2,   2,   0,   8,                             // scanline 1
      8,   128, 129, 130, 131, 132, 133, 134, 135,  //   R: 8 literals
      136, 255,                                     //   G: 8 x 255
      136, 0,                                       //   B: 8 x 0
      132, 130, 132, 0,                             //   E: 4 x 130, 4 x 0 (black)
  };
  const Image image = readRadianceHdr(writeHdr(dir / "rle.hdr", kHeader + "-Y 2 +X 8\n", bytes));
  ASSERT_EQ(image.width(), 8);
  ASSERT_EQ(image.height(), 2);
  for (int x = 0; x < 8; ++x) {
    EXPECT_EQ(image.at(x, 0),
              glm::vec4(rgbe(128, 129), rgbe(16 * x, 129), rgbe(x < 3 ? 10 : x - 2, 129), 1.0f))
        << "x = " << x;
    const glm::vec4 expected = x < 4 ? glm::vec4(rgbe(128 + x, 130), rgbe(255, 130), rgbe(0, 130), 1.0f)
                                     : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    EXPECT_EQ(image.at(x, 1), expected) << "x = " << x;
  }
}

TEST(RadianceHdr, BadFilesGiveClearErrors) {
  const std::filesystem::path dir = test::scratchDir();
  const auto expectError = [](const std::filesystem::path& file, const std::string& problem) {
    EXPECT_EQ(test::errorMessage([&] { readRadianceHdr(file); }), file.string() + ": " + problem);
  };
  const std::vector<int> onePixel = {128, 128, 128, 129};
  expectError(writeHdr(dir / "a.hdr", "RADIANCE\n\n-Y 1 +X 1\n", onePixel),
              "not a Radiance HDR file (no \"#?RADIANCE\" signature)");
  expectError(writeHdr(dir / "b.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n", onePixel),
              "unsupported FORMAT=32-bit_rle_xyze (only 32-bit_rle_rgbe)");
  expectError(writeHdr(dir / "c.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n", {}),
              "truncated header (no blank line and resolution string)");
  expectError(writeHdr(dir / "d.hdr", kHeader + "+Y 1 +X 1\n", onePixel),
              "unsupported orientation \"+Y 1 +X 1\" (only \"-Y H +X W\")");
  expectError(writeHdr(dir / "e.hdr", kHeader + "-Y 1 +X\n", onePixel), "bad resolution string \"-Y 1 +X\"");
  expectError(writeHdr(dir / "f.hdr", kHeader + "-Y 1 +X -3\n", onePixel),
              "bad resolution string \"-Y 1 +X -3\"");
  expectError(writeHdr(dir / "g.hdr", kHeader + "-Y 0 +X 4\n", onePixel), "zero-size image (4 x 0)");
  expectError(writeHdr(dir / "h.hdr", kHeader + "-Y 4 +X 2\n", {128, 128, 128, 129, 128, 128, 128, 129}),
              "truncated pixel data: 2 x 4 pixels need at least 32 bytes, the file has 8");
  expectError(writeHdr(dir / "i.hdr", kHeader + "-Y 1 +X 2\n", {128, 128, 128, 129, 1, 1, 1, 3}),
              "scanline 0 uses the old run-length encoding (not supported)");
  expectError(
      writeHdr(dir / "j.hdr", kHeader + "-Y 1 +X 8\n", {2, 2, 0, 9, 136, 1, 136, 1, 136, 1, 136, 129}),
      "corrupt scanline 0: run-length scanline of width 9 in an image of width 8");
  expectError(
      writeHdr(dir / "k.hdr", kHeader + "-Y 1 +X 8\n", {2, 2, 0, 8, 137, 1, 136, 1, 136, 1, 136, 129}),
      "corrupt scanline 0: run of 9 at pixel 0 of 8");
  expectError(
      writeHdr(dir / "l.hdr", kHeader + "-Y 1 +X 8\n", {2, 2, 0, 8, 132, 1, 0, 136, 1, 136, 1, 136, 129}),
      "corrupt scanline 0: run of 0 at pixel 4 of 8");
  expectError(writeHdr(dir / "m.hdr", kHeader + "-Y 1 +X 8\n",
                       {2, 2, 0, 8, 8, 1, 2, 3, 4, 5, 6, 7, 8, 136, 1, 136, 1, 8, 129, 129}),
              "truncated pixel data (scanline 0 is incomplete)");
}

}  // namespace
}  // namespace iblkit
