#pragma once
// Runs iblkit's programs as separate processes for the report, as a user would: each stage's
// command line is the documented one, and a crash in one stage cannot corrupt the report's state.

#include <filesystem>
#include <string>
#include <vector>

namespace iblkit {

// Runs argv[0] (a path, not searched in PATH) with the given arguments, no shell involved, with
// standard output and standard error appended to `log`. Returns the program's standard output
// and error (the part it added to the log). Throws Error naming the program when it cannot be
// started or exits with a non-zero status; the message ends with the last line it printed.
std::string runProgram(const std::vector<std::string>& argv, const std::filesystem::path& log);

// The command line as a shell would show it (arguments with spaces or quotes quoted by
// shellQuoted), for logs and reports.
std::string commandLine(const std::vector<std::string>& argv);

// `text` as one word of a POSIX shell: in single quotes, each ' inside written '\''.
std::string shellQuoted(const std::string& text);

}  // namespace iblkit
