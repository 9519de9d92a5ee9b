#include "cli/program.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>
#include <thread>

#include "core/error.h"
#include "core/image_io.h"
#include "core/temporary_files.h"
#include "core/usage_error.h"

namespace iblkit {

const char* const kExitStatusHelp =
    "Exit status: 0 success, 1 failure at run time (bad input file, I/O), 2 command-line usage "
    "error, 3 iblkit-report --strict: a claim does not hold.";

namespace {

// The lines of `message`, trimmed and joined by single spaces.
std::string foldedOntoOneLine(const std::string& message) {
  std::istringstream lines(message);
  std::string line, folded;
  while (std::getline(lines, line)) {
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    const std::size_t last = line.find_last_not_of(" \t\r");
    if (!folded.empty()) folded += ' ';
    folded += line.substr(first, last - first + 1);
  }
  return folded;
}

std::string joined(const std::vector<std::string>& names, const char* separator) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : separator) + name;
  return text;
}

// Gives every floating-point option of `app` and its subcommands the finiteNumber check, so that
// "nan", "inf" and "1e999" are usage errors in every program (CLI11 converts them otherwise).
void checkFloatOptionsAreFinite(CLI::App& app) {
  for (CLI::Option* option : app.get_options())
    if (option->get_type_name().find("FLOAT") != std::string::npos) option->check(finiteNumber());
  for (CLI::App* subcommand : app.get_subcommands([](CLI::App*) { return true; }))
    checkFloatOptionsAreFinite(*subcommand);
}

}  // namespace

CLI::Validator finiteNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        // The text CLI11 converts: std::strtold reads what its lexical_cast reads (nan, inf, hex).
        char* end = nullptr;
        const long double value = std::strtold(text.c_str(), &end);
        if (end == text.c_str()) return {};  // not a number: CLI11's conversion reports it
        if (!std::isfinite(value) || std::fabs(value) > std::numeric_limits<double>::max())
          return "must be a finite number, not '" + text + "'";
        return {};
      },
      "", "FINITE");
}

void printError(const std::string& program, const std::string& message) {
  std::cout.flush();
  // Control characters left inside a line (a carriage return or an escape sequence in an argument
  // CLI11 quotes) would split or rewrite the line on a terminal.
  std::string line = foldedOntoOneLine(message);
  for (char& c : line)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  std::cerr << program << ": " << line << '\n';
}

ThreadLimit::ThreadLimit(int threads) {
  if (threads <= 0) return;
  control_ = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                   static_cast<std::size_t>(threads));
  setExrThreads(threads);
}

ThreadLimit::~ThreadLimit() {
  if (control_) setExrThreads(static_cast<int>(std::thread::hardware_concurrency()));
}

int runProgram(CLI::App& app, int argc, const char* const* argv, const std::function<int()>& run) {
  const std::string program = app.get_name();
  app.footer(kExitStatusHelp);
  installInterruptCleanup();
  setExrThreads(static_cast<int>(std::thread::hardware_concurrency()));
  checkFloatOptionsAreFinite(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help: the help on stdout, status 0
  } catch (const CLI::ParseError& e) {
    printError(program, e.what());
    return kExitUsage;
  }
  try {
    return run();
  } catch (const UsageError& e) {
    printError(program, e.what());
    return kExitUsage;
  } catch (const std::filesystem::filesystem_error& e) {
    // "<path>: <reason>", as every other error names its file first.
    printError(program, (e.path1().empty() ? std::string("filesystem") : e.path1().string()) + ": " +
                            e.code().message());
    return kExitFailure;
  } catch (const std::exception& e) {
    printError(program, e.what());
    return kExitFailure;
  } catch (...) {
    printError(program, "unknown error");
    return kExitFailure;
  }
}

void addEnvironmentOptions(CLI::App& app, EnvironmentOverride& override) {
  app.add_option("--env", override.file, "environment map (default: the scene's)");
  app.add_option("--env-rotation", override.rotationDegrees,
                 "absolute environment rotation about +Y in degrees (replaces the scene's)");
  app.add_option("--env-intensity", override.intensity,
                 "environment radiance multiplier (replaces the scene's)");
}

void addForceOption(CLI::App& app, bool& force) {
  app.add_flag("--force", force, "replace an existing output folder even when it is not one this program wrote");
}

std::vector<std::filesystem::path> sceneInputs(const Scene& scene, const EnvironmentOverride& override) {
  std::vector<std::filesystem::path> inputs = {scene.file};
  inputs.insert(inputs.end(), scene.modelFiles.begin(), scene.modelFiles.end());
  inputs.push_back(overriddenEnvironment(scene.environment, override).file);
  return inputs;
}

CLI::Validator nameChoice(std::vector<std::string> names, std::string noun) {
  const std::string description = "{" + joined(names, ",") + "}";
  return CLI::Validator(
      [names = std::move(names), noun = std::move(noun)](std::string& text) -> std::string {
        if (std::find(names.begin(), names.end(), text) != names.end()) return {};
        return unknownNameProblem(noun, text, names);
      },
      description);
}

}  // namespace iblkit
