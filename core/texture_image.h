#pragma once
// Decoding the images glTF materials use (glTF 2.0 section 3.9: PNG and JPEG; EXT_texture_webp:
// WebP) into TextureImage's 8-bit RGBA. PNG and JPEG go through stb_image, WebP through libwebp.
// The format is decided by the bytes' signature, not by the name or the declared mimeType.
// Before anything is decoded, the size is read from the header (PNG IHDR, stbi_info for JPEG,
// WebPGetInfo for WebP: for VP8X files the canvas) and checked against kMaxTextureSize, so a
// crafted header claiming 64k x 64k is refused without allocating its pixels; so is a JPEG with
// fewer bytes than its 8 x 8 blocks need (one bit each at least), which stb_image would decode
// for seconds as grey blocks. Every failure is
// one line: "<file>: <what>: <problem>", with stb_image's or libwebp's reason for data that does
// not decode.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/texture.h"

namespace iblkit {

// The largest texture side iblkit decodes: GL_MAX_TEXTURE_SIZE of current desktop GPUs and of
// Mesa's llvmpipe, so every image the reference samples the raster can upload too. A 16384 x 16384
// RGBA image is 1 GiB decoded. Images of 0 pixels on a side are refused too.
inline constexpr int kMaxTextureSize = 16384;

// "image/png", "image/jpeg", "image/webp" or "image/ktx2" from the bytes' signature (PNG's 8-byte
// signature, JPEG's SOI marker FF D8 FF, RIFF....WEBP, KTX 2.0's 12-byte identifier); "" when the
// bytes are none of these.
std::string sniffImageMimeType(std::span<const std::uint8_t> bytes);

// True for the mime types decodeTextureImage reads: image/png, image/jpeg and image/webp.
bool isDecodableImageMimeType(const std::string& mimeType);

// Decodes `encoded` (PNG, JPEG or WebP) into image.rgba (row 0 at the top), filling width,
// height, channels (of the encoded file: 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA) and mimeType
// (sniffed), and moves `encoded` into image.encoded; name, file and uri are left as they are.
// `what` names the image in messages, e.g. "image 2 'albedo.png'". Throws Error("<file>: <what>:
// ...") for bytes that are none of the three formats (KTX2 named as such), a size of 0 or beyond
// kMaxTextureSize on a side, and data that does not decode.
void decodeTextureImage(TextureImage& image, std::vector<std::uint8_t> encoded,
                        const std::filesystem::path& file, const std::string& what);

}  // namespace iblkit
