#pragma once
// The command of one cached stage of the report, and the stage's cache key hashed from it, so
// that what runs and what the key says ran cannot drift apart (docs/report.md).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace iblkit {

// Stands for the stage's output folder at the start of an argument ("{stage}/frame.exr"). The
// folder is a temporary one whose name changes from run to run, so the key hashes this instead.
inline constexpr std::string_view kStageFolder = "{stage}";
// Stands for the cache's folder at the start of an argument naming another stage's output
// ("{cache}/bake-sphere-sky-0123.../bake"), so that a cache moved or given elsewhere keeps its keys.
inline constexpr std::string_view kCacheFolder = "{cache}";

struct StageCommand {
  std::filesystem::path program;       // argv[0]
  std::vector<std::string> arguments;  // argv[1...]; paths may start with kStageFolder, kCacheFolder
  // Files the program reads that its arguments do not name, or whose bytes may change under the
  // same name (a scene's model files, the scene itself). Another stage's folder needs no entry: its
  // name holds that stage's key.
  std::vector<std::filesystem::path> inputFiles;
};

// The argument vector that runs: program, then the arguments with kStageFolder replaced by `folder`
// and kCacheFolder by `cache`.
std::vector<std::string> stageArgv(const StageCommand& command, const std::filesystem::path& cache,
                                   const std::filesystem::path& folder);

// The stage's cache key (content_hash.h): the argument vector with both folders left as placeholders,
// the program binary's bytes (a rebuilt program invalidates its stages) and the input files' bytes.
std::string stageKey(const StageCommand& command);

}  // namespace iblkit
