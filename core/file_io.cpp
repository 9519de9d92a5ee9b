#include "core/file_io.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <system_error>

#include "core/error.h"
#include "core/input_file.h"
#include "core/temporary_files.h"

namespace iblkit {

std::vector<char> readFileBytes(const std::filesystem::path& file) {
  return readInputFile(file, kMaxBinaryInputBytes);
}

void refuseNonRegularOutput(const std::filesystem::path& file) {
  struct stat info {};
  if (::stat(file.c_str(), &info) != 0) return;  // a new path
  if (S_ISDIR(info.st_mode)) fail(file, "is a folder");
  if (!S_ISREG(info.st_mode)) fail(file, "exists and is not a regular file (not replaced)");
}

void writeAtomically(const std::filesystem::path& file,
                     const std::function<void(const std::filesystem::path& temporary)>& write) {
  refuseNonRegularOutput(file);
  const std::filesystem::path temporary = createTemporaryFile(file);
  try {
    write(temporary);
  } catch (...) {
    discardTemporary(temporary);
    throw;
  }
  withTemporariesLocked([&] {
    // Checked again just before the rename, which would replace a device node or a FIFO.
    try {
      refuseNonRegularOutput(file);
    } catch (...) {
      discardTemporary(temporary);
      throw;
    }
    std::error_code error;
    std::filesystem::rename(temporary, file, error);
    if (error) {
      discardTemporary(temporary);
      fail(file, "cannot rename " + temporary.filename().string() + ": " + error.message());
    }
    unregisterTemporary(temporary);
  });
}

}  // namespace iblkit
