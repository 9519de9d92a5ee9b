#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <ImfRgbaFile.h>
#include <ImfTiledRgbaFile.h>

#include "core/image_io.h"
#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

// A w x h image whose every component differs: value = 1000 * level + 100 * c + 10 * y + x, scaled.
Image numberedImage(int width, int height, float scale = 1.0f, int level = 0) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 4; ++c) image.at(x, y)[c] = scale * float(1000 * level + 100 * c + 10 * y + x);
  return image;
}

TEST(Exr, FloatRgbaRoundTripIsExact) {
  const std::filesystem::path file = test::scratchDir() / "float.exr";
  Image image = numberedImage(5, 3, 0.37f);
  image.at(4, 2) = glm::vec4(1e9f, 1e-9f, 0.0f, 0.5f);  // beyond half's range and precision
  writeExr(file, image, {.pixelType = PixelType::Float, .writeAlpha = true});
  const Image read = readExr(file);
  ASSERT_EQ(read.width(), 5);
  ASSERT_EQ(read.height(), 3);
  EXPECT_EQ(read.pixels(), image.pixels());
  EXPECT_FALSE(std::filesystem::exists(file.string() + ".tmp"));
}

TEST(Exr, HalfRgbRoundTripKeepsHalfPrecisionAndReadsAlphaAsOne) {
  const std::filesystem::path file = test::scratchDir() / "half.exr";
  const Image image = numberedImage(7, 4, 0.013f);
  writeExr(file, image);  // defaults: half, RGB
  const Image read = readExr(file);
  ASSERT_EQ(read.width(), 7);
  ASSERT_EQ(read.height(), 4);
  for (std::size_t i = 0; i < image.pixelCount(); ++i) {
    for (int c = 0; c < 3; ++c)  // half has an 11-bit significand: relative error <= 2^-11
      EXPECT_NEAR(read.pixels()[i][c], image.pixels()[i][c], image.pixels()[i][c] * 0x1p-11f) << i;
    EXPECT_EQ(read.pixels()[i].a, 1.0f);
  }
}

TEST(Exr, HalfClampsToTheLargestHalfInsteadOfInf) {
  const std::filesystem::path file = test::scratchDir() / "bright.exr";
  Image image(2, 1, glm::vec4(1.0f));
  image.at(0, 0) = glm::vec4(1e6f, -1e6f, 65504.0f, 1.0f);
  test::WarningCapture capture;
  writeExr(file, image);
  ASSERT_EQ(capture.lines().size(), 1u);
  EXPECT_EQ(capture.lines()[0],
            file.string() + ": warning: 2 pixel values beyond the largest half (65504) clamped");
  const glm::vec4 read = readExr(file).at(0, 0);
  EXPECT_EQ(read.r, 65504.0f);
  EXPECT_EQ(read.g, 0.0f);  // -65504 in the file, then repaired as negative
  EXPECT_EQ(read.b, 65504.0f);
}

TEST(Exr, EnvmapAndStringAttributesRoundTrip) {
  const std::filesystem::path dir = test::scratchDir();
  const ExrWriteOptions latLong{
      .envmap = EnvmapLayout::LatLong,
      .stringAttributes = {{"iblkit:roughnessPerLevel", "0 0.25 0.5"}, {"owner", "me"}}};
  writeExr(dir / "latlong.exr", numberedImage(8, 4), latLong);
  ExrInfo info;
  readExr(dir / "latlong.exr", &info);
  EXPECT_EQ(info.width, 8);
  EXPECT_EQ(info.height, 4);
  EXPECT_EQ(info.levels, 1);
  EXPECT_EQ(info.envmap, EnvmapLayout::LatLong);
  EXPECT_EQ(info.stringAttributes, latLong.stringAttributes);  // sorted by name, as written here

  writeExr(dir / "cube.exr", numberedImage(2, 12), {.envmap = EnvmapLayout::Cube});
  readExr(dir / "cube.exr", &info);
  EXPECT_EQ(info.envmap, EnvmapLayout::Cube);
  EXPECT_TRUE(info.stringAttributes.empty());

  writeExr(dir / "plain.exr", numberedImage(2, 2));
  readExr(dir / "plain.exr", &info);
  EXPECT_EQ(info.envmap, EnvmapLayout::None);
}

