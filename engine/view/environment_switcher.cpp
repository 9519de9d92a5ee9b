#include "engine/view/environment_switcher.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <utility>

#include "core/scene_environment.h"

namespace iblkit {

namespace fs = std::filesystem;

namespace {

bool isEnvironmentFile(const fs::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension == ".exr" || extension == ".hdr";
}

}  // namespace

EnvironmentSwitcher::EnvironmentSwitcher(const fs::path& folder, float rotationDegrees, float intensity,
                                         EnvironmentPreparer prepare)
    : folder_(folder), rotationDegrees_(rotationDegrees), intensity_(intensity), prepare_(std::move(prepare)) {
  std::error_code error;
  if (fs::is_directory(folder_, error))
    for (const fs::directory_entry& entry : fs::directory_iterator(folder_, error))
      if (entry.is_regular_file() && isEnvironmentFile(entry.path())) files_.push_back(entry.path());
  std::sort(files_.begin(), files_.end());
  status_ =
      files_.empty() ? folder_.string() + ": no .exr or .hdr environment maps" : "the bake's environment";
}

EnvironmentSwitcher::~EnvironmentSwitcher() {
  if (worker_.valid()) worker_.wait();
}

void EnvironmentSwitcher::start(int index) {
  pending_ = index;
  status_ = "prefiltering " + files_[std::size_t(index)].filename().string() + " ...";
  worker_ = std::async(std::launch::async, [file = files_[std::size_t(index)], rotation = rotationDegrees_,
                                            intensity = intensity_, prepare = prepare_] {
    return prepare(loadEnvironment({.file = file, .rotationDegrees = rotation, .intensity = intensity}));
  });
}

void EnvironmentSwitcher::request(int index) {
  if (index < 0 || index >= int(files_.size())) return;
  if (busy())
    queued_ = index;
  else
    start(index);
}

void EnvironmentSwitcher::requestFile(const fs::path& file) {
  auto found = std::find_if(files_.begin(), files_.end(), [&](const fs::path& listed) {
    std::error_code error;
    return fs::equivalent(listed, file, error);
  });
  if (found == files_.end()) found = files_.insert(files_.end(), file);
  request(int(found - files_.begin()));
}

void EnvironmentSwitcher::step(int direction) {
  if (files_.empty()) return;
  const int from = queued_ >= 0 ? queued_ : pending_ >= 0 ? pending_ : current_;
  const int count = int(files_.size());
  request(from < 0 ? (direction > 0 ? 0 : count - 1) : ((from + direction) % count + count) % count);
}

std::optional<EnvironmentStages> EnvironmentSwitcher::poll() {
  if (!busy() || worker_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
  std::optional<EnvironmentStages> result;
  const fs::path& file = files_[std::size_t(pending_)];
  try {
    result = worker_.get();
    current_ = pending_;
    status_ = file.filename().string();
  } catch (const std::exception& e) {
    status_ = e.what();
  }
  pending_ = -1;
  if (queued_ >= 0) {
    const int next = std::exchange(queued_, -1);
    if (next != current_) start(next);
  }
  return result;
}

std::optional<EnvironmentStages> EnvironmentSwitcher::waitForResult() {
  std::optional<EnvironmentStages> last;
  while (busy()) {
    worker_.wait();
    if (std::optional<EnvironmentStages> stages = poll()) last = std::move(stages);
  }
  return last;
}

}  // namespace iblkit
