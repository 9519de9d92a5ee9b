#include "core/temporary_files.h"

#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "core/error.h"

namespace iblkit {

namespace fs = std::filesystem;

namespace {

struct Temporary {
  fs::path path, restoreTo;
};

// Never destroyed: the cleanup thread may use it while the program exits.
struct Registry {
  std::recursive_mutex mutex;
  std::vector<Temporary> temporaries;
  std::vector<pid_t> children;
};

Registry& registry() {
  static Registry* instance = new Registry;
  return *instance;
}

mode_t currentUmask() {
  static const mode_t mask = [] {
    const mode_t old = ::umask(022);
    ::umask(old);
    return old;
  }();
  return mask;
}

// Removes `path` and everything in it; retried, since a thread still running may be creating a
// file inside a folder being removed.
void removeCompletely(const fs::path& path) {
  std::error_code error;
  for (int attempt = 0; attempt < 20; ++attempt) {
    fs::remove_all(path, error);
    if (!fs::exists(fs::symlink_status(path, error))) return;
  }
}

void stopChildren(const std::vector<pid_t>& children) {
  for (const pid_t pid : children) ::kill(pid, SIGTERM);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  std::vector<pid_t> running = children;
  while (!running.empty()) {
    std::erase_if(running, [](pid_t pid) {
      int status = 0;
      const pid_t done = ::waitpid(pid, &status, WNOHANG);
      return done == pid || (done < 0 && errno != EINTR);
    });
    if (running.empty()) break;
    if (std::chrono::steady_clock::now() > deadline) {
      for (const pid_t pid : running) ::kill(pid, SIGKILL);
      for (const pid_t pid : running) ::waitpid(pid, nullptr, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

sigset_t interruptSignals() {
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  return signals;
}

[[noreturn]] void cleanUpAndDie(int signal) {
  Registry& r = registry();
  r.mutex.lock();  // never unlocked: no temporary is made or renamed from now on
  stopChildren(r.children);
  for (auto it = r.temporaries.rbegin(); it != r.temporaries.rend(); ++it) {
    std::error_code error;
    if (!it->restoreTo.empty() && !fs::exists(fs::symlink_status(it->restoreTo, error))) {
      fs::rename(it->path, it->restoreTo, error);
      if (!error) continue;
    }
    removeCompletely(it->path);
  }
  std::signal(signal, SIG_DFL);
  const sigset_t signals = interruptSignals();
  pthread_sigmask(SIG_UNBLOCK, &signals, nullptr);
  std::raise(signal);
  std::_Exit(128 + signal);
}

}  // namespace

fs::path createTemporaryFile(const fs::path& target) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  std::string name = target.string() + ".tmp-XXXXXX";
  const int fd = ::mkstemp(name.data());
  if (fd < 0) fail(target, std::string("cannot create a temporary file beside it: ") + std::strerror(errno));
  ::fchmod(fd, 0666 & ~currentUmask());
  ::close(fd);
  r.temporaries.push_back({name, {}});
  return name;
}

fs::path createTemporaryFolder(const fs::path& target, const char* suffix) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  std::string name = target.string() + suffix + "XXXXXX";
  if (!::mkdtemp(name.data()))
    fail(target, std::string("cannot create a folder beside it: ") + std::strerror(errno));
  r.temporaries.push_back({name, {}});
  return name;
}

void registerTemporary(const fs::path& path, const fs::path& restoreTo) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  r.temporaries.push_back({path, restoreTo});
}

void unregisterTemporary(const fs::path& path) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  std::erase_if(r.temporaries, [&](const Temporary& t) { return t.path == path; });
}

void discardTemporary(const fs::path& path) {
  std::error_code error;
  fs::remove_all(path, error);
  unregisterTemporary(path);
}

void withTemporariesLocked(const std::function<void()>& change) {
  const std::lock_guard lock(registry().mutex);
  change();
}

void registerChildProcess(pid_t pid) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  r.children.push_back(pid);
}

void unregisterChildProcess(pid_t pid) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  std::erase(r.children, pid);
}

void installInterruptCleanup() {
  static std::once_flag once;
  std::call_once(once, [] {
    currentUmask();
    registry();
    const sigset_t signals = interruptSignals();
    pthread_sigmask(SIG_BLOCK, &signals, nullptr);
    std::thread([signals] {
      int signal = 0;
      while (sigwait(&signals, &signal) != 0) {
      }
      cleanUpAndDie(signal);
    }).detach();
  });
}

}  // namespace iblkit
