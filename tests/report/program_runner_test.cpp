#include "report/program_runner.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/error.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

TEST(ProgramRunner, CapturesOutputInTheLog) {
  const auto log = test::scratchDir() / "log.txt";
  const std::string output = runProgram({"/bin/sh", "-c", "echo out; echo err >&2"}, log);
  EXPECT_EQ(output, "out\nerr\n");
  std::ifstream stream(log);
  std::stringstream text;
  text << stream.rdbuf();
  EXPECT_EQ(text.str(), "$ /bin/sh -c 'echo out; echo err >&2'\nout\nerr\n");
}

TEST(ProgramRunner, FailureNamesTheProgramStatusAndLastLine) {
  const auto log = test::scratchDir() / "log.txt";
  try {
    runProgram({"/bin/sh", "-c", "echo working; echo 'scene.json: broken' >&2; exit 3"}, log);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "/bin/sh: exited with status 3: scene.json: broken (log: " + log.string() + ")");
  }
  try {
    runProgram({"/nonexistent/iblkit-view"}, log);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/iblkit-view: cannot run: No such file or directory");
  }
}

TEST(ProgramRunner, CommandLineQuotesWhatAShellWouldSplit) {
  EXPECT_EQ(commandLine({"iblkit-trace", "a b.json", "--spp", "16", ""}), "iblkit-trace 'a b.json' --spp 16 ''");
  // A quote inside is closed, escaped and reopened, so the line still pastes into a shell.
  EXPECT_EQ(commandLine({"iblkit-trace", "it's.json"}), "iblkit-trace 'it'\\''s.json'");
  EXPECT_EQ(shellQuoted("/a b/x"), "'/a b/x'");
}

}  // namespace
}  // namespace iblkit
