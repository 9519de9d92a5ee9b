#pragma once
// Where tests find committed data (tests/data), the fetched assets and the built programs: the
// paths of the build tree that compiled the tests, or the environment variables IBLKIT_TEST_DATA,
// IBLKIT_ASSETS and IBLKIT_BIN when set.

#include <filesystem>
#include <string>

namespace iblkit::test {

std::filesystem::path dataDir();    // tests/data
std::filesystem::path assetsDir();  // assets (hdri/, models/, scenes/)
std::filesystem::path binDir();     // build/bin
// A fresh, empty folder under the system temp dir, unique to the running test.
std::filesystem::path scratchDir();

// `path` single-quoted for a shell command line.
std::string shellQuoted(const std::filesystem::path& path);

// Runs a shell command, returns its exit status, captures stdout+stderr into *output.
int runCommand(const std::string& command, std::string* output);

}  // namespace iblkit::test
