#include "core/texture_image.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "core/error.h"
#include "support/texture_files.h"

namespace iblkit {
namespace {

// The message decodeTextureImage throws, after "img.glb: image 0: ".
std::string decodeError(std::vector<std::uint8_t> bytes) {
  TextureImage image;
  try {
    decodeTextureImage(image, std::move(bytes), "img.glb", "image 0");
  } catch (const Error& e) {
    const std::string message = e.what();
    const std::string prefix = "img.glb: image 0: ";
    EXPECT_EQ(message.rfind(prefix, 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message.substr(prefix.size());
  }
  return "(no error)";
}

TextureImage decode(std::vector<std::uint8_t> bytes) {
  TextureImage image;
  decodeTextureImage(image, std::move(bytes), "img.glb", "image 0");
  return image;
}

TEST(TextureImage, SniffsTheSignature) {
  EXPECT_EQ(sniffImageMimeType(test::encodePng(2, 2, test::quadPixels())), "image/png");
  EXPECT_EQ(sniffImageMimeType(test::encodeJpeg(2, 2, test::quadPixels())), "image/jpeg");
  EXPECT_EQ(sniffImageMimeType(test::encodeWebp(2, 2, test::quadPixels())), "image/webp");
  EXPECT_EQ(sniffImageMimeType(std::vector<std::uint8_t>{0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n'}), "image/ktx2");
  EXPECT_EQ(sniffImageMimeType(std::vector<std::uint8_t>{'G', 'I', 'F', '8', '9', 'a'}), "");
  EXPECT_EQ(sniffImageMimeType(std::vector<std::uint8_t>{}), "");
  EXPECT_TRUE(isDecodableImageMimeType("image/webp"));
  EXPECT_FALSE(isDecodableImageMimeType("image/ktx2"));
}

// Every PNG channel count decodes to RGBA (grey replicated, alpha 255 when absent); the channels
// of the file are reported; the bytes are kept as they were.
TEST(TextureImage, PngOfEachChannelCount) {
  const std::vector<std::uint8_t> quad = test::quadPixels();
  for (int channels = 1; channels <= 4; ++channels) {
    const std::vector<std::uint8_t> png = test::encodePng(2, 2, quad, channels);
    const TextureImage image = decode(png);
    EXPECT_EQ(image.width, 2);
    EXPECT_EQ(image.height, 2);
    EXPECT_EQ(image.channels, channels);
    EXPECT_EQ(image.mimeType, "image/png");
    EXPECT_EQ(image.encoded, png);
    ASSERT_EQ(image.rgba.size(), 16u);
    for (int p = 0; p < 4; ++p) {
      const std::uint8_t* texel = &image.rgba[std::size_t(p) * 4];
      const std::uint8_t* source = &quad[std::size_t(p) * 4];
      if (channels <= 2) {  // grey (+ alpha): the file's first channel replicated
        EXPECT_EQ(texel[0], source[0]);
        EXPECT_EQ(texel[1], source[0]);
        EXPECT_EQ(texel[2], source[0]);
        EXPECT_EQ(texel[3], channels == 2 ? source[1] : 255);
      } else {
        for (int c = 0; c < 3; ++c) EXPECT_EQ(texel[c], source[c]);
        EXPECT_EQ(texel[3], channels == 4 ? source[3] : 255);
      }
    }
  }
}

TEST(TextureImage, WebpLosslessIsExactAndLossyHasNoAlpha) {
  const TextureImage lossless = decode(test::encodeWebp(2, 2, test::quadPixels()));
  EXPECT_EQ(lossless.rgba, test::quadPixels());
  EXPECT_EQ(lossless.channels, 4);
  EXPECT_EQ(lossless.mimeType, "image/webp");
  const std::vector<std::uint8_t> flat(16 * 16 * 4, 140);
  const TextureImage lossy = decode(test::encodeWebp(16, 16, flat, false, 95.0f));
  EXPECT_EQ(lossy.channels, 3);
  EXPECT_EQ(lossy.width, 16);
  for (std::size_t i = 0; i < lossy.rgba.size(); i += 4) {
    EXPECT_NEAR(int(lossy.rgba[i]), 140, 3);
    EXPECT_EQ(lossy.rgba[i + 3], 255);
  }
}

TEST(TextureImage, Jpeg) {
  const std::vector<std::uint8_t> flat(8 * 8 * 4, 60);
  const TextureImage image = decode(test::encodeJpeg(8, 8, flat));
  EXPECT_EQ(image.channels, 3);
  EXPECT_EQ(image.mimeType, "image/jpeg");
  ASSERT_EQ(image.rgba.size(), 256u);
  EXPECT_NEAR(int(image.rgba[0]), 60, 2);
  EXPECT_EQ(image.rgba[3], 255);
}

TEST(TextureImage, SizeIsCheckedFromTheHeaderBeforeDecoding) {
  EXPECT_EQ(decodeError(test::pngHeaderClaiming(0, 0)), "image is 0 x 0 pixels");
  EXPECT_EQ(decodeError(test::pngHeaderClaiming(4, 0)), "image is 4 x 0 pixels");
  // 64k x 64k RGBA would be 16 GiB: refused from the IHDR, nothing allocated.
  EXPECT_EQ(decodeError(test::pngHeaderClaiming(65536, 65536)),
            "image is 65536 x 65536 pixels, beyond the limit of 16384 on a side");
  EXPECT_EQ(decodeError(test::pngHeaderClaiming(16385, 1)),
            "image is 16385 x 1 pixels, beyond the limit of 16384 on a side");
  EXPECT_EQ(decodeError(test::webpHeaderClaiming(40000, 2)),
            "image is 40000 x 2 pixels, beyond the limit of 16384 on a side");
  // The limit itself passes the size check (and then fails for want of pixel data).
  EXPECT_EQ(decodeError(test::pngHeaderClaiming(16384, 1)).find("beyond"), std::string::npos);
}

// A JPEG's header claiming more blocks than its data can code is refused before stb_image spends
// seconds decoding grey blocks; the most compressible real file (flat, 1024 x 1024) still passes.
TEST(TextureImage, JpegTooShortForItsSizeIsRefused) {
  std::vector<std::uint8_t> jpeg = test::encodeJpeg(16, 8, std::vector<std::uint8_t>(16 * 8 * 4, 90));
  std::size_t sof = 0;
  while (sof + 1 < jpeg.size() && !(jpeg[sof] == 0xFF && jpeg[sof + 1] == 0xC0)) ++sof;
  ASSERT_LT(sof + 9, jpeg.size());
  jpeg[sof + 5] = 16000 >> 8, jpeg[sof + 6] = 16000 & 255;  // height
  jpeg[sof + 7] = 16000 >> 8, jpeg[sof + 8] = 16000 & 255;  // width
  EXPECT_EQ(decodeError(jpeg), "JPEG of " + std::to_string(jpeg.size()) +
                                   " bytes is too short for its 16000 x 16000 pixels (truncated?)");
  const TextureImage flat = decode(test::encodeJpeg(1024, 1024, std::vector<std::uint8_t>(1024 * 1024 * 4, 128)));
  EXPECT_EQ(flat.width, 1024);
}

TEST(TextureImage, BadDataGivesTheDecodersReason) {
  EXPECT_EQ(decodeError({0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n', 0, 0}),
            "KTX2 images (KHR_texture_basisu) are not supported; use PNG, JPEG or WebP");
  EXPECT_EQ(decodeError({'B', 'M', 0, 0}), "not a PNG, JPEG or WebP image (unknown signature)");
  const std::vector<std::uint8_t> png = test::encodePng(4, 4, std::vector<std::uint8_t>(64, 3));
  EXPECT_EQ(decodeError(std::vector<std::uint8_t>(png.begin(), png.begin() + 20)),
            "PNG does not start with an IHDR chunk");
  // Cut inside its IDAT: the chunk claims more bytes than follow.
  std::vector<std::uint8_t> cut(png.begin(), png.end() - 20);
  EXPECT_EQ(decodeError(cut).rfind("PNG chunk at byte ", 0), 0u) << decodeError(cut);
  EXPECT_NE(decodeError(cut).find("(corrupt or truncated)"), std::string::npos) << decodeError(cut);
  // Cut after its IDAT, before IEND: the chunks are whole, stb_image gives its reason.
  std::vector<std::uint8_t> noEnd(png.begin(), png.end() - 12);
  const std::string noEndError = decodeError(noEnd);
  EXPECT_TRUE(noEndError == "(no error)" || noEndError.rfind("PNG does not decode (", 0) == 0u) << noEndError;
  std::vector<std::uint8_t> webp = test::encodeWebp(4, 4, std::vector<std::uint8_t>(64, 3));
  webp.resize(webp.size() - 6);
  EXPECT_EQ(decodeError(webp).rfind("WebP does not decode (", 0), 0u) << decodeError(webp);
  const std::vector<std::uint8_t> jpeg = test::encodeJpeg(8, 8, std::vector<std::uint8_t>(256, 3));
  EXPECT_EQ(decodeError(std::vector<std::uint8_t>(jpeg.begin(), jpeg.begin() + 4)).rfind("JPEG does not decode (", 0),
            0u);
}

// The fuzz finding fuzz/corpus/texture/finding_png_idat_claims_2gib.png: a valid small PNG followed
// by an IDAT whose length says 0x71717171 bytes. stb_image grew its buffer to that length (2 GiB)
// before reading; the chunk walk refuses it first.
TEST(TextureImage, PngChunkLongerThanTheFileIsRefusedBeforeDecoding) {
  std::vector<std::uint8_t> png = test::encodePng(3, 2, std::vector<std::uint8_t>(3 * 2 * 4, 7));
  std::size_t iend = png.size() - 12;
  ASSERT_EQ(std::memcmp(png.data() + iend + 4, "IEND", 4), 0);
  const std::uint8_t chunk[] = {0x71, 0x71, 0x71, 0x71, 'I', 'D', 'A', 'T', 0x71, 0x71, 0x71, 0x71};
  png.insert(png.begin() + std::ptrdiff_t(iend), std::begin(chunk), std::end(chunk));
  EXPECT_EQ(decodeError(png), "PNG chunk at byte " + std::to_string(iend) + " claims " + std::to_string(0x71717171) +
                                  " bytes of data, but only " + std::to_string(png.size() - iend - 12) +
                                  " follow (corrupt or truncated)");
}

// The fuzz finding fuzz/corpus/texture/finding_png_cut_chunk_claims_1gib.png: a 3 x 2 PNG whose
// last chunk is cut off inside its header's CRC-less tail (length, "IDAT" and 3 bytes): the chunk
// walk used to stop where fewer than 12 bytes were left, and stb_image grew its IDAT buffer to the
// stated 0x56503858 bytes (2 GiB after doubling) before finding nothing to read.
TEST(TextureImage, APngChunkCutOffInsideItsHeaderIsRefusedBeforeDecoding) {
  std::vector<std::uint8_t> png = test::encodePng(3, 2, std::vector<std::uint8_t>(3 * 2 * 4, 7));
  const std::size_t iend = png.size() - 12;
  png.resize(iend);  // no IEND
  const std::uint8_t cut[] = {0x56, 0x50, 0x38, 0x58, 'I', 'D', 'A', 'T', 0x26, 0x60, 0x82};
  png.insert(png.end(), std::begin(cut), std::end(cut));
  EXPECT_EQ(decodeError(png), "PNG chunk at byte " + std::to_string(iend) + " claims " + std::to_string(0x56503858) +
                                  " bytes of data, but only 0 follow (corrupt or truncated)");
  // A chunk of length 0 cut off in its CRC is refused too; 7 bytes or fewer after the last chunk
  // hold no length and type, which stb_image reads as the end.
  png.resize(iend);
  const std::uint8_t empty[] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae};
  png.insert(png.end(), std::begin(empty), std::end(empty));
  EXPECT_EQ(decodeError(png), "PNG chunk at byte " + std::to_string(iend) +
                                  " claims 0 bytes of data, but only 0 follow (corrupt or truncated)");
}

}  // namespace
}  // namespace iblkit
