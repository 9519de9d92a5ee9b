#pragma once
// Errors for bad input: every loader throws iblkit::Error with a one-line message that names the
// file and the problem ("scene.glb: accessor 3 reads past the end of buffer 0"). Programs catch
// it in main, print it on one line and exit non-zero.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace iblkit {

class Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// Throws Error("<file>: <problem>").
[[noreturn]] void fail(const std::filesystem::path& file, const std::string& problem);

// Text from a bad input, fit to quote in a one-line message: control characters (carriage
// returns, escapes) and bytes outside printable ASCII become '?', and text longer than
// `maxLength` is cut with "...".
std::string printableExcerpt(std::string_view text, std::size_t maxLength = 40);

// Throws UsageError("<what>: must be in lo..hi, not value") unless lo <= value <= hi (see
// usage_error.h). For programs checking an option before reading anything (what: "--width").
void requireInRange(const std::filesystem::path& what, long long value, long long lo, long long hi);

// Non-fatal repairs (NaN pixels set to 0, normals generated) are reported through this hook, one
// line each, "<file>: warning: <what was repaired>". The default prints to stderr; tests capture.
using WarningSink = void (*)(const std::string& line);
void setWarningSink(WarningSink sink);
void warn(const std::filesystem::path& file, const std::string& what);

}  // namespace iblkit
