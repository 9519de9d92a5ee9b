#include "report/page_images.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/base64.h"
#include "core/error.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

TEST(PageImages, RgbeKeepsEachChannelWithinItsEightBitMantissa) {
  Image image(4, 2);
  const glm::vec3 values[] = {{0.18f, 0.5f, 0.02f}, {1.0f, 1.0f, 1.0f}, {1e4f, 3.0f, 0.0f}, {0.0f, 0.0f, 0.0f},
                              {1e-6f, 2e-6f, 3e-6f}, {-1.0f, 0.5f, NAN}, {7.25f, 0.0f, 65504.0f}, {1e-3f, 1e-3f, 1e-3f}};
  for (int i = 0; i < 8; ++i) image.pixels()[std::size_t(i)] = glm::vec4(values[i], 1.0f);
  const std::vector<std::uint8_t> rgbe = encodeRgbe(image);
  ASSERT_EQ(rgbe.size(), 32u);
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 decoded = decodeRgbe(&rgbe[std::size_t(4 * i)]);
    const float largest = std::max({values[i].r, values[i].g, values[i].b, 0.0f});
    for (int c = 0; c < 3; ++c) {
      const float expected = std::isfinite(values[i][c]) && values[i][c] > 0.0f ? values[i][c] : 0.0f;
      // One step of the shared mantissa is largest / 128 at most; the decoder takes its middle.
      EXPECT_NEAR(decoded[c], expected, largest / 256.0f + 1e-30f) << "pixel " << i << " channel " << c;
    }
  }
  EXPECT_EQ(rgbe[12], 0);  // black is all zero
  EXPECT_EQ(rgbe[15], 0);
}

TEST(PageImages, ZlibRoundTrips) {
  std::vector<std::uint8_t> bytes;
  for (int i = 0; i < 5000; ++i) bytes.push_back(std::uint8_t((i * 7) % 13));
  EXPECT_EQ(zlibDecompress(zlibCompress(bytes)), bytes);
  EXPECT_LT(zlibCompress(bytes).size(), bytes.size() / 4);
}

TEST(PageImages, TheScriptNamesEveryImageAndRefusesMismatchedSizes) {
  Image reference(3, 2, glm::vec4(0.5f)), frame(3, 2, glm::vec4(2.0f)), small(2, 2);
  const auto file = test::scratchDir() / "case-linear.js";
  writeCaseImagesScript(file, "bunny-sky", {{"reference", &reference}, {"sh", &frame}});
  std::ifstream stream(file);
  std::stringstream text;
  text << stream.rdbuf();
  EXPECT_EQ(text.str().rfind("iblkitCaseImages(\"bunny-sky\", {\"width\": 3, \"height\": 2,", 0), 0u);
  EXPECT_NE(text.str().find("\"sh\": \"" + base64(zlibCompress(encodeRgbe(frame))) + "\""), std::string::npos);
  const auto refused = test::scratchDir() / "refused-linear.js";
  EXPECT_THROW(writeCaseImagesScript(refused, "x", {{"reference", &reference}, {"sh", &small}}), Error);
  EXPECT_FALSE(std::filesystem::exists(refused));
}

}  // namespace
}  // namespace iblkit

namespace iblkit {
namespace {

TEST(PageImages, TheScriptReadsBackInOrderWithinRgbePrecision) {
  Image reference(4, 3), frame(4, 3, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) reference.at(x, y) = glm::vec4(0.01f * float(1 + x), 3.0f * float(1 + y), 250.0f, 1.0f);
  const auto file = test::scratchDir() / "case-linear.js";
  // Not in alphabetical order: the reader keeps the written order.
  writeCaseImagesScript(file, "bunny-sky", {{"reference", &reference}, {"full", &frame}, {"sh", &frame}});
  const CaseImagesScript script = readCaseImagesScript(file);
  EXPECT_EQ(script.caseName, "bunny-sky");
  ASSERT_EQ(script.images.size(), 3u);
  EXPECT_EQ(script.images[0].first, "reference");
  EXPECT_EQ(script.images[1].first, "full");
  EXPECT_EQ(script.images[2].first, "sh");
  const Image& read = script.images[0].second;
  ASSERT_EQ(read.width(), 4);
  ASSERT_EQ(read.height(), 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) {
      // RGBE keeps 8 bits of mantissa against the pixel's largest channel (250 here).
      const glm::vec4 a = reference.at(x, y), b = read.at(x, y);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(b[c], a[c], 250.0f / 128.0f) << x << "," << y << "," << c;
      EXPECT_NEAR(b.g, a.g, 2.0f) << "row " << y;
      EXPECT_EQ(b.a, 1.0f);
    }
  EXPECT_EQ(script.images[1].second.at(0, 0), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
}

TEST(PageImages, AScriptThatDoesNotReadIsNamed) {
  const auto dir = test::scratchDir();
  auto problem = [](const std::filesystem::path& file) {
    try {
      readCaseImagesScript(file);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(problem(dir / "none.js"), (dir / "none.js").string() + ": cannot open: No such file or directory");
  std::ofstream(dir / "other.js") << "console.log(1);\n";
  EXPECT_EQ(problem(dir / "other.js").rfind((dir / "other.js").string() + ": not a report's linear images script", 0), 0u);
  std::ofstream(dir / "short.js") << "iblkitCaseImages(\"a-b\", {\"width\": 4, \"height\": 4, \"images\": {\"reference\": \""
                                  << base64(zlibCompress(std::vector<std::uint8_t>(12, 1))) << "\"}});\n";
  EXPECT_EQ(problem(dir / "short.js"), (dir / "short.js").string() + ": image 'reference' has 3 pixels, not 4x4");
  std::ofstream(dir / "corrupt.js") << "iblkitCaseImages(\"a-b\", {\"width\": 1, \"height\": 1, \"images\": {\"reference\": \"Zm9v\"}});\n";
  EXPECT_EQ(problem(dir / "corrupt.js"), (dir / "corrupt.js").string() + ": zlib: corrupt data");
  // A bomb: 64 MiB of zeros in 64 KiB of text, for a 1 x 1 image; inflating stops at 4 bytes.
  std::ofstream(dir / "bomb.js") << "iblkitCaseImages(\"a-b\", {\"width\": 1, \"height\": 1, \"images\": {\"reference\": \""
                                 << base64(zlibCompress(std::vector<std::uint8_t>(std::size_t(64) << 20, 0))) << "\"}});\n";
  EXPECT_EQ(problem(dir / "bomb.js"),
            (dir / "bomb.js").string() + ": zlib: the data inflates to more than the 4 bytes expected");
  std::ofstream(dir / "huge.js") << "iblkitCaseImages(\"a-b\", {\"width\": 100000, \"height\": 100000, \"images\": {}});\n";
  EXPECT_EQ(problem(dir / "huge.js"), (dir / "huge.js").string() + ": bad size 100000x100000 (each side 1..16384)");
}

}  // namespace
}  // namespace iblkit
