#include "report/stage_cache.h"

#include "core/error.h"
#include "core/temporary_files.h"

namespace iblkit {

namespace fs = std::filesystem;

StageCache::StageCache(fs::path root) : root_(std::move(root)) {
  std::error_code error;
  fs::create_directories(root_, error);
  if (error) fail(root_, "cannot create the cache folder: " + error.message());
}

fs::path StageCache::stage(const std::string& name, const std::string& key,
                           const std::function<void(const fs::path&)>& produce, bool* hit) const {
  const fs::path folder = this->folder(name, key);
  std::error_code error;
  if (fs::is_directory(folder, error)) {
    if (hit) *hit = true;
    ++hits_;
    return folder;
  }
  if (hit) *hit = false;
  ++misses_;
  // A unique name keeps two reports sharing a cache from writing into the same temporary folder,
  // and an interrupt removes it (core/temporary_files.h).
  const fs::path temporary = createTemporaryFolder(folder, ".tmp-");
  try {
    produce(temporary);
  } catch (...) {
    discardTemporary(temporary);
    throw;
  }
  bool renamed = false;
  withTemporariesLocked([&] {
    fs::rename(temporary, folder, error);
    renamed = !error;
    if (renamed) unregisterTemporary(temporary);
  });
  if (!renamed) {
    // Another report finished the same stage first: keep its folder.
    discardTemporary(temporary);
    if (!fs::is_directory(folder, error)) fail(folder, "cannot create the stage folder");
  }
  return folder;
}

}  // namespace iblkit