TEST(Exr, MipChainRoundTripsAsTiledRoundDownLevels) {
  const std::filesystem::path file = test::scratchDir() / "mips.exr";
  const std::vector<Image> levels = {numberedImage(8, 4, 0.5f, 0), numberedImage(4, 2, 0.5f, 1),
                                     numberedImage(2, 1, 0.5f, 2), numberedImage(1, 1, 0.5f, 3)};
  writeExrLevels(file, levels, {.pixelType = PixelType::Float, .writeAlpha = true});
  ExrInfo info;
  const std::vector<Image> read = readExrLevels(file, &info);
  EXPECT_EQ(info.levels, 4);
  EXPECT_EQ(info.width, 8);
  EXPECT_EQ(info.height, 4);
  ASSERT_EQ(read.size(), 4u);
  for (std::size_t l = 0; l < read.size(); ++l)
    EXPECT_EQ(read[l].pixels(), levels[l].pixels()) << "level " << l;

  const Image level2 = readExr(file, nullptr, 2);
  EXPECT_EQ(level2.width(), 2);
  EXPECT_EQ(level2.height(), 1);
  EXPECT_EQ(level2.pixels(), levels[2].pixels());
  EXPECT_EQ(test::errorMessage([&] { readExr(file, nullptr, 4); }),
            file.string() + ": has no level 4 (levels 0 to 3)");
}

TEST(Exr, OddSizedMipChainRoundsDown) {
  const std::filesystem::path file = test::scratchDir() / "odd.exr";
  const std::vector<Image> levels = {numberedImage(5, 3), numberedImage(2, 1), numberedImage(1, 1)};
  writeExrLevels(file, levels);
  const std::vector<Image> read = readExrLevels(file);
  ASSERT_EQ(read.size(), 3u);
  EXPECT_EQ(read[1].width(), 2);
  EXPECT_EQ(read[1].height(), 1);
}

TEST(Exr, SingleImageIsOneLevel) {
  const std::filesystem::path file = test::scratchDir() / "single.exr";
  writeExrLevels(file, {numberedImage(4, 4)});
  ExrInfo info;
  EXPECT_EQ(readExrLevels(file, &info).size(), 1u);
  EXPECT_EQ(info.levels, 1);
  EXPECT_EQ(test::errorMessage([&] { readExr(file, nullptr, 1); }),
            file.string() + ": has no level 1 (levels 0 to 0)");
}

TEST(Exr, WriterRejectsWhatItCannotWriteFaithfully) {
  const std::filesystem::path file = test::scratchDir() / "bad.exr";
  EXPECT_EQ(test::errorMessage([&] { writeExr(file, Image()); }),
            file.string() + ": cannot write an empty image");
  EXPECT_EQ(test::errorMessage([&] {
              writeExrLevels(file, {numberedImage(8, 4), numberedImage(4, 2)});
            }),
            file.string() + ": a 8 x 4 mip chain needs 4 levels, got 2");
  EXPECT_EQ(test::errorMessage([&] {
              writeExrLevels(file, {numberedImage(5, 3), numberedImage(3, 2), numberedImage(1, 1)});
            }),
            file.string() + ": mip level 1 is 3 x 2, expected 2 x 1 (ROUND_DOWN)");
  EXPECT_EQ(test::errorMessage([&] { writeExr(file, numberedImage(4, 4), {.envmap = EnvmapLayout::Cube}); }),
            file.string() + ": a cube envmap is six square faces stacked vertically (W x 6W), got 4 x 4");
  Image withNaN = numberedImage(3, 2);
  withNaN.at(2, 1).g = std::nanf("");
  EXPECT_EQ(test::errorMessage([&] { writeExr(file, withNaN); }),
            file.string() + ": cannot write NaN or Inf (level 0, pixel 2, 1)");
  EXPECT_FALSE(std::filesystem::exists(file));
  EXPECT_FALSE(std::filesystem::exists(file.string() + ".tmp"));
}

TEST(Exr, OpenExrErrorsBecomeOneLineErrors) {
  const std::filesystem::path file = test::scratchDir() / "attribute.exr";
  // "compression" is a standard attribute of another type: OpenEXR refuses, we report it.
  EXPECT_EQ(test::errorMessage([&] {
              writeExr(file, numberedImage(2, 2), {.stringAttributes = {{"compression", "x"}}});
            }),
            file.string() +
                ": Cannot assign a value of type \"string\" to image attribute \"compression\" of type "
                "\"compression\".");
  const std::filesystem::path missingDir = test::scratchDir() / "no" / "such" / "dir.exr";
  EXPECT_EQ(test::errorMessage([&] { writeExr(missingDir, numberedImage(2, 2)); }),
            missingDir.string() + ": cannot create a temporary file beside it: No such file or directory");
}

