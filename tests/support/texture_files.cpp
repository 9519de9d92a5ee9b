#include "support/texture_files.h"

#include <stb/stb_image_write.h>
#include <webp/encode.h>

#include <array>
#include <fstream>
#include <stdexcept>

namespace iblkit::test {

namespace {

void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(context);
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

std::vector<std::uint8_t> channelsOf(const std::vector<std::uint8_t>& rgba, int channels) {
  std::vector<std::uint8_t> out;
  for (std::size_t i = 0; i < rgba.size(); i += 4)
    for (int c = 0; c < channels; ++c) out.push_back(rgba[i + std::size_t(c)]);
  return out;
}

void appendU32BigEndian(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(std::uint8_t(v >> shift));
}

// PNG specification annex D: CRC-32 over the chunk type and data.
std::uint32_t crc32(const std::uint8_t* data, std::size_t size) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xFFFFFFFFu;
}

void appendChunk(std::vector<std::uint8_t>& out, const char* type, const std::vector<std::uint8_t>& data) {
  appendU32BigEndian(out, std::uint32_t(data.size()));
  std::vector<std::uint8_t> typed(type, type + 4);
  typed.insert(typed.end(), data.begin(), data.end());
  out.insert(out.end(), typed.begin(), typed.end());
  appendU32BigEndian(out, crc32(typed.data(), typed.size()));
}

void appendU24LittleEndian(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 0; shift < 24; shift += 8) out.push_back(std::uint8_t(v >> shift));
}

}  // namespace

std::vector<std::uint8_t> encodePng(int width, int height, const std::vector<std::uint8_t>& rgba, int channels) {
  std::vector<std::uint8_t> out;
  const std::vector<std::uint8_t> pixels = channelsOf(rgba, channels);
  if (!stbi_write_png_to_func(&appendBytes, &out, width, height, channels, pixels.data(), width * channels))
    throw std::runtime_error("stbi_write_png_to_func failed");
  return out;
}

std::vector<std::uint8_t> encodeJpeg(int width, int height, const std::vector<std::uint8_t>& rgba, int quality) {
  std::vector<std::uint8_t> out;
  const std::vector<std::uint8_t> pixels = channelsOf(rgba, 3);
  if (!stbi_write_jpg_to_func(&appendBytes, &out, width, height, 3, pixels.data(), quality))
    throw std::runtime_error("stbi_write_jpg_to_func failed");
  return out;
}

std::vector<std::uint8_t> encodeWebp(int width, int height, const std::vector<std::uint8_t>& rgba, bool lossless,
                                     float quality) {
  std::uint8_t* data = nullptr;
  const std::size_t size = lossless ? WebPEncodeLosslessRGBA(rgba.data(), width, height, width * 4, &data)
                                    : WebPEncodeRGB(channelsOf(rgba, 3).data(), width, height, width * 3, quality, &data);
  if (size == 0) throw std::runtime_error("libwebp encoding failed");
  std::vector<std::uint8_t> out(data, data + size);
  WebPFree(data);
  return out;
}

std::vector<std::uint8_t> quadPixels() {
  return {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128};
}

std::vector<std::uint8_t> pngHeaderClaiming(std::uint32_t width, std::uint32_t height) {
  std::vector<std::uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<std::uint8_t> ihdr;
  appendU32BigEndian(ihdr, width);
  appendU32BigEndian(ihdr, height);
  ihdr.insert(ihdr.end(), {8, 6, 0, 0, 0});  // 8-bit, RGBA, deflate, adaptive filter, no interlace
  appendChunk(out, "IHDR", ihdr);
  appendChunk(out, "IEND", {});
  return out;
}

std::vector<std::uint8_t> webpHeaderClaiming(std::uint32_t width, std::uint32_t height) {
  // WebP container specification, "Extended file format": RIFF size, 'WEBP', then a VP8X chunk of
  // 10 bytes: flags (4), canvas width - 1 (3, little-endian), canvas height - 1 (3).
  std::vector<std::uint8_t> chunk = {'V', 'P', '8', 'X', 10, 0, 0, 0, 0, 0, 0, 0};
  appendU24LittleEndian(chunk, width - 1);
  appendU24LittleEndian(chunk, height - 1);
  std::vector<std::uint8_t> out = {'R', 'I', 'F', 'F'};
  const std::uint32_t riffSize = std::uint32_t(4 + chunk.size());
  for (int shift = 0; shift < 32; shift += 8) out.push_back(std::uint8_t(riffSize >> shift));
  out.insert(out.end(), {'W', 'E', 'B', 'P'});
  out.insert(out.end(), chunk.begin(), chunk.end());
  return out;
}

void writeFileBytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream stream(path, std::ios::binary);
  stream.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  if (!stream) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace iblkit::test
