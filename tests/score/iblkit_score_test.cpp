// End-to-end runs of the built iblkit-score program.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "core/image_io.h"
#include "support/test_paths.h"
#include "support/usage_error_check.h"

namespace iblkit {
namespace {

// Single-quoted for the shell (built by appending: GCC 12 warns falsely on "'" + string).
std::string quoted(const std::filesystem::path& path) {
  std::string text(1, '\'');
  text += path.string();
  text += '\'';
  return text;
}

TEST(IblkitScore, PrintsOneLineForIdenticalImages) {
  const std::filesystem::path dir = test::dataDir() / "flip";
  std::string output;
  const int status = test::runCommand((test::binDir() / "iblkit-score").string() + " " +
                                          quoted(dir / "ldr-noise-park.ref.png") + " " +
                                          quoted(dir / "ldr-noise-park.ref.png"),
                                      &output);
  EXPECT_EQ(status, 0) << output;
  EXPECT_EQ(output, "relMSE 0  MSE 0  PSNR inf dB  SSIM 1.0000  FLIP 0.0000 (LDR)\n");
}

TEST(IblkitScore, WritesJsonAndAHeatMap) {
  const std::filesystem::path dir = test::dataDir() / "flip", heatMap = test::scratchDir() / "heat.png";
  std::string output;
  const int status = test::runCommand((test::binDir() / "iblkit-score").string() + " " +
                                          quoted(dir / "hdr-blur-lobby.ref.exr") + " " +
                                          quoted(dir / "hdr-blur-lobby.test.exr") +
                                          " --json --metric flip --exposure-range -5.7873 2.0654 --heatmap " +
                                          quoted(heatMap) + " 2>/dev/null",
                                      &output);
  ASSERT_EQ(status, 0) << output;
  const nlohmann::json result = nlohmann::json::parse(output);
  EXPECT_NEAR(result["flip"].get<double>(), 0.060273, 0.02 * 0.060273);
  EXPECT_EQ(result["flip_kind"], "HDR");
  EXPECT_EQ(result["flip_exposures"]["count"], 8);
  EXPECT_FALSE(result.contains("mse"));
  EXPECT_EQ(result["scored_pixels"], 256 * 192);
  const Image read = readPng(heatMap);
  EXPECT_EQ(read.width(), 256);
  EXPECT_EQ(read.height(), 192 + 2 * 12);
}

TEST(IblkitScore, BadInputIsOneLineAndNonZeroExit) {
  const std::filesystem::path dir = test::scratchDir();
  writeExr(dir / "ref.exr", Image(128, 64));
  writeExr(dir / "test.exr", Image(64, 32));
  std::string output;
  EXPECT_EQ(test::runCommand((test::binDir() / "iblkit-score").string() + " " + quoted(dir / "ref.exr") +
                                 " " + quoted(dir / "test.exr"),
                             &output),
            1);
  EXPECT_EQ(output,
            "iblkit-score: " + (dir / "test.exr").string() + ": image is 64x32, reference is 128x64\n");
  const std::filesystem::path bad = test::dataDir() / "bad" / "nan_pixels.exr";
  writeExr(dir / "small.exr", Image(4, 2));
  EXPECT_EQ(test::runCommand((test::binDir() / "iblkit-score").string() + " " + quoted(dir / "small.exr") +
                                 " " + quoted(bad),
                             &output),
            1);
  EXPECT_EQ(output, "iblkit-score: " + bad.string() + ": 4 NaN or infinite pixel values\n");
}

// Every program's command-line errors: one line naming the program, status 2 (cli/program.h).
TEST(IblkitScore, ABadOptionIsOneLineAndStatusTwo) {
  const std::filesystem::path image = test::dataDir() / "flip" / "ldr-noise-park.ref.png";
  const std::string score =
      (test::binDir() / "iblkit-score").string() + " " + quoted(image) + " " + quoted(image);
  test::expectUsageError(score + " --no-such-option",
                         "iblkit-score: The following argument was not expected: --no-such-option");
  test::expectUsageError(
      score + " --metric lpips",
      "iblkit-score: --metric: unknown metric 'lpips' (expected one of mse, relmse, psnr, ssim, flip)");
}

}  // namespace
}  // namespace iblkit
