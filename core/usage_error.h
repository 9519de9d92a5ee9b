#pragma once
// A command line the program cannot run: an option out of range, options that exclude each other.
// The programs exit with status 2 for it and 1 for every other Error (cli/program.h, README.md
// "Exit codes"); requireInRange (error.h) throws it too.

#include <string>

#include "core/error.h"

namespace iblkit {

class UsageError : public Error {
 public:
  using Error::Error;
};

// Throws UsageError("<option>: <problem>").
[[noreturn]] void failUsage(const std::string& option, const std::string& problem);

}  // namespace iblkit