std::vector<char> fileBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Where `attribute` (name, then type name) starts in `bytes`: its 4-byte size follows.
std::size_t attributeAt(const std::vector<char>& bytes, const std::string& nameAndType) {
  const std::string pattern(nameAndType.c_str(), nameAndType.size() + 1);
  const auto at = std::search(bytes.begin(), bytes.end(), pattern.begin(), pattern.end());
  EXPECT_NE(at, bytes.end()) << nameAndType;
  return at == bytes.end() ? 0 : std::size_t(at - bytes.begin());
}

// readExr(file) fails with `expected`, also in a child process limited to 1 GiB of address space,
// where allocating what the header claims (2 GiB) would fail with std::bad_alloc instead. The
// child is skipped under AddressSanitizer, which needs far more address space than that.
void expectRefusedWithinOneGiB(const std::filesystem::path& file, const std::string& expected) {
  EXPECT_EQ(test::errorMessage([&] { readExr(file); }), expected);
#if defined(__SANITIZE_ADDRESS__)
  return;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return;
#endif
#endif
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const auto readWithinOneGiB = [&] {
    const rlim_t oneGiB = rlim_t{1} << 30;
    const rlimit limit{oneGiB, oneGiB};
    setrlimit(RLIMIT_AS, &limit);
    _exit(test::errorMessage([&] { readExr(file); }) == expected ? 0 : 1);
  };
  EXPECT_EXIT(readWithinOneGiB(), testing::ExitedWithCode(0), "") << file;
}

// fuzz/fuzz_exr found both: OpenEXR allocates an attribute of unknown type at the size the header
// claims before reading it, and we allocated the image of any data window up to kMaxImagePixels,
// so a file of a few hundred bytes made us allocate 2 GiB. Both are checked against the file first.
TEST(Exr, AttributeClaimingMoreBytesThanTheFileIsTruncationWithoutAllocatingIt) {
  const std::filesystem::path file = test::scratchDir() / "huge_attribute.exr";
  writeExr(file, numberedImage(4, 2), {.stringAttributes = {{"iblkit:fuzz", "x"}}});
  std::vector<char> bytes = fileBytes(file);
  const std::size_t at = attributeAt(bytes, std::string("iblkit:fuzz") + '\0' + "string");
  std::memcpy(&bytes[at + 12], "fuzzed", 6);  // a type OpenEXR does not know: an opaque attribute
  const std::int32_t claimed = 0x7fffffff;
  std::memcpy(&bytes[at + 19], &claimed, sizeof claimed);
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
  expectRefusedWithinOneGiB(file, file.string() + ": truncated file (unexpected end of data)");
}

// The header is walked as OpenEXR reads it, not by the declared sizes alone: OpenEXR reads a
// channel list up to its empty name whatever its declared size says, so a channel list declaring
// 0 bytes hides the opaque attribute that follows from a walk by declared sizes.
TEST(Exr, OpaqueAttributeAfterAChannelListOfWrongDeclaredSizeIsStillChecked) {
  const std::filesystem::path file = test::scratchDir() / "chlist_out_of_step.exr";
  writeExr(file, numberedImage(4, 2), {.stringAttributes = {{"iblkit:fuzz", "x"}}});
  std::vector<char> bytes = fileBytes(file);
  const std::size_t at = attributeAt(bytes, std::string("iblkit:fuzz") + '\0' + "string");
  std::memcpy(&bytes[at + 12], "fuzzed", 6);
  const std::int32_t claimed = 0x7fffffff;
  std::memcpy(&bytes[at + 19], &claimed, sizeof claimed);
  const std::size_t channels = attributeAt(bytes, std::string("channels") + '\0' + "chlist");
  // Moves the opaque attribute right after the channel list (before the other attributes) ...
  std::vector<char> opaque(bytes.begin() + std::ptrdiff_t(at), bytes.begin() + std::ptrdiff_t(at + 24));
  bytes.erase(bytes.begin() + std::ptrdiff_t(at), bytes.begin() + std::ptrdiff_t(at + 24));
  std::int32_t listBytes = 0;
  std::memcpy(&listBytes, &bytes[channels + 16], sizeof listBytes);
  const std::size_t afterList = channels + 16 + 4 + std::size_t(listBytes);
  bytes.insert(bytes.begin() + std::ptrdiff_t(afterList), opaque.begin(), opaque.end());
  // ... and declares the channel list 0 bytes long: a walk by declared sizes would then read the
  // list's first channel name as the next attribute and lose step.
  const std::int32_t zero = 0;
  std::memcpy(&bytes[channels + 16], &zero, sizeof zero);
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
  expectRefusedWithinOneGiB(file, file.string() + ": truncated file (unexpected end of data)");
}

