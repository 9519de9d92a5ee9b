// 8-bit sRGB PNG through stb_image_write and stb_image. Debian's libstb already exports both, so
// the writer is compiled here with STB_IMAGE_WRITE_STATIC: its symbols stay private to this file
// and cannot clash with the library's.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/png_chunks.h"
#include "core/file_io.h"
#include "core/image_io.h"

namespace iblkit {

namespace {

// Display value in [0,1] to the nearest 8-bit code (NaN gives 0).
std::uint8_t quantize(float value) {
  const float v = value > 0.0f ? std::min(value, 1.0f) : 0.0f;
  return static_cast<std::uint8_t>(std::lround(v * 255.0f));
}

}  // namespace

void writePng(const std::filesystem::path& file, const Image& image, const ToneMapping& toneMapping,
              bool writeAlpha) {
  if (image.empty()) fail(file, "cannot write an empty image");
  const int channels = writeAlpha ? 4 : 3;
  std::vector<std::uint8_t> bytes;
  bytes.reserve(image.pixelCount() * static_cast<std::size_t>(channels));
  for (const glm::vec4& pixel : image.pixels()) {
    const glm::vec3 display = toneMap(glm::vec3(pixel), toneMapping);
    for (int c = 0; c < 3; ++c) bytes.push_back(quantize(display[c]));
    if (writeAlpha) bytes.push_back(quantize(pixel.a));  // coverage, not light: no curve, no sRGB
  }
  writeAtomically(file, [&](const std::filesystem::path& temporary) {
    errno = 0;
    if (!stbi_write_png(temporary.c_str(), image.width(), image.height(), channels, bytes.data(),
                        image.width() * channels))
      fail(file,
           std::string("cannot write PNG: ") + (errno ? std::strerror(errno) : "stb_image_write failed"));
  });
}

Image readPng(const std::filesystem::path& file, PixelRepair repair) {
  const std::vector<char> bytes = readFileBytes(file);
  constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < sizeof(kSignature) || std::memcmp(bytes.data(), kSignature, sizeof(kSignature)) != 0)
    fail(file, "not a PNG file (bad signature)");
  if (bytes.size() > static_cast<std::size_t>(INT_MAX)) fail(file, "file too large for the PNG decoder");
  // A chunk running past the end, refused before stb_image allocates its stated length, in the
  // words every image reader uses for a truncated file.
  try {
    requirePngChunksInside({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()}, file, "");
  } catch (const Error&) {
    fail(file, "truncated file (unexpected end of data)");
  }
  // stb_image reduces 16-bit PNGs to 8 bits and expands grey and palette images to RGBA.
  int width = 0, height = 0, channelsInFile = 0;
  const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), static_cast<int>(bytes.size()),
                            &width, &height, &channelsInFile, 4),
      stbi_image_free);
  if (!pixels) {
    // stb_image's reasons are terse ("outofdata" is a truncated file) and a few are empty.
    std::string reason = stbi_failure_reason() ? stbi_failure_reason() : "";
    // An unknown chunk's reason starts with the chunk type's four raw bytes, which may be line
    // breaks or other control characters (found by fuzz/fuzz_png): the message stays one line.
    for (char& c : reason)
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    if (reason == "outofdata") fail(file, "truncated file (unexpected end of data)");
    fail(file, reason.empty() ? "cannot decode PNG" : "cannot decode PNG: " + reason);
  }
  checkImageSize(file, width, height);

  // sRGB decoding through a table of the 256 codes (alpha is linear coverage: code / 255).
  static const std::array<float, 256> kLinear = [] {
    std::array<float, 256> table{};
    for (int code = 0; code < 256; ++code) table[static_cast<std::size_t>(code)] = srgbDecode(code / 255.0f);
    return table;
  }();
  Image image(width, height);
  const stbi_uc* rgba = pixels.get();
  for (glm::vec4& pixel : image.pixels()) {
    pixel = glm::vec4(kLinear[rgba[0]], kLinear[rgba[1]], kLinear[rgba[2]], rgba[3] / 255.0f);
    rgba += 4;
  }
  if (repair == PixelRepair::Repair) repairPixels(file, {&image, 1});
  return image;
}

}  // namespace iblkit
