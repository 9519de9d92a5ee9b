#include "support/warning_capture.h"

#include "core/error.h"

namespace iblkit::test {

namespace {
std::vector<std::string>& captured() {
  static std::vector<std::string> lines;
  return lines;
}
void capture(const std::string& line) { captured().push_back(line); }
}  // namespace

WarningCapture::WarningCapture() {
  captured().clear();
  setWarningSink(&capture);
}

WarningCapture::~WarningCapture() { setWarningSink(nullptr); }

const std::vector<std::string>& WarningCapture::lines() const { return captured(); }

bool WarningCapture::contains(const std::string& text) const {
  for (const std::string& line : captured())
    if (line.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace iblkit::test
