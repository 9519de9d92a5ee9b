#pragma once
// What the demo's numbers must show (issue 6), checked by the report itself on its own results:
//  - the lone mirror sphere's `mirror` frames: mean FLIP at most 0.02, averaged over environments;
//  - the lone diffuse sphere's `sh` frames: mean relative error at most 3%, averaged likewise;
//  - the lone diffuse sphere's `irradiance` frames (the brute-force cube): mean relative error below
//    the `sh` frames', averaged likewise (the detail lists both per map);
//  - the white bunny on its ground: the approximation ladder sh > sh-ao > sh-ao-bent >= prt in
//    mean FLIP averaged over environments, each rung a claim of its own;
//  - per kind of map (map_kind.h; issue 15's fidelity targets), the dominant-light mode
//    lights-shadowed against full: on sunny and on studio maps the bunny's mean FLIP at most half
//    of full's and the diffuse sphere's at most 0.05, on every map of the kind; on every kind no
//    scene and map worse than full by more than 0.005.
// A claim whose scene or modes are not in the report is left out; a claim whose frames failed
// does not hold.

#include <string>
#include <vector>

#include "report/report_case.h"

namespace iblkit {

struct Claim {
  std::string statement;  // e.g. "mirror_sphere: mirror mean FLIP <= 0.02"
  double measured = 0.0, bound = 0.0;
  bool holds = false;
  std::string detail;  // what was averaged, or why it could not be measured
};

// The mode the claims per kind of map are about, the one they compare it with, and their bounds.
inline constexpr const char* kLightClaimMode = "lights-shadowed";
inline constexpr const char* kLightBaselineMode = "full";
inline constexpr double kLightFlipRatioBound = 0.5;     // bunny, sunny and studio maps: half of full's
inline constexpr double kLightDiffuseFlipBound = 0.05;  // diffuse sphere, sunny and studio maps
inline constexpr double kLightNoWorseMargin = 0.005;    // every scene and map: full's + this

std::vector<Claim> evaluateClaims(const std::vector<CaseResult>& cases);

// The mean of a mode's metric over the environments of a scene; sets `failures` to the number of
// that scene's cases where the mode has no score. NaN when no case has one.
enum class Metric { MeanFlip, RelMse, MeanRelativeError, Ssim };
double meanOverEnvironments(const std::vector<CaseResult>& cases, const std::string& scene, const std::string& mode,
                            Metric metric, int* failures = nullptr);
double metricValue(const FrameScores& scores, Metric metric);

}  // namespace iblkit
