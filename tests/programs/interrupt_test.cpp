// End-to-end: SIGINT or SIGTERM at random points during a bake, a trace and a report leave no
// partial output and no temporary behind (issue 13, point 5): the real programs are started on a
// small generated scene and killed after a random delay (seeded; the delays are printed), several
// times each. The output must then be absent or complete, and a report rerun after the
// interrupts must finish and give the numbers of an uninterrupted run.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "core/gltf_load.h"
#include "core/image_io.h"
#include "support/small_scene.h"
#include "support/test_paths.h"

extern char** environ;

namespace iblkit {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Ended {
  bool signalled = false;
  int code = -1;  // the exit status, or the signal
};

// Starts `program` with `arguments` (output into `log`), sends `signal` after `delay` seconds
// unless it ended before, and waits for it.
Ended runAndInterrupt(const std::string& program, const std::vector<std::string>& arguments, double delay,
                      int signal, const fs::path& log) {
  std::vector<std::string> argv = {(test::binDir() / program).string()};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  std::vector<char*> pointers;
  for (std::string& argument : argv) pointers.push_back(argument.data());
  pointers.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0].c_str(), &actions, nullptr, pointers.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  EXPECT_EQ(spawned, 0) << argv[0];
  if (spawned != 0) return {};
  int status = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(delay);
  bool sent = false;
  while (true) {
    const pid_t done = waitpid(pid, &status, sent ? 0 : WNOHANG);
    if (done == pid) break;
    if (!sent && std::chrono::steady_clock::now() >= deadline) {
      kill(pid, signal);
      sent = true;
      continue;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return WIFSIGNALED(status) ? Ended{true, WTERMSIG(status)} : Ended{false, WEXITSTATUS(status)};
}

double secondsOf(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Paths under `folder` (recursively) whose names hold ".tmp" or ".old-": temporaries left behind.
std::vector<std::string> leftovers(const fs::path& folder) {
  std::vector<std::string> found;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name.find(".tmp") != std::string::npos || name.find(".old-") != std::string::npos)
      found.push_back(entry.path().string());
  }
  return found;
}

// The delays of `tries` interrupts, spread over [0, 1.1 * seconds] by a seeded generator.
std::vector<double> delays(double seconds, int tries, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.1 * seconds);
  std::vector<double> result;
  for (int i = 0; i < tries; ++i) result.push_back(uniform(random));
  return result;
}

constexpr int kTries = 5;
constexpr unsigned kSeed = 13;

void expectEnded(const Ended& ended, int signal, const std::string& what) {
  std::printf("%s: %s %d\n", what.c_str(), ended.signalled ? "killed by signal" : "exited", ended.code);
  EXPECT_TRUE((ended.signalled && ended.code == signal) || (!ended.signalled && ended.code == 0))
      << what << ": signalled " << ended.signalled << ", code " << ended.code;
}

TEST(Interrupt, BakeLeavesTheOldFolderOrTheNewOneWhole) {
  const fs::path root = test::scratchDir();
  const test::SmallScene small = test::writeSmallScene(root);
  const fs::path out = root / "bake";
  const std::vector<std::string> arguments = {small.scene.string(), "-o", out.string(), "--ao-rays", "4000",
                                              "--specular-samples", "64", "--lut-size", "32"};
  Ended first;
  const double seconds = secondsOf([&] { first = runAndInterrupt("iblkit-bake", arguments, 1e9, SIGTERM, root / "log"); });
  ASSERT_FALSE(first.signalled);
  ASSERT_EQ(first.code, 0) << test::fileBytes(root / "log");
  int index = 0;
  for (const double delay : delays(seconds, kTries, kSeed)) {
    const int signal = index++ % 2 ? SIGINT : SIGTERM;
    const std::string what = "bake interrupted after " + std::to_string(delay) + " s by signal " + std::to_string(signal);
    SCOPED_TRACE(what);
    expectEnded(runAndInterrupt("iblkit-bake", arguments, delay, signal, root / "log"), signal, what);
    // The earlier bake or the new one, whole.
    ASSERT_TRUE(fs::is_regular_file(out / "bake.json"));
    std::ifstream record(out / "bake.json");
    EXPECT_EQ(json::parse(record)["version"], "iblkit-bake 1");
    EXPECT_NO_THROW(loadGltf(out / "scene.glb"));
    EXPECT_NO_THROW(readExr(out / "env" / "specular.exr"));
    EXPECT_EQ(leftovers(root), std::vector<std::string>());
  }
}

