#include "core/png_chunks.h"

#include <cstdint>

#include "core/error.h"

namespace iblkit {

namespace {

std::uint32_t bigEndian32(const std::uint8_t* p) {
  return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | std::uint32_t(p[3]);
}

}  // namespace

// Every chunk up to IEND (PNG specification section 5.3: a 4-byte length, the type, the data and
// a CRC) lies inside the data. stb_image trusts a chunk's length and grows its IDAT buffer to it
// before reading: a 3 x 2 PNG whose second IDAT claimed 0x71717171 bytes asked for 2 GiB (a fuzz
// finding, fuzz/corpus/texture/).
void requirePngChunksInside(std::span<const std::uint8_t> bytes, const std::filesystem::path& file,
                            const std::string& what) {
  std::size_t at = std::size_t{8};
  // Every chunk whose length and type are there, the last one too when its data or CRC is cut
  // off: stb_image reads a length and type 8 bytes from the end just the same.
  while (at + 8 <= bytes.size()) {
    const std::uint64_t length = bigEndian32(bytes.data() + at);
    const std::string type(reinterpret_cast<const char*>(bytes.data() + at + 4), 4);
    const std::uint64_t afterType = bytes.size() - at - 8;  // the data and the 4-byte CRC
    const std::uint64_t remaining = afterType >= 4 ? afterType - 4 : 0;
    if (afterType < 4 || length > remaining)
      fail(file, (what.empty() ? "" : what + ": ") + "PNG chunk at byte " + std::to_string(at) + " claims " + std::to_string(length) +
                     " bytes of data, but only " + std::to_string(remaining) + " follow (corrupt or truncated)");
    if (type == "IEND") return;
    at += 12 + std::size_t(length);
  }
}

}  // namespace iblkit
