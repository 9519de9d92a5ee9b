#pragma once
// How far a file being opened from the window is: the loader's worker reports its step and count
// (the in-memory bake: "visibility" vertices, then "environment" stages), and the panel shows it
// each frame ("opening bunny.glb: visibility 45%, 1.2 s ...").
#include <cstddef>
#include <filesystem>
#include <mutex>
#include <string>

namespace iblkit {

class LoadProgress {
 public:
  // From any thread, possibly concurrently (the baker's workers). A count lower than one already
  // reported for the same step is ignored (workers finish out of order).
  void report(const char* step, std::size_t done, std::size_t total);

  // The panel's line for `file` after `seconds`; before any report, the step is "reading".
  std::string describe(const std::filesystem::path& file, double seconds) const;

 private:
  mutable std::mutex mutex_;
  std::string step_;
  std::size_t done_ = 0, total_ = 0;
};

}  // namespace iblkit
