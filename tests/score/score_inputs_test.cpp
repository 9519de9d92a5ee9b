#include "score/score_inputs.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/image_io.h"
#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

TEST(ScoreInputs, RefusesImagesOfDifferentSizes) {
  const std::filesystem::path dir = test::scratchDir();
  writeExr(dir / "ref.exr", Image(128, 64));
  writeExr(dir / "test.exr", Image(64, 32));
  EXPECT_EQ(test::errorMessage([&] { loadScoreInputs(dir / "ref.exr", dir / "test.exr"); }),
            (dir / "test.exr").string() + ": image is 64x32, reference is 128x64");
}

// nan_pixels.exr: 4 x 2 with 3 NaN, 1 Inf and 2 negative values (tests/core/image_io_test.cpp).
TEST(ScoreInputs, NanAndInfiniteValuesOfTheTestAreAFailure) {
  const std::filesystem::path dir = test::scratchDir();
  writeExr(dir / "ref.exr", Image(4, 2));
  const std::filesystem::path bad = test::dataDir() / "bad" / "nan_pixels.exr";
  EXPECT_EQ(test::errorMessage([&] { loadScoreInputs(dir / "ref.exr", bad); }),
            bad.string() + ": 4 NaN or infinite pixel values");
}

TEST(ScoreInputs, ReportsMissingFiles) {
  const std::filesystem::path dir = test::scratchDir();
  writeExr(dir / "ref.exr", Image(4, 4));
  EXPECT_EQ(test::errorMessage([&] {
              loadScoreInputs(dir / "ref.exr", dir / "missing.exr");
            }).rfind((dir / "missing.exr").string() + ": ", 0),
            0u);
}

TEST(ScoreInputs, RefusesComparingLdrWithHdr) {
  const std::filesystem::path dir = test::scratchDir();
  writeExr(dir / "ref.exr", Image(4, 4));
  writePng(dir / "test.png", Image(4, 4));
  EXPECT_EQ(test::errorMessage([&] { loadScoreInputs(dir / "ref.exr", dir / "test.png"); }),
            (dir / "test.png").string() + ": cannot compare an LDR (.png) image with an HDR image");
}

TEST(ScoreInputs, MaskComesFromAMaskImageOrTheTestAlpha) {
  const std::filesystem::path dir = test::scratchDir();
  writePng(dir / "ref.png", Image(2, 1));
  Image test(2, 1);
  test.at(1, 0).a = 0.0f;
  writePng(dir / "test.png", test, {}, true);
  ScoreInputs inputs = loadScoreInputs(dir / "ref.png", dir / "test.png");
  EXPECT_FALSE(inputs.highDynamicRange);
  EXPECT_EQ(inputs.mask, (std::vector<std::uint8_t>{1, 0}));

  Image mask(2, 1, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  mask.at(1, 0) = glm::vec4(1.0f);  // luminance 1: scored
  writePng(dir / "mask.png", mask, ToneMapping{0.0f, ToneCurve::Clamp});
  inputs = loadScoreInputs(dir / "ref.png", dir / "test.png", dir / "mask.png");
  EXPECT_EQ(inputs.mask, (std::vector<std::uint8_t>{0, 1}));

  writePng(dir / "empty.png", Image(2, 1), ToneMapping{0.0f, ToneCurve::Clamp});
  EXPECT_EQ(
      test::errorMessage([&] { loadScoreInputs(dir / "ref.png", dir / "test.png", dir / "empty.png"); }),
      (dir / "empty.png").string() + ": the mask scores no pixel");
  writePng(dir / "small.png", Image(1, 1), ToneMapping{0.0f, ToneCurve::Clamp});
  EXPECT_EQ(
      test::errorMessage([&] { loadScoreInputs(dir / "ref.png", dir / "test.png", dir / "small.png"); }),
      (dir / "small.png").string() + ": mask is 1x1, images are 2x1");
}

}  // namespace
}  // namespace iblkit