TEST(Exr, DataWindowLargerThanTheFileCanHoldIsRefusedBeforeAllocating) {
  const std::filesystem::path file = test::scratchDir() / "huge_window.exr";
  writeExr(file, numberedImage(4, 2));  // ZIP-compressed half RGB
  std::vector<char> bytes = fileBytes(file);
  const std::size_t at = attributeAt(bytes, std::string("dataWindow") + '\0' + "box2i");
  const std::int32_t window[4] = {0, 0, (1 << 26) - 1, 1};  // 2^27 pixels, 2 GiB as our RGBA floats
  std::memcpy(&bytes[at + 17 + 4], window, sizeof window);
  // Uncompressed, as in the fuzzer's input (OpenEXR itself limits a compressed line's size).
  bytes[attributeAt(bytes, std::string("compression") + '\0' + "compression") + 24 + 4] = 0;
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
  expectRefusedWithinOneGiB(file, file.string() + ": data window of 67108864 x 2 pixels holds more data than the file's " +
                                      std::to_string(bytes.size()) + " bytes can (truncated or corrupt header)");
}

// A tiled uncompressed file whose one tile declares fewer bytes than its pixels need: OpenEXR 3.1
// copies an uncompressed tile by its pixels' size and so read past the declared data (issue 13's
// short scanline chunk, in a tile). Written by OpenEXR, then the tile's size field is cut.
TEST(Exr, TileShorterThanItsPixelsIsRefused) {
  const std::filesystem::path file = test::scratchDir() / "short_tile.exr";
  {
    std::vector<Imf::Rgba> pixels(16, Imf::Rgba(0.5f, 0.25f, 1.0f, 1.0f));
    Imf::TiledRgbaOutputFile out(file.c_str(), 4, 4, 8, 8, Imf::ONE_LEVEL, Imf::ROUND_DOWN, Imf::WRITE_RGBA, 1.0f,
                                 Imath::V2f(0.0f, 0.0f), 1.0f, Imf::INCREASING_Y, Imf::NO_COMPRESSION);
    out.setFrameBuffer(pixels.data(), 1, 4);
    out.writeTile(0, 0);
  }
  EXPECT_FLOAT_EQ(readExr(file).at(3, 3).g, 0.25f);  // whole, it reads
  std::vector<char> bytes = fileBytes(file);
  // One tile at the end: tx, ty, lx, ly, size and 4 x 4 RGBA halves (128 bytes).
  const std::size_t sizeField = bytes.size() - 128 - 4;
  std::int32_t size = 0;
  std::memcpy(&size, &bytes[sizeField], 4);
  ASSERT_EQ(size, 128);
  size = 4;
  std::memcpy(&bytes[sizeField], &size, 4);
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
  EXPECT_EQ(test::errorMessage([&] { readExr(file); }),
            file.string() + ": tile 0, 0 of level 0 holds 4 bytes, but its pixels need 128 uncompressed "
                            "(corrupt or truncated file?)");
}

// The programs decode with OpenEXR's threads (setExrThreads, cli/program.h): a compressed file
// reads the same pixels as on one thread, and a damaged one fails with the same one-line error.
TEST(Exr, ThreadedDecodingReadsTheSamePixelsAndFailsTheSameWay) {
  const std::filesystem::path file = test::scratchDir() / "piz.exr";
  const int width = 257, height = 131;  // PIZ blocks of 32 lines: 5, the last one partial
  {
    std::vector<Imf::Rgba> pixels;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        pixels.emplace_back(0.01f * float(x), 0.02f * float(y), float((x * 7 + y * 13) % 31), 1.0f);
    Imf::RgbaOutputFile out(file.c_str(), width, height, Imf::WRITE_RGBA, 1.0f, Imath::V2f(0.0f, 0.0f), 1.0f,
                            Imf::INCREASING_Y, Imf::PIZ_COMPRESSION);
    out.setFrameBuffer(pixels.data(), 1, width);
    out.writePixels(height);
  }
  setExrThreads(0);
  const Image oneThread = readExr(file);
  setExrThreads(4);
  const Image threaded = readExr(file);
  ASSERT_EQ(threaded.width(), width);
  EXPECT_TRUE(std::equal(oneThread.pixels().begin(), oneThread.pixels().end(), threaded.pixels().begin()));
  EXPECT_EQ(threaded.at(256, 130).g, float(Imath::half(0.02f * 130.0f)));
  // Cut inside the third block's compressed data.
  std::vector<char> bytes = fileBytes(file);
  bytes.resize(bytes.size() * 3 / 5);
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
  const std::string threadedError = test::errorMessage([&] { readExr(file); });
  setExrThreads(0);
  const std::string oneThreadError = test::errorMessage([&] { readExr(file); });
  EXPECT_EQ(threadedError.rfind(file.string() + ": ", 0), 0u) << threadedError;
  EXPECT_EQ(threadedError, oneThreadError);
}

