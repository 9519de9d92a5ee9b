#pragma once
// Helpers for tests of bad input: the message an Error carries, and the warnings emitted while a
// WarningCapture is alive, so tests compare exact text.

#include <string>
#include <utility>
#include <vector>

#include "core/error.h"

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

// Collects every warning line while alive (tests run one at a time in a test program), then
// restores the default sink.
class WarningCapture {
 public:
  WarningCapture() {
    lines().clear();
    setWarningSink([](const std::string& line) { lines().push_back(line); });
  }
  ~WarningCapture() { setWarningSink(nullptr); }
  WarningCapture(const WarningCapture&) = delete;
  WarningCapture& operator=(const WarningCapture&) = delete;

  const std::vector<std::string>& warnings() const { return lines(); }

 private:
  static std::vector<std::string>& lines() {
    static std::vector<std::string> captured;
    return captured;
  }
};

}  // namespace iblkit::test
