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
