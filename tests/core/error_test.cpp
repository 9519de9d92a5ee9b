#include "core/error.h"

#include <gtest/gtest.h>

#include <string>

#include "core/usage_error.h"

namespace iblkit {
namespace {

std::string messageOf(long long value, long long lo, long long hi) {
  try {
    requireInRange("--width", value, lo, hi);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

// Both bounds are inside; one step past either fails with the option, the range and the value, as a
// usage error (exit status 2).
TEST(RequireInRange, AcceptsTheClosedRangeAndNamesTheOptionOtherwise) {
  EXPECT_EQ(messageOf(1, 1, 16384), "");
  EXPECT_EQ(messageOf(16384, 1, 16384), "");
  EXPECT_EQ(messageOf(0, 1, 16384), "--width: must be in 1..16384, not 0");
  EXPECT_EQ(messageOf(16385, 1, 16384), "--width: must be in 1..16384, not 16385");
  EXPECT_EQ(messageOf(-4, 1, 16384), "--width: must be in 1..16384, not -4");
}

}  // namespace
}  // namespace iblkit
