#include "report/stage_command.h"

#include "core/content_hash.h"

namespace iblkit {

namespace fs = std::filesystem;

namespace {

std::string replacedPrefix(const std::string& argument, std::string_view placeholder,
                           const fs::path& folder) {
  return folder.string() + argument.substr(placeholder.size());
}

}  // namespace

std::vector<std::string> stageArgv(const StageCommand& command, const fs::path& cache,
                                   const fs::path& folder) {
  std::vector<std::string> argv = {command.program.string()};
  for (const std::string& argument : command.arguments) {
    if (argument.starts_with(kStageFolder))
      argv.push_back(replacedPrefix(argument, kStageFolder, folder));
    else if (argument.starts_with(kCacheFolder))
      argv.push_back(replacedPrefix(argument, kCacheFolder, cache));
    else
      argv.push_back(argument);
  }
  return argv;
}

std::string stageKey(const StageCommand& command) {
  ContentHash hash;
  for (const std::string& argument : stageArgv(command, std::string(kCacheFolder), std::string(kStageFolder)))
    hash.add(argument);
  hash.addFile(command.program);
  for (const fs::path& file : command.inputFiles) hash.add(file.string()).addFile(file);
  return hash.hex();
}

}  // namespace iblkit
