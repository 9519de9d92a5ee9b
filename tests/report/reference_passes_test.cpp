#include "report/reference_passes.h"

#include <gtest/gtest.h>

#include <limits>

namespace iblkit {
namespace {

// The target: at most 1e-3 whatever the modes, at most 10% of the best mode's relMSE, but never
// asked below 1e-4 (a nearly exact mode); no scored mode leaves the absolute bound alone.
TEST(ReferencePasses, TargetIsTheAbsoluteBoundAndTenPercentOfTheBestModeAboveTheFloor) {
  const ReportSettings settings;
  EXPECT_DOUBLE_EQ(referenceTargetRelMse(settings, 0.05), 1e-3);   // 10% would be 5e-3
  EXPECT_DOUBLE_EQ(referenceTargetRelMse(settings, 0.004), 4e-4);  // 10% of the best
  EXPECT_DOUBLE_EQ(referenceTargetRelMse(settings, 1e-4), 1e-4);   // the floor
  EXPECT_DOUBLE_EQ(referenceTargetRelMse(settings, std::numeric_limits<double>::infinity()), 1e-3);
  ReportSettings loose = settings;
  loose.maxReferenceRelMse = 1.0;  // the rule before the absolute bound
  EXPECT_DOUBLE_EQ(referenceTargetRelMse(loose, 0.05), 5e-3);
}

// relMSE falls as 1 / passes: the count is aimed at the target with 25% to spare, even, at least
// two more passes and at most the maximum.
TEST(ReferencePasses, PassesAreAimedAtTheTargetFromTheMeasuredNoise) {
  ReportSettings settings;
  settings.maxPasses = 64;
  EXPECT_EQ(referencePassesFor(settings, 4, 4e-3, 1e-3), 20);    // 4 x 4 x 1.25
  EXPECT_EQ(referencePassesFor(settings, 4, 2.2e-3, 1e-3), 12);  // 11 rounded up to even
  EXPECT_EQ(referencePassesFor(settings, 4, 1.01e-3, 1e-3), 6);  // 5.05: at least two more
  EXPECT_EQ(referencePassesFor(settings, 4, 0.5, 1e-3), 64);     // the maximum
  EXPECT_EQ(referencePassesFor(settings, 62, 2e-3, 1e-3), 64);
  EXPECT_EQ(referencePassesFor(settings, 4, 1e-2, 0.0), 64);
}

}  // namespace
}  // namespace iblkit