// Large images at 1 spp: writing the five images takes a good part of the run, so that some
// interrupts fall while they are written.
TEST(Interrupt, TraceLeavesNoPartialImage) {
  const fs::path root = test::scratchDir();
  const test::SmallScene small = test::writeSmallScene(root);
  const fs::path out = root / "out.exr", png = root / "out.png";
  const std::vector<fs::path> images = {out, png, root / "albedo.exr", root / "normal.exr", root / "depth.exr"};
  const std::vector<std::string> arguments = {
      small.scene.string(), "-o", out.string(), "--png", png.string(), "--albedo", images[2].string(),
      "--normal", images[3].string(), "--depth", images[4].string(), "--spp", "1", "--width", "800", "--height", "600"};
  Ended first;
  const double seconds = secondsOf([&] { first = runAndInterrupt("iblkit-trace", arguments, 1e9, SIGTERM, root / "log"); });
  ASSERT_EQ(first.code, 0) << test::fileBytes(root / "log");
  int index = 0;
  for (const double delay : delays(seconds, 2 * kTries, kSeed + 1)) {
    const int signal = index++ % 2 ? SIGINT : SIGTERM;
    const std::string what = "trace interrupted after " + std::to_string(delay) + " s by signal " + std::to_string(signal);
    SCOPED_TRACE(what);
    // Half the tries start with no earlier images.
    if (index % 2)
      for (const fs::path& image : images) fs::remove(image);
    expectEnded(runAndInterrupt("iblkit-trace", arguments, delay, signal, root / "log"), signal, what);
    for (const fs::path& image : images) {
      if (fs::exists(image)) {
        EXPECT_EQ(image == png ? readImage(image).width() : readExr(image).width(), 800) << image;
      }
    }
    EXPECT_EQ(leftovers(root), std::vector<std::string>());
  }
}

std::vector<std::string> reportArguments(const test::SmallScene& small, const fs::path& out) {
  return {small.scene.string(), "--envs",       small.map.string(), "--bin",        test::binDir().string(),
          "--width",            "16",           "--height",         "12",           "--pass-spp",
          "4",                  "--min-passes", "2",                "--max-passes", "2",
          "--bench",            "0",            "--modes",          "sh,full",      "-o",
          out.string()};
}

json readJson(const fs::path& file) {
  std::ifstream stream(file);
  return json::parse(stream);
}

TEST(Interrupt, ReportRerunsAfterInterruptsToTheUninterruptedNumbers) {
  const fs::path root = test::scratchDir();
  const test::SmallScene small = test::writeSmallScene(root);
  Ended first;
  const double seconds = secondsOf([&] {
    first = runAndInterrupt("iblkit-report", reportArguments(small, root / "whole"), 1e9, SIGTERM, root / "log");
  });
  ASSERT_EQ(first.code, 0) << test::fileBytes(root / "log");
  const json whole = readJson(root / "whole" / "report.json");

  const fs::path out = root / "interrupted";
  int index = 0;
  for (const double delay : delays(seconds, kTries, kSeed + 2)) {
    const int signal = index++ % 2 ? SIGINT : SIGTERM;
    const std::string what = "report interrupted after " + std::to_string(delay) + " s by signal " + std::to_string(signal);
    SCOPED_TRACE(what);
    // Each try but the last starts afresh; the last leaves what it had cached for the rerun.
    if (index < kTries) fs::remove_all(out);
    expectEnded(runAndInterrupt("iblkit-report", reportArguments(small, out), delay, signal, root / "log"), signal,
                what);
    if (fs::exists(out)) {
      EXPECT_EQ(leftovers(out), std::vector<std::string>());
      if (fs::exists(out / "report.json")) {
        EXPECT_NO_THROW(readJson(out / "report.json"));
      }
    }
  }
  const Ended last = runAndInterrupt("iblkit-report", reportArguments(small, out), 1e9, SIGTERM, root / "log");
  ASSERT_FALSE(last.signalled);
  ASSERT_EQ(last.code, 0) << test::fileBytes(root / "log");
  const json again = readJson(out / "report.json");
  ASSERT_EQ(again["cases"].size(), whole["cases"].size());
  for (std::size_t c = 0; c < whole["cases"].size(); ++c) {
    EXPECT_EQ(again["cases"][c]["reference"], whole["cases"][c]["reference"]);
    EXPECT_EQ(again["cases"][c]["modes"].size(), whole["cases"][c]["modes"].size());
    for (std::size_t m = 0; m < whole["cases"][c]["modes"].size(); ++m)
      EXPECT_EQ(again["cases"][c]["modes"][m]["meanFlip"], whole["cases"][c]["modes"][m]["meanFlip"]);
  }
  EXPECT_EQ(leftovers(out), std::vector<std::string>());
}

}  // namespace
}  // namespace iblkit
