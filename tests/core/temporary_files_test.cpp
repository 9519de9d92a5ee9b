// The temporaries of the atomic writes (core/temporary_files.h): unique names, the permissions of
// an ordinary new file, and SIGINT / SIGTERM removing every registered temporary (and putting a
// previous output moved aside back) before the process ends by that signal. The interrupt cases
// run in a forked child that the test signals.
#include "core/temporary_files.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>
#include <thread>

#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

TEST(TemporaryFiles, NamesAreUniqueAndFilesHaveTheUmaskPermissions) {
  const fs::path target = test::scratchDir() / "out.exr";
  const fs::path a = createTemporaryFile(target), b = createTemporaryFile(target);
  EXPECT_NE(a, b);
  EXPECT_EQ(a.string().rfind(target.string() + ".tmp-", 0), 0u);
  const mode_t mask = ::umask(0);
  ::umask(mask);
  struct stat info {};
  ASSERT_EQ(::stat(a.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0666 & ~mask);
  discardTemporary(a);
  discardTemporary(b);
  EXPECT_FALSE(fs::exists(a));
  const fs::path folder = createTemporaryFolder(target, ".tmp-");
  EXPECT_TRUE(fs::is_directory(folder));
  discardTemporary(folder);
  EXPECT_FALSE(fs::exists(folder));
}

// Forks a child that installs the cleanup, makes the temporaries of `prepare` and waits; the
// parent sends `signal` once the child says it is ready. Returns the child's wait status.
int interruptChild(int signal, const std::function<void()>& prepare) {
  int ready[2];
  EXPECT_EQ(::pipe(ready), 0);
  const pid_t pid = ::fork();
  if (pid == 0) {
    installInterruptCleanup();
    prepare();
    const char byte = 1;
    (void)!::write(ready[1], &byte, 1);
    for (;;) ::pause();
  }
  char byte = 0;
  EXPECT_EQ(::read(ready[0], &byte, 1), 1);
  ::close(ready[0]);
  ::close(ready[1]);
  ::kill(pid, signal);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

TEST(TemporaryFiles, AnInterruptRemovesEveryTemporaryAndEndsByTheSignal) {
  const fs::path root = test::scratchDir();
  for (const int signal : {SIGINT, SIGTERM}) {
    const int status = interruptChild(signal, [&] {
      const fs::path file = createTemporaryFile(root / "image.exr");
      std::ofstream(file) << "half";
      const fs::path folder = createTemporaryFolder(root / "bake", ".tmp-");
      fs::create_directories(folder / "env");
      std::ofstream(folder / "env" / "sh9.json") << "{";
    });
    EXPECT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(WTERMSIG(status), signal);
    EXPECT_TRUE(fs::is_empty(root)) << fs::directory_iterator(root)->path();
  }
}

TEST(TemporaryFiles, AnInterruptPutsAPreviousOutputBack) {
  const fs::path root = test::scratchDir();
  const int status = interruptChild(SIGTERM, [&] {
    // The moment between moving the previous output aside and renaming the new one into place.
    fs::create_directories(root / "bake.old-x");
    std::ofstream(root / "bake.old-x" / "bake.json") << "{}";
    registerTemporary(root / "bake.old-x", root / "bake");
  });
  EXPECT_TRUE(WIFSIGNALED(status));
  EXPECT_TRUE(fs::is_regular_file(root / "bake" / "bake.json"));
  EXPECT_FALSE(fs::exists(root / "bake.old-x"));
}

}  // namespace
}  // namespace iblkit
