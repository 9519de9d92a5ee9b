#include "core/output_directory.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>

#include "core/error.h"
#include "core/temporary_files.h"

namespace iblkit {

namespace fs = std::filesystem;

void writeDirectoryAtomically(const fs::path& directory, const std::function<void(const fs::path&)>& fill) {
  fs::path target = directory.lexically_normal();
  if (target.filename().empty()) target = target.parent_path();  // "out/" names the folder "out"
  std::error_code error;
  const auto refuseNonFolder = [&] {
    if (fs::exists(target, error) && !fs::is_directory(target, error))
      fail(target, "exists and is not a folder");
  };
  refuseNonFolder();
  if (target.has_parent_path()) fs::create_directories(target.parent_path(), error);
  if (error) fail(target.parent_path(), "cannot create folder: " + error.message());

  const fs::path temporary = createTemporaryFolder(target, ".tmp-");
  try {
    fill(temporary);
  } catch (...) {
    discardTemporary(temporary);
    throw;
  }

  // The previous output moves aside and the new one into place with no interrupt in between; an
  // interrupt after that removes the previous output, before it restores it.
  fs::path old;
  withTemporariesLocked([&] {
    try {
      refuseNonFolder();
    } catch (...) {
      discardTemporary(temporary);
      throw;
    }
    if (fs::exists(target, error)) {
      old = createTemporaryFolder(target, ".old-");
      // Renaming a folder onto an empty folder replaces it (POSIX rename).
      fs::rename(target, old, error);
      if (error) {
        const std::string reason = error.message();
        discardTemporary(temporary);
        discardTemporary(old);
        fail(target, "cannot move the previous output aside: " + reason);
      }
      unregisterTemporary(old);
      registerTemporary(old, target);
    }
    fs::rename(temporary, target, error);
    if (error) {
      const std::string reason = error.message();
      if (!old.empty()) {
        fs::rename(old, target, error);
        unregisterTemporary(old);
      }
      discardTemporary(temporary);
      fail(target, "cannot rename " + temporary.filename().string() + " into place: " + reason);
    }
    unregisterTemporary(temporary);
    if (!old.empty()) {
      unregisterTemporary(old);
      registerTemporary(old);
    }
  });
  if (!old.empty()) discardTemporary(old);
}

}  // namespace iblkit
