#pragma once
// The report's cache of finished stages (bakes, reference passes, engine frames): each stage's
// output is a folder <root>/<name>-<key>, where the key hashes everything the output depends on
// (content_hash.h). A stage is produced in a temporary folder beside it and renamed only when it
// is complete, so an interrupted run never leaves a half-written stage that a later run trusts.

#include <filesystem>
#include <functional>
#include <string>

namespace iblkit {

class PendingStages;

class StageCache {
 public:
  explicit StageCache(std::filesystem::path root);

  // The folder of stage `name` with `key`. When it does not exist yet, `produce` is called with an
  // empty temporary folder to fill, which then becomes the stage's folder. `hit` (optional) says
  // whether the stage was already cached. Errors thrown by `produce` propagate, and the temporary
  // folder is removed.
  std::filesystem::path stage(const std::string& name, const std::string& key,
                              const std::function<void(const std::filesystem::path&)>& produce,
                              bool* hit = nullptr) const;

  // The folder stage `name` with `key` has in the cache, whether or not it exists yet.
  std::filesystem::path folder(const std::string& name, const std::string& key) const {
    return root_ / (name + "-" + key);
  }

  // From now on runStage (stage_run.h) adds each stage it does not find to `pending` instead of
  // running it (nullptr: runs them again), for a scheduler to run elsewhere (pending_stages.h).
  void collectInto(PendingStages* pending) { pending_ = pending; }
  PendingStages* collecting() const { return pending_; }

  const std::filesystem::path& root() const { return root_; }
  int hits() const { return hits_; }      // stages found in the cache so far
  int misses() const { return misses_; }  // stages produced so far

 private:
  std::filesystem::path root_;
  mutable int hits_ = 0, misses_ = 0;
  PendingStages* pending_ = nullptr;
};

}  // namespace iblkit
