#include "core/texture_image.h"

#include "core/png_chunks.h"

// Debian's libstb exports stb_image's implementation (png_io.cpp uses it too), so only the header.
#include <stb/stb_image.h>
#include <webp/decode.h>

#include <climits>
#include <cstring>
#include <memory>

#include "core/error.h"

namespace iblkit {

namespace {

constexpr std::uint8_t kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
// KTX 2.0 file identifier (KTX 2.0 specification section 3.1): «KTX 20»\r\n\x1A\n.
constexpr std::uint8_t kKtx2Identifier[12] = {0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n'};

bool startsWith(std::span<const std::uint8_t> bytes, const std::uint8_t* prefix, std::size_t size) {
  return bytes.size() >= size && std::memcmp(bytes.data(), prefix, size) == 0;
}

std::uint32_t bigEndian32(const std::uint8_t* p) {
  return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | std::uint32_t(p[3]);
}

std::string sizeText(long long width, long long height) {
  return std::to_string(width) + " x " + std::to_string(height);
}

// The size check every format goes through before its pixels are allocated.
void requireTextureSize(long long width, long long height, const std::filesystem::path& file,
                        const std::string& what) {
  if (width <= 0 || height <= 0) fail(file, what + ": image is " + sizeText(width, height) + " pixels");
  if (width > kMaxTextureSize || height > kMaxTextureSize)
    fail(file, what + ": image is " + sizeText(width, height) + " pixels, beyond the limit of " +
                   std::to_string(kMaxTextureSize) + " on a side");
}

std::string webpStatusText(VP8StatusCode status) {
  switch (status) {
    case VP8_STATUS_OK: return "ok";
    case VP8_STATUS_OUT_OF_MEMORY: return "out of memory";
    case VP8_STATUS_INVALID_PARAM: return "invalid parameter";
    case VP8_STATUS_BITSTREAM_ERROR: return "bitstream error";
    case VP8_STATUS_UNSUPPORTED_FEATURE: return "unsupported feature";
    case VP8_STATUS_SUSPENDED: return "suspended";
    case VP8_STATUS_USER_ABORT: return "aborted";
    case VP8_STATUS_NOT_ENOUGH_DATA: return "not enough data (truncated?)";
  }
  return "error " + std::to_string(int(status));
}

// stb_image's reason for its last failure, fit for a one-line message (it may quote raw bytes).
std::string stbReason() {
  const char* reason = stbi_failure_reason();
  return reason ? printableExcerpt(reason, 80) : "unknown reason";
}

// PNG and JPEG through stb_image. The PNG size comes from IHDR (PNG specification section 11.2.2,
// the first chunk), since stbi_info refuses sizes it would not decode with a vaguer "too large".
void decodeWithStb(TextureImage& image, std::span<const std::uint8_t> bytes, bool png,
                   const std::filesystem::path& file, const std::string& what) {
  const std::string format = png ? "PNG" : "JPEG";
  if (bytes.size() > std::size_t(INT_MAX)) fail(file, what + ": " + format + " data larger than 2 GiB");
  const int size = int(bytes.size());
  if (png) {
    if (bytes.size() < 24 || std::memcmp(bytes.data() + 12, "IHDR", 4) != 0)
      fail(file, what + ": PNG does not start with an IHDR chunk");
    requireTextureSize(bigEndian32(bytes.data() + 16), bigEndian32(bytes.data() + 20), file, what);
    requirePngChunksInside(bytes, file, what);
  }
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_memory(bytes.data(), size, &width, &height, &channels))
    fail(file, what + ": " + format + " does not decode (" + stbReason() + ")");
  requireTextureSize(width, height, file, what);
  // stb_image decodes a truncated JPEG to the end, as grey blocks: a 700-byte header claiming
  // 16000 x 16000 took 35 s and 2 GiB. Every 8 x 8 block of a full-resolution component codes at
  // least its DC difference, a Huffman code of at least 1 bit (ITU T.81 F.1.2.1, and the first DC
  // scan of a progressive file, G.1.2.1), so a real file has at least one byte per 8 blocks.
  const long long blocks = (width + 7LL) / 8 * ((height + 7LL) / 8);
  if (!png && (long long)(bytes.size()) * 8 < blocks)
    fail(file, what + ": JPEG of " + std::to_string(bytes.size()) + " bytes is too short for its " +
                   sizeText(width, height) + " pixels (truncated?)");

  int decodedWidth = 0, decodedHeight = 0, fileChannels = 0;
  const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load_from_memory(bytes.data(), size, &decodedWidth, &decodedHeight, &fileChannels, 4), &stbi_image_free);
  if (!pixels) fail(file, what + ": " + format + " does not decode (" + stbReason() + ")");
  if (decodedWidth != width || decodedHeight != height)
    fail(file, what + ": " + format + " decodes to " + sizeText(decodedWidth, decodedHeight) +
                   " pixels, not the " + sizeText(width, height) + " of its header");
  image.width = width;
  image.height = height;
  image.channels = channels;
  image.rgba.assign(pixels.get(), pixels.get() + std::size_t(width) * std::size_t(height) * 4);
}

// WebP (lossy, lossless, with or without alpha; not animated) through libwebp's advanced API, so
// that a failure has libwebp's status to report.
void decodeWithWebp(TextureImage& image, std::span<const std::uint8_t> bytes, const std::filesystem::path& file,
                    const std::string& what) {
  WebPDecoderConfig config;
  if (!WebPInitDecoderConfig(&config)) fail(file, what + ": libwebp version mismatch");
  const VP8StatusCode status = WebPGetFeatures(bytes.data(), bytes.size(), &config.input);
  if (status != VP8_STATUS_OK) fail(file, what + ": WebP does not decode (" + webpStatusText(status) + ")");
  if (config.input.has_animation) fail(file, what + ": animated WebP is not supported");
  const int width = config.input.width, height = config.input.height;
  requireTextureSize(width, height, file, what);

  image.rgba.resize(std::size_t(width) * std::size_t(height) * 4);
  config.output.colorspace = MODE_RGBA;
  config.output.is_external_memory = 1;
  config.output.u.RGBA.rgba = image.rgba.data();
  config.output.u.RGBA.stride = width * 4;
  config.output.u.RGBA.size = image.rgba.size();
  const VP8StatusCode decoded = WebPDecode(bytes.data(), bytes.size(), &config);
  WebPFreeDecBuffer(&config.output);  // nothing to free with external memory; the API asks for it
  if (decoded != VP8_STATUS_OK) {
    image.rgba.clear();
    fail(file, what + ": WebP does not decode (" + webpStatusText(decoded) + ")");
  }
  image.width = width;
  image.height = height;
  image.channels = config.input.has_alpha ? 4 : 3;
}

}  // namespace

