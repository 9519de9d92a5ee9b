#pragma once
// Small encoded images for texture tests, made in memory with the encoders of the libraries the
// loader decodes with (stb_image_write for PNG and JPEG, libwebp for WebP), and headers crafted
// to claim sizes no test should allocate.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace iblkit::test {

// `rgba` holds width * height * 4 bytes, row 0 at the top; `channels` (1..4) of them are stored.
std::vector<std::uint8_t> encodePng(int width, int height, const std::vector<std::uint8_t>& rgba, int channels = 4);
std::vector<std::uint8_t> encodeJpeg(int width, int height, const std::vector<std::uint8_t>& rgba, int quality = 95);
// Lossless keeps every byte (alpha too); lossy is VP8 (no alpha) at `quality`.
std::vector<std::uint8_t> encodeWebp(int width, int height, const std::vector<std::uint8_t>& rgba,
                                     bool lossless = true, float quality = 90.0f);

// A 2 x 2 RGBA test pattern: red, green / blue, white with alpha 128 (row 0 at the top).
std::vector<std::uint8_t> quadPixels();

// A PNG signature and IHDR chunk (CRC correct) claiming width x height 8-bit RGBA, then IEND:
// nothing to decode, but a reader that trusts the header would allocate width * height * 4.
std::vector<std::uint8_t> pngHeaderClaiming(std::uint32_t width, std::uint32_t height);
// A WebP (RIFF, VP8X) header whose canvas is width x height (up to 2^24 on a side), no image data.
std::vector<std::uint8_t> webpHeaderClaiming(std::uint32_t width, std::uint32_t height);

void writeFileBytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes);

}  // namespace iblkit::test
