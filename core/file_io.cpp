#include "core/file_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <system_error>

#include "core/error.h"
#include "core/input_file.h"

namespace iblkit {

std::vector<char> readFileBytes(const std::filesystem::path& file) {
  return readInputFile(file, kMaxBinaryInputBytes);
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
