#include "support/usage_error_check.h"

#include <gtest/gtest.h>

#include "support/test_paths.h"

namespace iblkit::test {

void expectUsageError(const std::string& command, const std::string& line) {
  std::string stderrText;
  // runCommand captures both streams: stdout is dropped so that only stderr is compared.
  EXPECT_EQ(runCommand(command + " 2>&1 >/dev/null", &stderrText), 2) << command;
  EXPECT_EQ(stderrText, line + "\n") << command;
}

}  // namespace iblkit::test