std::string sniffImageMimeType(std::span<const std::uint8_t> bytes) {
  constexpr std::uint8_t kJpegSoi[3] = {0xFF, 0xD8, 0xFF};
  if (startsWith(bytes, kPngSignature, sizeof(kPngSignature))) return "image/png";
  if (startsWith(bytes, kJpegSoi, sizeof(kJpegSoi))) return "image/jpeg";
  if (bytes.size() >= 12 && std::memcmp(bytes.data(), "RIFF", 4) == 0 && std::memcmp(bytes.data() + 8, "WEBP", 4) == 0)
    return "image/webp";
  if (startsWith(bytes, kKtx2Identifier, sizeof(kKtx2Identifier))) return "image/ktx2";
  return "";
}

bool isDecodableImageMimeType(const std::string& mimeType) {
  return mimeType == "image/png" || mimeType == "image/jpeg" || mimeType == "image/webp";
}

void decodeTextureImage(TextureImage& image, std::vector<std::uint8_t> encoded, const std::filesystem::path& file,
                        const std::string& what) {
  const std::string mimeType = sniffImageMimeType(encoded);
  if (mimeType == "image/ktx2")
    fail(file, what + ": KTX2 images (KHR_texture_basisu) are not supported; use PNG, JPEG or WebP");
  if (!isDecodableImageMimeType(mimeType))
    fail(file, what + ": not a PNG, JPEG or WebP image (unknown signature)");
  if (mimeType == "image/webp")
    decodeWithWebp(image, encoded, file, what);
  else
    decodeWithStb(image, encoded, mimeType == "image/png", file, what);
  image.mimeType = mimeType;
  image.encoded = std::move(encoded);
}

}  // namespace iblkit
