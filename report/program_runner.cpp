#include "report/program_runner.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/temporary_files.h"

extern char** environ;

namespace iblkit {

namespace fs = std::filesystem;

std::string commandLine(const std::vector<std::string>& argv) {
  std::string line;
  for (const std::string& argument : argv) {
    if (!line.empty()) line += ' ';
    const bool quote = argument.empty() || argument.find_first_of(" \t'\"$") != std::string::npos;
    line += quote ? shellQuoted(argument) : argument;
  }
  return line;
}

std::string shellQuoted(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string runProgram(const std::vector<std::string>& argv, const fs::path& log) {
  if (argv.empty()) fail("runProgram", "no program given");
  std::error_code error;
  {
    std::ofstream header(log, std::ios::app);
    if (!header) fail(log, "cannot write file");
    header << "$ " << commandLine(argv) << '\n';
  }
  const std::uintmax_t outputStart = fs::file_size(log, error);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_APPEND | O_CREAT, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  std::vector<char*> arguments;
  for (const std::string& argument : argv) arguments.push_back(const_cast<char*>(argument.c_str()));
  arguments.push_back(nullptr);
  // The child starts with no signal blocked (runProgram blocks SIGINT and SIGTERM for its
  // interrupt cleanup), and an interrupt of this program stops it before removing its folder.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
  pid_t pid = 0;
  int spawned = 0;
  withTemporariesLocked([&] {
    spawned = posix_spawn(&pid, argv[0].c_str(), &actions, &attributes, arguments.data(), environ);
    if (spawned == 0) registerChildProcess(pid);
  });
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) fail(argv[0], std::string("cannot run: ") + std::strerror(spawned));

  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) {
      unregisterChildProcess(pid);
      fail(argv[0], std::string("cannot wait for it: ") + std::strerror(errno));
    }
  unregisterChildProcess(pid);

  std::ifstream stream(log, std::ios::binary);
  stream.seekg(std::streamoff(outputStart));
  std::ostringstream output;
  output << stream.rdbuf();
  const std::string text = output.str();

  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return text;
  std::string lastLine = text;
  while (!lastLine.empty() && lastLine.back() == '\n') lastLine.pop_back();
  lastLine = lastLine.substr(lastLine.find_last_of('\n') == std::string::npos ? 0 : lastLine.find_last_of('\n') + 1);
  const std::string how = WIFEXITED(status) ? "exited with status " + std::to_string(WEXITSTATUS(status))
                                            : "was killed by signal " + std::to_string(WTERMSIG(status));
  fail(argv[0], how + (lastLine.empty() ? "" : ": " + lastLine) + " (log: " + log.string() + ")");
}

}  // namespace iblkit
