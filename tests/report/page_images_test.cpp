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
