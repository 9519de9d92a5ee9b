#pragma once
// The end-to-end check every program gets for its command line (cli/program.h): a bad option is
// exactly one line "PROGRAM: message" on stderr, nothing on stdout, and exit status 2.

#include <string>

namespace iblkit::test {

// Runs the shell command `command` and expects status 2 and stderr == `line` + "\n".
void expectUsageError(const std::string& command, const std::string& line);

}  // namespace iblkit::test
