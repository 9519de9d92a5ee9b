#include "report/stage_cache.h"

#include <unistd.h>

#include "core/error.h"

namespace iblkit {

namespace fs = std::filesystem;

StageCache::StageCache(fs::path root) : root_(std::move(root)) {
  std::error_code error;
  fs::create_directories(root_, error);
  if (error) fail(root_, "cannot create the cache folder: " + error.message());
}

fs::path StageCache::stage(const std::string& name, const std::string& key,
                           const std::function<void(const fs::path&)>& produce, bool* hit) const {
  const fs::path folder = root_ / (name + "-" + key);
  std::error_code error;
  if (fs::is_directory(folder, error)) {
    if (hit) *hit = true;
    ++hits_;
    return folder;
  }
  if (hit) *hit = false;
  ++misses_;
  // The process id keeps two reports sharing a cache from writing into the same temporary folder.
  const fs::path temporary = root_ / (name + "-" + key + ".tmp-" + std::to_string(::getpid()));
  fs::remove_all(temporary, error);
  fs::create_directories(temporary, error);
  if (error) fail(temporary, "cannot create folder: " + error.message());
  try {
    produce(temporary);
  } catch (...) {
    fs::remove_all(temporary, error);
    throw;
  }
  fs::rename(temporary, folder, error);
  if (error) {
    // Another report finished the same stage first: keep its folder.
    fs::remove_all(temporary, error);
    if (!fs::is_directory(folder, error)) fail(folder, "cannot create the stage folder");
  }
  return folder;
}

}  // namespace iblkit
