#pragma once
// A 64-bit FNV-1a hash (Fowler, Noll, Vo) of bytes and files. The report's stage cache keys hash
// everything a stage's output depends on (its input files' bytes, its arguments and the program
// that runs it), so a stale result is never reused; the reference tracer's render keys
// (reference/pass_sum.h) so keep passes of different renders from merging, and check its files.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace iblkit {

class ContentHash {
 public:
  // Adds the bytes of `text` and its length (so "ab" + "c" differs from "a" + "bc").
  ContentHash& add(std::string_view text);
  // Adds the file's size and bytes. Throws Error naming the file when it cannot be read.
  ContentHash& addFile(const std::filesystem::path& file);
  std::uint64_t value() const { return state_; }
  std::string hex() const;  // 16 lowercase hex digits

 private:
  void addBytes(const void* data, std::size_t size);
  std::uint64_t state_ = 0xcbf29ce484222325ull;  // the FNV-1a 64-bit offset basis
};

}  // namespace iblkit
