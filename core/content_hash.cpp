#include "core/content_hash.h"

#include <array>
#include <cstdio>
#include <fstream>

#include "core/error.h"
#include "core/input_file.h"

namespace iblkit {

void ContentHash::addBytes(const void* data, std::size_t size) {
  constexpr std::uint64_t kPrime = 0x100000001b3ull;  // the FNV 64-bit prime
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) state_ = (state_ ^ bytes[i]) * kPrime;
}

ContentHash& ContentHash::add(std::string_view text) {
  const std::uint64_t length = text.size();
  addBytes(&length, sizeof length);
  addBytes(text.data(), text.size());
  return *this;
}

ContentHash& ContentHash::addFile(const std::filesystem::path& file) {
  // A FIFO or /dev/zero named as an input would block or never end.
  requireRegularInputFile(file, kMaxBinaryInputBytes);
  std::ifstream stream(file, std::ios::binary);
  if (!stream) fail(file, "cannot read file");
  std::array<char, 1 << 16> buffer;
  std::uint64_t size = 0;
  while (stream) {
    stream.read(buffer.data(), buffer.size());
    addBytes(buffer.data(), std::size_t(stream.gcount()));
    size += std::uint64_t(stream.gcount());
  }
  if (stream.bad()) fail(file, "read error");
  addBytes(&size, sizeof size);
  return *this;
}

std::string ContentHash::hex() const {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(state_));
  return text;
}

}  // namespace iblkit
