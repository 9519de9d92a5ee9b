#include "report/report_claims.h"

#include <gtest/gtest.h>

#include <cmath>

namespace iblkit {
namespace {

CaseResult caseOf(const std::string& scene, const std::string& environment,
                  const std::vector<std::pair<std::string, double>>& flips) {
  CaseResult result;
  result.scene = scene;
  result.environment = environment;
  for (const auto& [mode, flip] : flips) {
    ModeResult modeResult;
    modeResult.mode = mode;
    modeResult.scores.meanFlip = flip;
    modeResult.scores.meanRelativeError = flip;  // the tests below read one or the other
    result.modes.push_back(modeResult);
  }
  return result;
}

TEST(ReportClaims, LadderRungsAreAveragedOverEnvironments) {
  const std::vector<CaseResult> cases = {
      caseOf("bunny", "sky", {{"sh", 0.30}, {"sh-ao", 0.20}, {"sh-ao-bent", 0.25}, {"prt", 0.10}}),
      caseOf("bunny", "city", {{"sh", 0.10}, {"sh-ao", 0.08}, {"sh-ao-bent", 0.01}, {"prt", 0.02}}),
  };
  const std::vector<Claim> claims = evaluateClaims(cases);
  ASSERT_EQ(claims.size(), 3u);
  EXPECT_EQ(claims[0].statement, "bunny: mean FLIP of sh > sh-ao (0.2 > 0.14)");
  EXPECT_TRUE(claims[0].holds);
  EXPECT_NEAR(claims[1].measured, 0.14, 1e-12);
  EXPECT_NEAR(claims[1].bound, 0.13, 1e-12);
  EXPECT_TRUE(claims[1].holds);  // the mean decides, not each environment
  EXPECT_TRUE(claims[2].holds);  // 0.13 >= 0.06
  EXPECT_EQ(claims[2].detail, "averaged over 2 environments");

  const std::vector<CaseResult> inverted = {
      caseOf("bunny", "sky", {{"sh", 0.1}, {"sh-ao", 0.2}, {"sh-ao-bent", 0.2}, {"prt", 0.2}})};
  const std::vector<Claim> failing = evaluateClaims(inverted);
  EXPECT_FALSE(failing[0].holds);
  EXPECT_FALSE(failing[1].holds);  // equal is not better for a strict rung
  EXPECT_TRUE(failing[2].holds);   // prt need only be no worse
}

TEST(ReportClaims, SphereBoundsAndFailedFrames) {
  std::vector<CaseResult> cases = {caseOf("mirror_sphere", "sky", {{"mirror", 0.015}}),
                                   caseOf("mirror_sphere", "city", {{"mirror", 0.02}}),
                                   caseOf("diffuse_sphere", "sky", {{"sh", 0.05}})};
  cases[2].sh9Truncation = 0.046;
  std::vector<Claim> claims = evaluateClaims(cases);
  ASSERT_EQ(claims.size(), 3u);
  EXPECT_TRUE(claims[0].holds);
  EXPECT_NEAR(claims[0].measured, 0.0175, 1e-12);
  EXPECT_FALSE(claims[1].holds);
  EXPECT_EQ(claims[1].bound, 0.03);
  EXPECT_NE(claims[1].detail.find("SH9's own truncation error on the same normals averages 4.6%"), std::string::npos)
      << claims[1].detail;
  // What the sh frame adds beyond SH9: unknown (no sh frame scored) fails, 0.4% holds, 2% fails.
  EXPECT_FALSE(claims[2].holds);
  cases[2].shBeyondSh9 = 0.004;
  claims = evaluateClaims(cases);
  EXPECT_TRUE(claims[2].holds);
  EXPECT_EQ(claims[2].detail, "largest under sky (error beyond SH9 on 16x16-pixel blocks)");
  cases[2].shBeyondSh9 = 0.02;
  EXPECT_FALSE(evaluateClaims(cases)[2].holds);

  cases[1].modes[0].failure = "3 NaN or infinite pixel values";
  claims = evaluateClaims(cases);
  EXPECT_FALSE(claims[0].holds);  // a failed frame is not averaged away
  EXPECT_EQ(claims[0].detail, "averaged over 2 environments; 1 frames failed");
}

// SH9 against the irradiance cube on the diffuse sphere: the mean over the maps decides, the detail
// lists each map's pair.
TEST(ReportClaims, IrradianceCubeAgainstSh9OnTheDiffuseSphere) {
  const std::vector<CaseResult> cases = {caseOf("diffuse_sphere", "sky", {{"sh", 0.07}, {"irradiance", 0.01}}),
                                         caseOf("diffuse_sphere", "city", {{"sh", 0.01}, {"irradiance", 0.012}})};
  const std::vector<Claim> claims = evaluateClaims(cases);
  ASSERT_EQ(claims.size(), 3u);
  EXPECT_EQ(claims[2].statement, "diffuse_sphere: irradiance mode (the cube) mean relative error < sh mode's (0.011 < 0.04)");
  EXPECT_TRUE(claims[2].holds);
  EXPECT_EQ(claims[2].detail, "averaged over 2 environments; sky 0.01 vs 0.07; city 0.012 vs 0.01");
  const std::vector<CaseResult> worse = {caseOf("diffuse_sphere", "city", {{"sh", 0.01}, {"irradiance", 0.012}})};
  EXPECT_FALSE(evaluateClaims(worse)[2].holds);
}

TEST(ReportClaims, ClaimsWithoutTheirSceneOrModeAreLeftOut) {
  EXPECT_TRUE(evaluateClaims({caseOf("suzi", "sky", {{"sh", 0.1}})}).empty());
  EXPECT_TRUE(evaluateClaims({caseOf("bunny", "sky", {{"full", 0.1}})}).empty());
  EXPECT_TRUE(std::isnan(meanOverEnvironments({}, "bunny", "sh", Metric::MeanFlip)));
}

}  // namespace
}  // namespace iblkit
