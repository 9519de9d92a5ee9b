#pragma once
// The scaffold every program's main runs through (programs/, bench/sampling_study.cpp): CLI11
// parses the command line, `--help` prints the help and exits 0, and every error, the parser's
// included, is one line "PROGRAM: message" on stderr with one exit status table for all programs.

#include <tbb/global_control.h>

#include <CLI/CLI.hpp>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/enum_names.h"
#include "core/output_path.h"
#include "core/scene.h"
#include "core/scene_environment.h"

namespace iblkit {

// The exit status of every program (README.md, "Exit codes").
enum ExitStatus : int {
  kExitSuccess = 0,
  kExitFailure = 1,     // failed at run time: a bad input file, I/O
  kExitUsage = 2,       // the command line: an unknown option, a bad or missing value
  kExitClaimFails = 3,  // iblkit-report --strict: a claim does not hold
};

// The most worker threads --threads takes (iblkit-bake, iblkit-trace): TBB crashes on an arena of
// 70,000 threads, and no machine iblkit runs on has more than this many cores.
inline constexpr int kMaxThreads = 1024;

// The table above as --help prints it (the footer runProgram gives every program).
extern const char* const kExitStatusHelp;

// Parses `argv` with `app` (whose name is the program's) and returns run()'s status. A parse
// error or a UsageError exits kExitUsage, any other exception kExitFailure, each after one line
// on stderr. Before parsing it installs the interrupt cleanup (core/temporary_files.h): SIGINT or
// SIGTERM removes every temporary of the atomic writes and ends the program by that signal, so
// an interrupted program leaves no partial output. It also gives OpenEXR the machine's cores
// (setExrThreads, core/image_io.h). Each program declares what it reads and
// writes with checkOutputs (core/output_path.h) before it writes anything; a refused output is a
// run-time failure (kExitFailure), as it depends on what is on disk, not on the command line.
int runProgram(CLI::App& app, int argc, const char* const* argv, const std::function<int()>& run);

// Limits every parallel part of the program, TBB's worker threads and OpenEXR's (setExrThreads), to
// `threads` for the object's lifetime; 0 leaves every core (runProgram's default). For --threads
// of iblkit-bake and iblkit-trace, whose set-up (the map's tables, ground visibility) runs in
// parallel before the render's own arena.
class ThreadLimit {
 public:
  explicit ThreadLimit(int threads);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

 private:
  std::unique_ptr<tbb::global_control> control_;
};

// A CLI11 check that refuses NaN and infinite numbers (and those beyond double's range).
// runProgram gives it to every option whose type is FLOAT, the options of subcommands included.
CLI::Validator finiteNumber();

// Prints "PROGRAM: message" on stderr, a multi-line message folded onto the one line and any
// other control character (a carriage return inside a line, an escape) printed as '?'.
void printError(const std::string& program, const std::string& message);

// A CLI11 check that accepts only `names`: the help lists them as {a,b,c}, anything else fails
// with "<option>: unknown <noun> 'x' (expected one of a, b, c)", the wording of parseEnumName.
CLI::Validator nameChoice(std::vector<std::string> names, std::string noun);

template <class E, std::size_t N>
CLI::Validator nameChoice(const EnumName<E> (&table)[N], std::string noun) {
  return nameChoice(enumNames(table), std::move(noun));
}

// A string option `name` that takes only the names of `table` (nameChoice with `noun`); the help
// shows the choices, the default and `description` (empty: the noun).
template <class E, std::size_t N>
CLI::Option* addNameOption(CLI::App& app, const std::string& name, std::string& value,
                           const EnumName<E> (&table)[N], const std::string& noun,
                           const std::string& description = {}) {
  return app.add_option(name, value, description.empty() ? noun : description)
      ->check(nameChoice(table, noun))
      ->capture_default_str();
}

// --env FILE, --env-rotation DEGREES and --env-intensity X into `override`, with one wording in
// every program that takes them (docs/conventions.md: each replaces the scene's).
void addEnvironmentOptions(CLI::App& app, EnvironmentOverride& override);

// --force: an existing output folder that is not of the program's kind may be replaced
// (checkOutputs' `force`).
void addForceOption(CLI::App& app, bool& force);

// The files a loaded scene was read from: the scene file, its models and its environment map
// (the override's, when it names one): the inputs an output must not replace.
std::vector<std::filesystem::path> sceneInputs(const Scene& scene, const EnvironmentOverride& override = {});

}  // namespace iblkit
