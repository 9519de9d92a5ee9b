#pragma once
// The check every PNG gets before stb_image decodes it (core/png_io.cpp's images, texture_image's
// textures): stb_image trusts a chunk's stated length and grows its IDAT buffer to it before
// reading, so a small file that claims a huge chunk asks for gigabytes (fuzz findings in
// fuzz/corpus/texture/ and fuzz/corpus/png/).

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

namespace iblkit {

// Throws Error("<file>: [<what>: ]PNG chunk at byte N claims L bytes of data, but only R follow
// (corrupt or truncated)") unless every chunk after the 8-byte signature, up to IEND, lies inside
// `bytes`, the last one too when only its length and type are there.
void requirePngChunksInside(std::span<const std::uint8_t> bytes, const std::filesystem::path& file,
                            const std::string& what);

}  // namespace iblkit
