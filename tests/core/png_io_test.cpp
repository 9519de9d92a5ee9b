#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/image_io.h"
#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

// A ramp over [0, 4) in x with different slopes per channel, alpha falling from 1 to 0.
Image ramp(int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float t = float(x + y * width) / float(width * height);
      image.at(x, y) = glm::vec4(4.0f * t, 2.0f * t, t * t, 1.0f - t);
    }
  return image;
}

TEST(Png, RoundTripMatchesTheToneMappedImageWithinOneCode) {
  const std::filesystem::path dir = test::scratchDir();
  const Image image = ramp(16, 8);
  for (const ToneMapping toneMapping :
       {ToneMapping{}, ToneMapping{1.5f, ToneCurve::Reinhard}, ToneMapping{-2.0f, ToneCurve::Clamp}}) {
    const std::filesystem::path file = dir / "ramp.png";
    writePng(file, image, toneMapping);
    EXPECT_FALSE(std::filesystem::exists(file.string() + ".tmp"));
    const Image read = readPng(file);
    ASSERT_EQ(read.width(), 16);
    ASSERT_EQ(read.height(), 8);
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 16; ++x) {
        const glm::vec3 expected = toneMap(glm::vec3(image.at(x, y)), toneMapping);
        for (int c = 0; c < 3; ++c)  // the reader decodes sRGB: encode again to compare display values
          ASSERT_NEAR(srgbEncode(read.at(x, y)[c]), expected[c], 1.0f / 255.0f)
              << x << ", " << y << " c" << c;
        ASSERT_EQ(read.at(x, y).a, 1.0f);  // no alpha written
      }
  }
}

TEST(Png, AlphaIsWrittenLinearly) {
  const std::filesystem::path file = test::scratchDir() / "alpha.png";
  Image image(2, 1, glm::vec4(0.0f, 0.0f, 0.0f, 0.5f));
  image.at(1, 0).a = 2.0f;  // clamped
  writePng(file, image, {}, true);
  const Image read = readPng(file);
  EXPECT_EQ(read.at(0, 0).a, 128.0f / 255.0f);
  EXPECT_EQ(read.at(1, 0).a, 1.0f);
}

TEST(Png, DecodesSrgbCodesExactly) {
  // Codes 0, 1 and 255 land on the ends and the linear segment of the sRGB curve.
  const std::filesystem::path file = test::scratchDir() / "codes.png";
  Image image(3, 1);
  image.at(0, 0) = glm::vec4(0.0f);
  image.at(1, 0) = glm::vec4(1.0f / 255.0f / 12.92f);  // encodes to exactly code 1
  image.at(2, 0) = glm::vec4(1.0f);
  writePng(file, image, {0.0f, ToneCurve::Clamp});
  const Image read = readPng(file);
  EXPECT_EQ(read.at(0, 0).r, 0.0f);
  EXPECT_FLOAT_EQ(read.at(1, 0).g, 1.0f / 255.0f / 12.92f);
  EXPECT_EQ(read.at(2, 0).b, 1.0f);
}

TEST(Png, BadFilesGiveClearErrors) {
  const std::filesystem::path dir = test::scratchDir();
  const std::filesystem::path text = dir / "text.png", empty = dir / "out.png";
  std::ofstream(text) << "not a png at all";
  EXPECT_EQ(test::errorMessage([&] { readPng(text); }), text.string() + ": not a PNG file (bad signature)");
  EXPECT_EQ(test::errorMessage([&] { writePng(empty, Image()); }),
            empty.string() + ": cannot write an empty image");
  const std::filesystem::path noDir = dir / "missing" / "out.png";
  EXPECT_EQ(test::errorMessage([&] { writePng(noDir, Image(1, 1)); }),
            noDir.string() + ": cannot create a temporary file beside it: No such file or directory");
}

// fuzz/fuzz_png found it: stb_image names an unknown chunk by its four raw bytes, which made a
// message of several lines when they were line breaks.
TEST(Png, AnUnknownChunkOfControlCharactersGivesAOneLineError) {
  const std::filesystem::path file = test::scratchDir() / "control_chunk.png";
  const char ihdr[] = "\0\0\0\x0dIHDR\0\0\0\x02\0\0\0\x01\x08\x02\0\0\0\0\0\0\0";  // 2 x 1 RGB, CRC not checked
  const char chunk[] = "\0\0\0\0\n\x1aXY\0\0\0\0";  // a critical chunk of type "\n\x1aXY", empty
  std::ofstream out(file, std::ios::binary);
  out.write("\x89PNG\r\n\x1a\n", 8);
  out.write(ihdr, sizeof ihdr - 1);
  out.write(chunk, sizeof chunk - 1);
  out.close();
  EXPECT_EQ(test::errorMessage([&] { readPng(file); }), file.string() + ": cannot decode PNG: ??XY PNG chunk not known");
}

}  // namespace
}  // namespace iblkit
