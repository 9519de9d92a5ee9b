#include "report/pending_stages.h"

namespace iblkit {

void PendingStages::add(PendingStage stage) {
  stage.caseName = case_;
  if (!folders_.insert(stage.folderName()).second) return;
  stages_.push_back(std::move(stage));
}

std::vector<std::string> stageFoldersRead(const StageCommand& command) {
  std::vector<std::string> folders;
  const std::string prefix = std::string(kCacheFolder) + "/";
  for (const std::string& argument : command.arguments)
    if (argument.starts_with(prefix)) {
      const std::string rest = argument.substr(prefix.size());
      folders.push_back(rest.substr(0, rest.find('/')));
    }
  return folders;
}

}  // namespace iblkit
