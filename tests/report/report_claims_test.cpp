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

// A case under a map of `kind` with the light mode's and full's mean FLIP.
CaseResult lightCase(const std::string& scene, const std::string& environment, MapKind kind, double light,
                     double full) {
  CaseResult result = caseOf(scene, environment, {{kLightBaselineMode, full}, {kLightClaimMode, light}});
  result.mapKind = kind;
  return result;
}

const Claim* findClaim(const std::vector<Claim>& claims, const std::string& prefix) {
  for (const Claim& claim : claims)
    if (claim.statement.rfind(prefix, 0) == 0) return &claim;
  return nullptr;
}

TEST(ReportClaims, LightModeAgainstFullPerKindOfMap) {
  std::vector<CaseResult> cases = {
      lightCase("bunny", "sky", MapKind::Sunny, 0.025, 0.055),          // 0.45 of full's
      lightCase("bunny", "esplanade", MapKind::Sunny, 0.060, 0.127),    // 0.47
      lightCase("bunny", "studio", MapKind::Studio, 0.070, 0.147),      // 0.48
      lightCase("bunny", "city", MapKind::Soft, 0.059, 0.057),          // +0.002
      lightCase("diffuse_sphere", "sky", MapKind::Sunny, 0.040, 0.07),  //
      lightCase("diffuse_sphere", "studio", MapKind::Studio, 0.049, 0.16),
      lightCase("diffuse_sphere", "city", MapKind::Soft, 0.020, 0.024),
  };
  std::vector<Claim> claims = evaluateClaims(cases);
  ASSERT_EQ(claims.size(), 7u);  // sunny and studio: bunny, sphere, every scene; soft: every scene
  const Claim* sunnyBunny = findClaim(claims, "bunny on sunny maps (sky, esplanade): lights-shadowed mean FLIP at most 0.5 x full's");
  ASSERT_NE(sunnyBunny, nullptr);
  EXPECT_TRUE(sunnyBunny->holds);
  EXPECT_NEAR(sunnyBunny->measured, 0.060 / 0.127, 1e-12);  // the largest ratio over the sunny maps
  EXPECT_EQ(sunnyBunny->detail, "bunny under sky: 0.025 against full's 0.055; bunny under esplanade: 0.06 against full's 0.127");
  const Claim* studioSphere = findClaim(claims, "diffuse_sphere on studio maps (studio): lights-shadowed mean FLIP <= 0.05");
  ASSERT_NE(studioSphere, nullptr);
  EXPECT_TRUE(studioSphere->holds);
  EXPECT_NEAR(studioSphere->measured, 0.049, 1e-12);
  const Claim* soft = findClaim(claims, "every scene on soft maps (city): lights-shadowed mean FLIP at most full's + 0.005");
  ASSERT_NE(soft, nullptr);
  EXPECT_TRUE(soft->holds);
  EXPECT_NEAR(soft->measured, 0.002, 1e-12);  // the bunny's +0.002, not the sphere's -0.004
  for (const Claim& claim : claims) EXPECT_TRUE(claim.holds) << claim.statement;

  // Each bound fails on its own side: one sunny map above half, a sphere above 0.05, a soft map
  // 0.008 worse than full.
  cases[1].modes[1].scores.meanFlip = 0.070;  // esplanade: 0.55 of full's
  cases[5].modes[1].scores.meanFlip = 0.051;
  cases[3].modes[1].scores.meanFlip = 0.065;
  claims = evaluateClaims(cases);
  EXPECT_FALSE(findClaim(claims, "bunny on sunny maps")->holds);
  EXPECT_NEAR(findClaim(claims, "bunny on sunny maps")->measured, 0.070 / 0.127, 1e-12);
  EXPECT_TRUE(findClaim(claims, "bunny on studio maps")->holds);
  EXPECT_FALSE(findClaim(claims, "diffuse_sphere on studio maps")->holds);
  EXPECT_TRUE(findClaim(claims, "diffuse_sphere on sunny maps")->holds);
  EXPECT_FALSE(findClaim(claims, "every scene on soft maps")->holds);
  EXPECT_NEAR(findClaim(claims, "every scene on soft maps")->measured, 0.008, 1e-12);
  EXPECT_TRUE(findClaim(claims, "every scene on sunny maps")->holds);

  // A failed frame makes its claim fail, unmeasured.
  cases[0].modes[0].failure = "3 NaN or infinite pixel values";
  claims = evaluateClaims(cases);
  EXPECT_FALSE(findClaim(claims, "every scene on sunny maps")->holds);
  EXPECT_TRUE(std::isnan(findClaim(claims, "bunny on sunny maps")->measured));
  EXPECT_NE(findClaim(claims, "bunny on sunny maps")->detail.find("bunny under sky: frame failed"), std::string::npos);
}

TEST(ReportClaims, LightClaimsNameTheLargestCaseOfMany) {
  std::vector<CaseResult> cases;
  for (const char* scene : {"bunny", "suzi", "pmndrs"})
    for (const char* map : {"city", "forest"}) cases.push_back(lightCase(scene, map, MapKind::Soft, 0.05, 0.05));
  cases[3].modes[1].scores.meanFlip = 0.054;  // suzi under forest
  const std::vector<Claim> claims = evaluateClaims(cases);
  ASSERT_EQ(claims.size(), 1u);
  EXPECT_EQ(claims[0].statement, "every scene on soft maps (city, forest): lights-shadowed mean FLIP at most full's + 0.005");
  EXPECT_TRUE(claims[0].holds);
  EXPECT_EQ(claims[0].detail, "largest: suzi under forest: 0.054 against full's 0.05; over 6 cases");
}

TEST(ReportClaims, LightClaimsNeedTheKindAndBothModes) {
  CaseResult noKind = lightCase("bunny", "sky", MapKind::Sunny, 0.02, 0.05);
  noKind.mapKind.reset();
  EXPECT_TRUE(evaluateClaims({noKind}).empty());
  CaseResult noFull = caseOf("bunny", "sky", {{kLightClaimMode, 0.02}});
  noFull.mapKind = MapKind::Sunny;
  EXPECT_TRUE(evaluateClaims({noFull}).empty());
  // Only the claims whose scene has cases of the kind.
  const std::vector<Claim> claims = evaluateClaims({lightCase("suzi", "studio", MapKind::Studio, 0.1, 0.1)});
  ASSERT_EQ(claims.size(), 1u);
  EXPECT_EQ(claims[0].statement.rfind("every scene on studio maps (studio)", 0), 0u) << claims[0].statement;
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
