// Writes the hand-made seeds of the texture target, fuzz/corpus/texture/seed_* (committed; run by
// hand after edits, like make_seeds.py, which cannot encode JPEG or WebP in plain Python):
//   make_texture_seeds OUT_DIR [NORMAL_MAP]
// Small generated images in every form the decoders take (PNG grey, grey + alpha, palette-free
// RGB and RGBA, 16-bit; baseline JPEG; lossless WebP with alpha and lossy WebP), and, given a
// real normal map (PNG, JPEG or WebP, e.g. one of @pmndrs/assets' normals/*.webp, CC0), its
// top-left 64 x 64 crop as lossy WebP and PNG.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#include <webp/decode.h>
#include <webp/encode.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(context);
  out->insert(out->end(), static_cast<std::uint8_t*>(data), static_cast<std::uint8_t*>(data) + size);
}

void put(const fs::path& folder, const std::string& name, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(folder / name, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  std::printf("%s: %zu bytes\n", (folder / name).c_str(), bytes.size());
}

std::vector<std::uint8_t> png(int w, int h, int channels, const std::vector<std::uint8_t>& pixels) {
  std::vector<std::uint8_t> out;
  stbi_write_png_to_func(&appendBytes, &out, w, h, channels, pixels.data(), w * channels);
  return out;
}

std::vector<std::uint8_t> jpeg(int w, int h, const std::vector<std::uint8_t>& rgb) {
  std::vector<std::uint8_t> out;
  stbi_write_jpg_to_func(&appendBytes, &out, w, h, 3, rgb.data(), 90);
  return out;
}

std::vector<std::uint8_t> webp(int w, int h, const std::vector<std::uint8_t>& rgba, bool lossless) {
  std::uint8_t* data = nullptr;
  const std::size_t size = lossless ? WebPEncodeLosslessRGBA(rgba.data(), w, h, w * 4, &data)
                                    : WebPEncodeRGBA(rgba.data(), w, h, w * 4, 80.0f, &data);
  std::vector<std::uint8_t> out(data, data + size);
  WebPFree(data);
  return out;
}

// A w x h gradient with `channels` channels.
std::vector<std::uint8_t> gradient(int w, int h, int channels) {
  std::vector<std::uint8_t> pixels;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < channels; ++c) pixels.push_back(std::uint8_t((x * 37 + y * 91 + c * 60) & 255));
  return pixels;
}

// A 16-bit grey PNG (stb_image_write writes only 8 bits): signature, IHDR, one stored-deflate IDAT
// (zlib header 78 01, a final stored block, Adler-32), IEND; CRCs computed here.
std::uint32_t crc32(const std::vector<std::uint8_t>& data) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (const std::uint8_t byte : data) {
    crc ^= byte;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xFFFFFFFFu;
}
void be32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(std::uint8_t(v >> s));
}
void chunk(std::vector<std::uint8_t>& out, const char* type, const std::vector<std::uint8_t>& data) {
  be32(out, std::uint32_t(data.size()));
  std::vector<std::uint8_t> typed(type, type + 4);
  typed.insert(typed.end(), data.begin(), data.end());
  out.insert(out.end(), typed.begin(), typed.end());
  be32(out, crc32(typed));
}
std::vector<std::uint8_t> png16Grey(int w, int h) {
  std::vector<std::uint8_t> raw;
  for (int y = 0; y < h; ++y) {
    raw.push_back(0);  // filter: none
    for (int x = 0; x < w; ++x) {
      const std::uint16_t value = std::uint16_t(x * 9000 + y * 20000);  // big-endian samples
      raw.push_back(std::uint8_t(value >> 8));
      raw.push_back(std::uint8_t(value));
    }
  }
  std::vector<std::uint8_t> z = {0x78, 0x01, 0x01, std::uint8_t(raw.size()), std::uint8_t(raw.size() >> 8),
                                 std::uint8_t(~raw.size()), std::uint8_t(~raw.size() >> 8)};
  z.insert(z.end(), raw.begin(), raw.end());
  std::uint32_t a = 1, b = 0;
  for (const std::uint8_t byte : raw) a = (a + byte) % 65521, b = (b + a) % 65521;
  be32(z, b << 16 | a);
  std::vector<std::uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<std::uint8_t> ihdr;
  be32(ihdr, std::uint32_t(w));
  be32(ihdr, std::uint32_t(h));
  ihdr.insert(ihdr.end(), {16, 0, 0, 0, 0});
  chunk(out, "IHDR", ihdr);
  chunk(out, "IDAT", z);
  chunk(out, "IEND", {});
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: make_texture_seeds OUT_DIR [NORMAL_MAP]\n");
    return 2;
  }
  const fs::path out = argv[1];
  fs::create_directories(out);
  put(out, "seed_grey_3x2.png", png(3, 2, 1, gradient(3, 2, 1)));
  put(out, "seed_grey_alpha_2x2.png", png(2, 2, 2, gradient(2, 2, 2)));
  put(out, "seed_rgb_4x3.png", png(4, 3, 3, gradient(4, 3, 3)));
  put(out, "seed_rgba_2x2.png", png(2, 2, 4, gradient(2, 2, 4)));
  put(out, "seed_grey16_3x2.png", png16Grey(3, 2));
  put(out, "seed_rgb_16x8.jpg", jpeg(16, 8, gradient(16, 8, 3)));
  put(out, "seed_rgba_lossless_4x4.webp", webp(4, 4, gradient(4, 4, 4), true));
  put(out, "seed_rgba_lossy_8x8.webp", webp(8, 8, gradient(8, 8, 4), false));
  if (argc > 2) {
    std::ifstream in(argv[2], std::ios::binary);
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    int w = 0, h = 0;
    std::uint8_t* rgba = WebPDecodeRGBA(bytes.data(), bytes.size(), &w, &h);
    bool fromWebp = rgba != nullptr;
    if (!rgba) {
      int channels = 0;
      rgba = stbi_load_from_memory(bytes.data(), int(bytes.size()), &w, &h, &channels, 4);
    }
    if (!rgba || w < 64 || h < 64) {
      std::fprintf(stderr, "make_texture_seeds: %s: not a PNG, JPEG or WebP of at least 64 x 64\n", argv[2]);
      return 1;
    }
    std::vector<std::uint8_t> crop;
    for (int y = 0; y < 64; ++y)
      crop.insert(crop.end(), rgba + std::size_t(y) * w * 4, rgba + std::size_t(y) * w * 4 + 64 * 4);
    fromWebp ? WebPFree(rgba) : stbi_image_free(rgba);
    put(out, "seed_normal_64x64.webp", webp(64, 64, crop, false));
    put(out, "seed_normal_64x64.png", png(64, 64, 3, [&] {
          std::vector<std::uint8_t> rgb;
          for (std::size_t i = 0; i < crop.size(); i += 4) rgb.insert(rgb.end(), crop.begin() + i, crop.begin() + i + 3);
          return rgb;
        }()));
  }
  return 0;
}
