#pragma once
// Switching the viewer between the environment maps of a folder (--env-dir, default assets/hdri).
// Prefiltering a map (SH9, the GGX specular chain, the DFG table: computeEnvironmentStages in the
// baker library, which the program passes in as an EnvironmentPreparer) takes about a second, so it runs on a worker thread while the window keeps
// drawing with the current environment; the frame loop polls for the result and uploads it.
// No OpenGL here.
#include <filesystem>
#include <functional>
#include <future>
#include <optional>
#include <string>
#include <vector>

#include "bakefile/environment_stages.h"
#include "core/environment_map.h"

namespace iblkit {

// Computes the stages of a map (rotation and intensity applied), on the worker thread.
using EnvironmentPreparer = std::function<EnvironmentStages(const EnvironmentMap&)>;

class EnvironmentSwitcher {
 public:
  // Lists the .exr and .hdr files of `folder` (case-insensitive, sorted by name); a missing folder
  // gives an empty list and says so in status(). Maps switched to get `rotationDegrees` and
  // `intensity` (the scene's) before `prepare` prefilters them.
  EnvironmentSwitcher(const std::filesystem::path& folder, float rotationDegrees, float intensity,
                      EnvironmentPreparer prepare);
  // Waits for a running worker (it cannot be interrupted).
  ~EnvironmentSwitcher();
  EnvironmentSwitcher(const EnvironmentSwitcher&) = delete;
  EnvironmentSwitcher& operator=(const EnvironmentSwitcher&) = delete;

  const std::filesystem::path& folder() const { return folder_; }
  const std::vector<std::filesystem::path>& files() const { return files_; }
  // The index into files() of the environment shown; -1: the bake's own.
  int current() const { return current_; }
  // The index being prefiltered, -1 when none.
  int pending() const { return pending_; }
  bool busy() const { return pending_ >= 0; }
  // One line for the panel: what is shown, what is being prefiltered, or the last error.
  const std::string& status() const { return status_; }

  // Starts prefiltering files()[index] on the worker thread. While a worker runs, the latest
  // request waits and starts when it finishes. Out-of-range indices are ignored.
  void request(int index);
  // Requests `file` (--env), adding it to files() when it is not in the folder.
  void requestFile(const std::filesystem::path& file);
  // Requests the next (+1) or previous (-1) file after the current or pending one, wrapping around.
  void step(int direction);
  // Non-blocking: the stages of a finished request (once), to upload with Renderer::setEnvironment.
  // A map that failed to load leaves the current environment and puts the error in status().
  std::optional<EnvironmentStages> poll();
  // Blocks until no request is left and returns the last finished stages (for tests and
  // --frames runs that must see the switch).
  std::optional<EnvironmentStages> waitForResult();

 private:
  void start(int index);

  std::filesystem::path folder_;
  std::vector<std::filesystem::path> files_;
  float rotationDegrees_, intensity_;
  EnvironmentPreparer prepare_;
  int current_ = -1, pending_ = -1, queued_ = -1;
  std::future<EnvironmentStages> worker_;
  std::string status_;
};

}  // namespace iblkit
