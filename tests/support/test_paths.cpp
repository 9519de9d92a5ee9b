#include "support/test_paths.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>

namespace iblkit::test {

namespace {
std::filesystem::path fromEnv(const char* name, const char* fallback) {
  const char* value = std::getenv(name);
  return value ? std::filesystem::path(value) : std::filesystem::path(fallback);
}
}  // namespace

std::filesystem::path dataDir() { return fromEnv("IBLKIT_TEST_DATA", IBLKIT_TEST_DATA_DEFAULT); }
std::filesystem::path assetsDir() { return fromEnv("IBLKIT_ASSETS", IBLKIT_ASSETS_DEFAULT); }
std::filesystem::path binDir() { return fromEnv("IBLKIT_BIN", IBLKIT_BIN_DEFAULT); }

std::filesystem::path scratchDir() {
  const testing::TestInfo* info = testing::UnitTest::GetInstance()->current_test_info();
  std::string name = "iblkit-test";
  if (info) name += std::string("-") + info->test_suite_name() + "-" + info->name();
  for (char& c : name)
    if (c == '/') c = '_';
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string shellQuoted(const std::filesystem::path& path) {
  // Built by appending: GCC 12 warns falsely (-Wrestrict, its bug 105329) on "'" + std::string.
  std::string text = "'";
  text += path.string();
  text += "'";
  return text;
}

int runCommand(const std::string& command, std::string* output) {
  // Grouped, so redirections inside `command` apply first and the rest of stderr joins stdout.
  FILE* pipe = popen(("{ " + command + "; } 2>&1").c_str(), "r");
  if (!pipe) return -1;
  std::array<char, 4096> buffer{};
  std::string text;
  while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe)) text += buffer.data();
  const int status = pclose(pipe);
  if (output) *output = text;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace iblkit::test