// Layouts our writer never makes are committed files in tests/data/exr, written once with
// OpenEXR's general interface as uncompressed float channels; their pixel values are listed here.

// luminance_only.exr: 3 x 2, one Y channel: 0.5, 1, 2 / 4, 8, 16.
TEST(Exr, LuminanceOnlyFileReadsAsGrey) {
  const Image read = readExr(test::dataDir() / "exr" / "luminance_only.exr");
  ASSERT_EQ(read.width(), 3);
  ASSERT_EQ(read.height(), 2);
  const float y[] = {0.5f, 1.0f, 2.0f, 4.0f, 8.0f, 16.0f};
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(read.pixels()[i], glm::vec4(glm::vec3(y[i]), 1.0f)) << i;
}

// data_window_10_20.exr: display window (0, 0)-(31, 31), data window (10, 20)-(13, 21), RGB;
// component i of the 4 x 2 x 3 interleaved data has the value i.
TEST(Exr, DataWindowAwayFromTheOriginIsTheImage) {
  ExrInfo info;
  const Image read = readExr(test::dataDir() / "exr" / "data_window_10_20.exr", &info);
  EXPECT_EQ(info.width, 4);
  EXPECT_EQ(info.height, 2);
  ASSERT_EQ(read.width(), 4);
  ASSERT_EQ(read.height(), 2);
  EXPECT_EQ(read.at(0, 0), glm::vec4(0, 1, 2, 1));
  EXPECT_EQ(read.at(1, 0), glm::vec4(3, 4, 5, 1));
  EXPECT_EQ(read.at(3, 1), glm::vec4(21, 22, 23, 1));  // pixel (13, 21) of the file
}

// depth_only.exr: 2 x 1, one Z channel.
TEST(Exr, FileWithoutColourChannelsIsAnError) {
  const std::filesystem::path file = test::dataDir() / "exr" / "depth_only.exr";
  EXPECT_EQ(test::errorMessage([&] { readExr(file); }), file.string() + ": no R, G, B or Y channel");
}

// The fetched maps are DWAB-compressed half RGB lat-long maps, 512 x 256.
TEST(Exr, EveryFetchedMapLoads) {
  const std::filesystem::path hdri = test::assetsDir() / "hdri";
  if (!std::filesystem::is_directory(hdri)) GTEST_SKIP() << "assets not fetched: " << hdri;
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(hdri)) {
    if (entry.path().extension() != ".exr") continue;
    ++count;
    const Image map = readExr(entry.path());
    EXPECT_EQ(map.width(), 512) << entry.path();
    EXPECT_EQ(map.height(), 256) << entry.path();
    const Image::Stats stats = map.stats();
    EXPECT_TRUE(std::isfinite(stats.maxLuminance)) << entry.path();
    EXPECT_GT(stats.maxLuminance, 0.0f) << entry.path();
    EXPECT_GE(std::min({stats.min.x, stats.min.y, stats.min.z}), 0.0f) << entry.path();
  }
  EXPECT_EQ(count, 18);
}

// Compressed, OpenEXR sized its line buffers by the data window when the file was opened (ZIP
// keeps 16 lines: 1.9 GB for this one, found by fuzz/fuzz_exr), before our own check of the image.
TEST(Exr, CompressedDataWindowLargerThanTheFileCanHoldIsRefusedBeforeOpenExrAllocates) {
  const std::filesystem::path file = test::scratchDir() / "huge_zip_window.exr";
  writeExr(file, numberedImage(4, 2));  // ZIP-compressed half RGB
  std::vector<char> bytes = fileBytes(file);
  const std::size_t at = attributeAt(bytes, std::string("dataWindow") + '\0' + "box2i");
  const std::int32_t window[4] = {0, 0, 20000630, 2};
  std::memcpy(&bytes[at + 17 + 4], window, sizeof window);
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
  expectRefusedWithinOneGiB(file, file.string() + ": data window of 20000631 x 3 pixels holds more data than the file's " +
                                      std::to_string(bytes.size()) + " bytes can (truncated or corrupt header)");
}

}  // namespace
}  // namespace iblkit
