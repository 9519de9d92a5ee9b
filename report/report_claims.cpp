#include "report/report_claims.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace iblkit {

namespace {
// errorBeyondSh9 allowed on each map: the engine's float SH9 against the brute force's quadrature,
// the pixel footprint, and what is left of the reference's noise after 16x16 blocks.
constexpr double kShBeyondBound = 0.01;
}  // namespace

double metricValue(const FrameScores& scores, Metric metric) {
  switch (metric) {
    case Metric::MeanFlip: return scores.meanFlip;
    case Metric::RelMse: return scores.relMse;
    case Metric::MeanRelativeError: return scores.meanRelativeError;
    case Metric::Ssim: return scores.ssim;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double meanOverEnvironments(const std::vector<CaseResult>& cases, const std::string& scene, const std::string& mode,
                            Metric metric, int* failures) {
  double sum = 0.0;
  int count = 0, failed = 0;
  for (const CaseResult& result : cases) {
    if (result.scene != scene) continue;
    for (const ModeResult& modeResult : result.modes) {
      if (modeResult.mode != mode) continue;
      if (!modeResult.failure.empty()) {
        ++failed;
        continue;
      }
      sum += metricValue(modeResult.scores, metric);
      ++count;
    }
  }
  if (failures) *failures = failed;
  return count > 0 ? sum / count : std::numeric_limits<double>::quiet_NaN();
}

namespace {

bool hasMode(const std::vector<CaseResult>& cases, const std::string& scene, const std::string& mode) {
  for (const CaseResult& result : cases)
    for (const ModeResult& modeResult : result.modes)
      if (result.scene == scene && modeResult.mode == mode) return true;
  return false;
}

int environmentCount(const std::vector<CaseResult>& cases, const std::string& scene) {
  int count = 0;
  for (const CaseResult& result : cases) count += result.scene == scene ? 1 : 0;
  return count;
}

std::string format(double value) {
  std::ostringstream text;
  text.precision(4);
  text << value;
  return text.str();
}

// measured <= bound (or measured > bound when `strictlyAbove`, for ladder rungs where the lower
// rung's error is the bound).
void addClaim(std::vector<Claim>& claims, const std::vector<CaseResult>& cases, const std::string& scene,
              const std::string& statement, double measured, double bound, bool above, bool strict,
              int failures) {
  if (environmentCount(cases, scene) == 0) return;
  Claim claim;
  claim.statement = statement;
  claim.measured = measured;
  claim.bound = bound;
  const bool measuredOk = std::isfinite(measured) && std::isfinite(bound) && failures == 0;
  if (above)
    claim.holds = measuredOk && (strict ? measured > bound : measured >= bound);
  else
    claim.holds = measuredOk && (strict ? measured < bound : measured <= bound);
  claim.detail = "averaged over " + std::to_string(environmentCount(cases, scene)) + " environments";
  if (failures > 0) claim.detail += "; " + std::to_string(failures) + " frames failed";
  claims.push_back(claim);
}

const ModeResult* findMode(const CaseResult& result, const std::string& mode) {
  for (const ModeResult& modeResult : result.modes)
    if (modeResult.mode == mode) return &modeResult;
  return nullptr;
}

// The cases of `kind` where both the light mode and full were run (scored or failed).
std::vector<const CaseResult*> casesOfKind(const std::vector<CaseResult>& cases, MapKind kind,
                                           const std::string& scene = {}) {
  std::vector<const CaseResult*> selected;
  for (const CaseResult& result : cases)
    if (result.mapKind == kind && (scene.empty() || result.scene == scene) && findMode(result, kLightClaimMode) &&
        findMode(result, kLightBaselineMode))
      selected.push_back(&result);
  return selected;
}

std::string mapNames(const std::vector<const CaseResult*>& cases) {
  std::vector<std::string> names;
  for (const CaseResult* result : cases)
    if (std::find(names.begin(), names.end(), result->environment) == names.end()) names.push_back(result->environment);
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

// One claim over the light mode's cases of one kind: `value` of each case (NaN when it cannot be
// measured) must be at most `bound`; the claim measures the largest value. Its detail gives each
// case's two FLIPs, or for more than kListedCases cases the largest one's.
constexpr std::size_t kListedCases = 4;

template <class Value>
void addLargestClaim(std::vector<Claim>& claims, const std::vector<const CaseResult*>& selected,
                     const std::string& statement, double bound, Value value) {
  if (selected.empty()) return;
  Claim claim;
  claim.statement = statement;
  claim.bound = bound;
  claim.measured = -std::numeric_limits<double>::infinity();
  int unmeasured = 0;
  std::string worst;
  for (const CaseResult* result : selected) {
    const ModeResult& light = *findMode(*result, kLightClaimMode);
    const ModeResult& full = *findMode(*result, kLightBaselineMode);
    std::string text = result->scene + " under " + result->environment + ": ";
    double caseValue = std::numeric_limits<double>::quiet_NaN();
    if (!light.failure.empty() || !full.failure.empty()) {
      text += "frame failed";
    } else {
      caseValue = value(light.scores.meanFlip, full.scores.meanFlip);
      text += format(light.scores.meanFlip) + " against full's " + format(full.scores.meanFlip);
    }
    if (!std::isfinite(caseValue)) ++unmeasured;
    else if (caseValue > claim.measured) {
      claim.measured = caseValue;
      worst = text;
    }
    if (selected.size() <= kListedCases) claim.detail += (claim.detail.empty() ? "" : "; ") + text;
  }
  if (selected.size() > kListedCases)
    claim.detail = "largest: " + (worst.empty() ? "none" : worst) + "; over " + std::to_string(selected.size()) + " cases";
  if (unmeasured > 0) {
    claim.measured = std::numeric_limits<double>::quiet_NaN();
    if (selected.size() > kListedCases) claim.detail += "; " + std::to_string(unmeasured) + " not measured";
  }
  claim.holds = unmeasured == 0 && claim.measured <= bound;
  claims.push_back(claim);
}

// The claims per kind of map: the light mode against full (report_claims.h).
void addLightClaims(std::vector<Claim>& claims, const std::vector<CaseResult>& cases) {
  const std::string light = kLightClaimMode, full = kLightBaselineMode;
  for (const auto& [kind, name] : kMapKindNames) {
    const std::string kindName(name);
    if (kind != MapKind::Soft) {
      const std::vector<const CaseResult*> bunny = casesOfKind(cases, kind, "bunny");
      addLargestClaim(claims, bunny,
                      "bunny on " + kindName + " maps (" + mapNames(bunny) + "): " + light +
                          " mean FLIP at most " + format(kLightFlipRatioBound) + " x " + full + "'s on each map",
                      kLightFlipRatioBound, [](double lightFlip, double fullFlip) {
                        return fullFlip > 0.0 ? lightFlip / fullFlip : std::numeric_limits<double>::quiet_NaN();
                      });
      const std::vector<const CaseResult*> sphere = casesOfKind(cases, kind, "diffuse_sphere");
      addLargestClaim(claims, sphere,
                      "diffuse_sphere on " + kindName + " maps (" + mapNames(sphere) + "): " + light +
                          " mean FLIP <= " + format(kLightDiffuseFlipBound) + " on each map",
                      kLightDiffuseFlipBound, [](double lightFlip, double) { return lightFlip; });
    }
    const std::vector<const CaseResult*> every = casesOfKind(cases, kind);
    addLargestClaim(claims, every,
                    "every scene on " + kindName + " maps (" + mapNames(every) + "): " + light +
                        " mean FLIP at most " + full + "'s + " + format(kLightNoWorseMargin),
                    kLightNoWorseMargin, [](double lightFlip, double fullFlip) { return lightFlip - fullFlip; });
  }
}

}  // namespace

std::vector<Claim> evaluateClaims(const std::vector<CaseResult>& cases) {
  std::vector<Claim> claims;
  int failures = 0;
  if (hasMode(cases, "mirror_sphere", "mirror")) {
    const double mirror = meanOverEnvironments(cases, "mirror_sphere", "mirror", Metric::MeanFlip, &failures);
    addClaim(claims, cases, "mirror_sphere", "mirror_sphere: mirror mode mean FLIP <= 0.02", mirror, 0.02, false,
             false, failures);
  }
  if (hasMode(cases, "diffuse_sphere", "sh")) {
    const double diffuse = meanOverEnvironments(cases, "diffuse_sphere", "sh", Metric::MeanRelativeError, &failures);
    addClaim(claims, cases, "diffuse_sphere", "diffuse_sphere: sh mode mean relative error <= 3%", diffuse, 0.03,
             false, false, failures);
    // The 3% is SH9's own truncation error on maps without a sun or small lights; with them, SH9
    // itself is further off. Name that share, and check the engine adds nothing to it.
    double truncation = 0.0, worstBeyond = 0.0;
    int count = 0;
    std::string worst;
    for (const CaseResult& result : cases) {
      if (result.scene != "diffuse_sphere") continue;
      truncation += result.sh9Truncation;
      ++count;
      if (!(result.shBeyondSh9 <= worstBeyond)) {  // NaN (no sh frame) is the worst
        worstBeyond = result.shBeyondSh9;
        worst = result.environment;
      }
    }
    claims.back().detail += "; SH9's own truncation error on the same normals averages " +
                            format(100.0 * truncation / std::max(count, 1)) + "%";
    addClaim(claims, cases, "diffuse_sphere",
             "diffuse_sphere: sh mode adds at most 1% to SH9's own error, on every environment", worstBeyond,
             kShBeyondBound, false, false, failures);
    if (!worst.empty()) claims.back().detail = "largest under " + worst + " (error beyond SH9 on 16x16-pixel blocks)";
  }

  if (hasMode(cases, "diffuse_sphere", "sh") && hasMode(cases, "diffuse_sphere", "irradiance")) {
    // SH9 against the brute-force irradiance cube on the same sphere: the cube has no truncation.
    int shFailures = 0, cubeFailures = 0;
    const double sh = meanOverEnvironments(cases, "diffuse_sphere", "sh", Metric::MeanRelativeError, &shFailures);
    const double cube =
        meanOverEnvironments(cases, "diffuse_sphere", "irradiance", Metric::MeanRelativeError, &cubeFailures);
    addClaim(claims, cases, "diffuse_sphere",
             "diffuse_sphere: irradiance mode (the cube) mean relative error < sh mode's (" + format(cube) + " < " +
                 format(sh) + ")",
             cube, sh, false, true, shFailures + cubeFailures);
    std::string perMap;
    for (const CaseResult& result : cases) {
      if (result.scene != "diffuse_sphere") continue;
      const double mapSh = meanOverEnvironments({result}, "diffuse_sphere", "sh", Metric::MeanRelativeError);
      const double mapCube = meanOverEnvironments({result}, "diffuse_sphere", "irradiance", Metric::MeanRelativeError);
      perMap += "; " + result.environment + " " + format(mapCube) + " vs " + format(mapSh);
    }
    claims.back().detail += perMap;
  }

  const char* ladder[] = {"sh", "sh-ao", "sh-ao-bent", "prt"};
  for (int rung = 0; rung + 1 < 4; ++rung) {
    if (!hasMode(cases, "bunny", ladder[rung]) || !hasMode(cases, "bunny", ladder[rung + 1])) continue;
    int upperFailures = 0, lowerFailures = 0;
    const double upper = meanOverEnvironments(cases, "bunny", ladder[rung], Metric::MeanFlip, &upperFailures);
    const double lower = meanOverEnvironments(cases, "bunny", ladder[rung + 1], Metric::MeanFlip, &lowerFailures);
    const bool strict = rung < 2;  // the last rung, prt, need only be no worse
    addClaim(claims, cases, "bunny",
             std::string("bunny: mean FLIP of ") + ladder[rung] + (strict ? " > " : " >= ") + ladder[rung + 1] +
                 " (" + format(upper) + (strict ? " > " : " >= ") + format(lower) + ")",
             upper, lower, true, strict, upperFailures + lowerFailures);
  }
  addLightClaims(claims, cases);
  return claims;
}

}  // namespace iblkit
