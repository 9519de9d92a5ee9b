#pragma once
// Helpers for tests of bad input: the message an Error carries (and, through
// support/warning_capture.h, the warnings emitted meanwhile), so tests compare exact text.

#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "support/warning_capture.h"

namespace iblkit::test {

// Runs f() and returns the message of the Error it throws, or "(no error)".
template <class F>
std::string errorMessage(F&& f) {
  try {
    std::forward<F>(f)();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

// WarningCapture (the warnings emitted while one is alive) is support/warning_capture.h's.

}  // namespace iblkit::test
