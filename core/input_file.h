#pragma once
// Input files are opened only when they are regular files of bounded size: a model `file` that is
// /dev/zero, a FIFO, a folder or a device is refused with one line naming it before anything reads
// it (stat does not open, so a FIFO cannot block), and a file over its limit is refused rather
// than read until memory runs out. Every loader goes through here, including those whose library
// opens the file itself (tinygltf's buffers, through its FsCallbacks).
//
// The limits:
//   kMaxBinaryInputBytes  4 GiB   models (.gltf/.glb/.bin) and images (.exr, .hdr, .png)
//   kMaxJsonInputBytes    256 MiB the .json files iblkit reads (scene, bake.json, env/sh9.json)
//   kMaxJsonNesting       256     arrays and objects inside each other in any JSON iblkit reads
//                                 (glTF's included): deeper documents are refused, since the JSON
//                                 readers (tinygltf's) recurse once per level.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace iblkit {

inline constexpr std::uintmax_t kMaxBinaryInputBytes = std::uintmax_t{4} << 30;
inline constexpr std::uintmax_t kMaxJsonInputBytes = std::uintmax_t{256} << 20;
inline constexpr int kMaxJsonNesting = 256;

// Throws Error("<file>: ...") unless `file` (symbolic links followed) exists, is a regular file
// and holds at most `limitBytes` bytes. Opens nothing.
void requireRegularInputFile(const std::filesystem::path& file, std::uintmax_t limitBytes);

// Every byte of a regular file of at most `limitBytes` bytes (opened non-blocking and checked
// again after opening, so a file swapped for a FIFO meanwhile cannot block either). Throws Error
// for a file that cannot be opened or read, one that is not regular or is too large, and an empty
// (0-byte) file, which no format we read accepts.
std::vector<char> readInputFile(const std::filesystem::path& file, std::uintmax_t limitBytes);

// Throws Error("<file>: JSON nests arrays and objects more than N deep") when `text` nests deeper
// than kMaxJsonNesting; strings (and the brackets inside them) are skipped. Nothing else is checked.
void requireJsonNesting(std::string_view text, const std::filesystem::path& file);

// The text of a JSON file, read with readInputFile(file, kMaxJsonInputBytes) and checked with
// requireJsonNesting, ready for the parser.
std::string readJsonText(const std::filesystem::path& file);

}  // namespace iblkit
