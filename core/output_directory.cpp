#include "core/output_directory.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>

#include "core/error.h"

namespace iblkit {

namespace fs = std::filesystem;

namespace {

// A new, empty folder "<base><suffix>XXXXXX" with a unique name (mkdtemp).
fs::path uniqueFolder(const fs::path& base, const char* suffix) {
  std::string name = base.string() + suffix + "XXXXXX";
  if (!mkdtemp(name.data()))
    fail(base, std::string("cannot create a folder beside it: ") + std::strerror(errno));
  return name;
}

}  // namespace

void writeDirectoryAtomically(const fs::path& directory, const std::function<void(const fs::path&)>& fill) {
  fs::path target = directory.lexically_normal();
  if (target.filename().empty()) target = target.parent_path();  // "out/" names the folder "out"
  std::error_code error;
  if (fs::exists(target, error) && !fs::is_directory(target, error))
    fail(target, "exists and is not a folder");
  if (target.has_parent_path()) fs::create_directories(target.parent_path(), error);
  if (error) fail(target.parent_path(), "cannot create folder: " + error.message());

  const fs::path temporary = uniqueFolder(target, ".tmp-");
  try {
    fill(temporary);
  } catch (...) {
    fs::remove_all(temporary, error);
    throw;
  }

  fs::path old;
  if (fs::exists(target, error)) {
    old = uniqueFolder(target, ".old-");
    // Renaming a folder onto an empty folder replaces it (POSIX rename).
    fs::rename(target, old, error);
    if (error) {
      const std::string reason = error.message();
      fs::remove_all(temporary, error);
      fs::remove(old, error);
      fail(target, "cannot move the previous output aside: " + reason);
    }
  }
  fs::rename(temporary, target, error);
  if (error) {
    const std::string reason = error.message();
    if (!old.empty()) fs::rename(old, target, error);
    fs::remove_all(temporary, error);
    fail(target, "cannot rename " + temporary.filename().string() + " into place: " + reason);
  }
  if (!old.empty()) fs::remove_all(old, error);
}

}  // namespace iblkit
