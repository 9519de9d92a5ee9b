// The scaffold of every program (cli/program.h): --help exits 0, a command-line error is one
// stderr line "PROGRAM: message" and status 2, a run-time exception of any kind one line and 1.
#include "cli/program.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/usage_error.h"

namespace iblkit {
namespace {

struct Outcome {
  int status = -1;
  std::string out, err;
  bool ran = false;
};

// Runs a program "test-program" with one integer option --count (1..9) and a --kind choice over
// `arguments`, whose run function is `run`.
Outcome runTestProgram(
    std::vector<std::string> arguments, const std::function<int()>& run = [] { return 0; }) {
  enum class Kind { Small, Large };
  static constexpr EnumName<Kind> kKinds[] = {{Kind::Small, "small"}, {Kind::Large, "large"}};
  CLI::App app{"A program for the test.", "test-program"};
  int count = 1;
  std::string kind = "small";
  double scale = 1.0;
  std::vector<double> range;
  app.add_option("--scale", scale, "a scale");
  app.add_option("--range", range, "two numbers")->expected(2);
  app.add_option("--count", count, "a count")->check(CLI::Range(1, 9));
  app.add_option("--kind", kind, "a kind")->check(nameChoice(kKinds, "kind"));
  arguments.insert(arguments.begin(), "test-program");
  std::vector<const char*> argv;
  for (const std::string& argument : arguments) argv.push_back(argument.c_str());
  Outcome outcome;
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  outcome.status = runProgram(app, int(argv.size()), argv.data(), [&] {
    outcome.ran = true;
    return run();
  });
  outcome.out = testing::internal::GetCapturedStdout();
  outcome.err = testing::internal::GetCapturedStderr();
  return outcome;
}

TEST(Program, HelpPrintsTheHelpAndTheExitStatusesAndExitsZero) {
  const Outcome help = runTestProgram({"--help"});
  EXPECT_EQ(help.status, kExitSuccess);
  EXPECT_FALSE(help.ran);
  EXPECT_NE(help.out.find("Usage: test-program"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("{small,large}"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find(kExitStatusHelp), std::string::npos) << help.out;
  EXPECT_EQ(help.err, "");
}

TEST(Program, AParseErrorIsOneLineWithTheProgramNameAndStatusTwo) {
  const std::pair<std::vector<std::string>, std::string> cases[] = {
      {{"--frobnicate"}, "test-program: The following argument was not expected: --frobnicate\n"},
      {{"--count", "x"}, "test-program: --count: Value x not in range 1 to 9\n"},
      {{"--count", "10"}, "test-program: --count: Value 10 not in range 1 to 9\n"},
      {{"--kind", "medium"}, "test-program: --kind: unknown kind 'medium' (expected one of small, large)\n"},
      // Every FLOAT option is finite (runProgram adds finiteNumber), vectors of them included.
      {{"--scale", "nan"}, "test-program: --scale: must be a finite number, not 'nan'\n"},
      {{"--scale", "-inf"}, "test-program: --scale: must be a finite number, not '-inf'\n"},
      {{"--scale", "1e999"}, "test-program: --scale: must be a finite number, not '1e999'\n"},
      {{"--range", "0", "nan"}, "test-program: --range: must be a finite number, not 'nan'\n"},
      // A carriage return or escape inside an argument cannot split or rewrite the line.
      {{"--bad\rarg\x1b[2K"}, "test-program: The following argument was not expected: --bad?arg?[2K\n"},
  };
  for (const auto& [arguments, expected] : cases) {
    const Outcome outcome = runTestProgram(arguments);
    EXPECT_EQ(outcome.status, kExitUsage) << expected;
    EXPECT_EQ(outcome.err, expected);
    EXPECT_FALSE(outcome.ran) << expected;
  }
}

TEST(Program, AUsageErrorFromTheRunFunctionIsStatusTwo) {
  const Outcome outcome = runTestProgram({}, [] {
    failUsage("--count", "needs --kind large");
    return 0;
  });
  EXPECT_EQ(outcome.status, kExitUsage);
  EXPECT_EQ(outcome.err, "test-program: --count: needs --kind large\n");
}

TEST(Program, EveryOtherExceptionIsOneLineAndStatusOne) {
  const std::pair<std::function<int()>, std::string> cases[] = {
      {[]() -> int { fail("scene.json", "cannot read file"); },
       "test-program: scene.json: cannot read file\n"},
      {[]() -> int { throw std::invalid_argument("stof"); }, "test-program: stof\n"},
      {[]() -> int { throw Error("first line\n  second line\n"); }, "test-program: first line second line\n"},
      {[]() -> int { throw 42; }, "test-program: unknown error\n"},
      // A filesystem error names its path first, like every other error (crash 4 of issue 13).
      {[]() -> int {
         std::filesystem::create_directories("/dev/null/out");
         return 0;
       },
       "test-program: /dev/null/out: Not a directory\n"},
  };
  for (const auto& [run, expected] : cases) {
    const Outcome outcome = runTestProgram({"--count", "3"}, run);
    EXPECT_TRUE(outcome.ran);
    EXPECT_EQ(outcome.status, kExitFailure) << expected;
    EXPECT_EQ(outcome.err, expected);
  }
}

TEST(Program, TheRunFunctionsStatusIsTheProgramsStatus) {
  EXPECT_EQ(runTestProgram({}, [] { return kExitClaimFails; }).status, kExitClaimFails);
  EXPECT_EQ(runTestProgram({"--kind", "large"}).status, kExitSuccess);
}

}  // namespace
}  // namespace iblkit
