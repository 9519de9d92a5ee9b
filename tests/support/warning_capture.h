#pragma once
// Collects the warnings iblkit::warn() emits while an instance is alive (tests check their exact
// text); the default stderr sink is restored on destruction. One instance at a time.

#include <string>
#include <vector>

namespace iblkit::test {

class WarningCapture {
 public:
  WarningCapture();
  ~WarningCapture();
  WarningCapture(const WarningCapture&) = delete;
  WarningCapture& operator=(const WarningCapture&) = delete;

  const std::vector<std::string>& lines() const;
  // True when some captured line contains `text`.
  bool contains(const std::string& text) const;
};

}  // namespace iblkit::test
