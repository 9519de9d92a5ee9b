#include "core/file_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <system_error>

#include "core/error.h"

namespace iblkit {

std::vector<char> readFileBytes(const std::filesystem::path& file) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> stream(std::fopen(file.c_str(), "rb"), std::fclose);
  if (!stream) fail(file, std::string("cannot open: ") + std::strerror(errno));
  std::vector<char> bytes;
  char buffer[1 << 16];
  std::size_t count = 0;
  while ((count = std::fread(buffer, 1, sizeof(buffer), stream.get())) > 0)
    bytes.insert(bytes.end(), buffer, buffer + count);
  if (std::ferror(stream.get())) fail(file, std::string("cannot read: ") + std::strerror(errno));
  if (bytes.empty()) fail(file, "empty file (0 bytes)");
  return bytes;
}

void writeAtomically(const std::filesystem::path& file,
                     const std::function<void(const std::filesystem::path& temporary)>& write) {
  std::filesystem::path temporary = file;
  temporary += ".tmp";
  std::error_code ignored;
  try {
    write(temporary);
  } catch (...) {
    std::filesystem::remove(temporary, ignored);
    throw;
  }
  std::error_code error;
  std::filesystem::rename(temporary, file, error);
  if (error) {
    std::filesystem::remove(temporary, ignored);
    fail(file, "cannot rename " + temporary.filename().string() + ": " + error.message());
  }
}

}  // namespace iblkit
