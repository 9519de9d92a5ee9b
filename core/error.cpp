#include "core/error.h"

#include <atomic>
#include <cstdio>
#include <string>

#include "core/usage_error.h"

namespace iblkit {

namespace {
void printWarning(const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); }
std::atomic<WarningSink> gSink{printWarning};
}  // namespace

void fail(const std::filesystem::path& file, const std::string& problem) {
  throw Error(file.string() + ": " + problem);
}

std::string printableExcerpt(std::string_view text, std::size_t maxLength) {
  std::string excerpt;
  for (std::size_t i = 0; i < text.size() && i < maxLength; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    excerpt += c >= 0x20 && c < 0x7f ? static_cast<char>(c) : '?';
  }
  if (text.size() > maxLength) excerpt += "...";
  return excerpt;
}

void failUsage(const std::string& option, const std::string& problem) {
  throw UsageError(option + ": " + problem);
}

void requireInRange(const std::filesystem::path& what, long long value, long long lo, long long hi) {
  if (value < lo || value > hi)
    failUsage(what.string(), "must be in " + std::to_string(lo) + ".." + std::to_string(hi) + ", not " +
                                 std::to_string(value));
}

void setWarningSink(WarningSink sink) { gSink.store(sink ? sink : printWarning); }

void warn(const std::filesystem::path& file, const std::string& what) {
  gSink.load()(file.string() + ": warning: " + what);
}

}  // namespace iblkit
