#pragma once
// Cost against error (docs/report.md): per scene, each mode's frame time (the median of its
// cases' `--bench` frame times) against its mean FLIP averaged over the environments, as an SVG
// scatter plot with the Pareto front marked: the modes that no other mode beats on both.

#include <limits>
#include <string>
#include <vector>

#include "report/report_case.h"

namespace iblkit {

struct CostPoint {
  std::string mode;
  double milliseconds = std::numeric_limits<double>::quiet_NaN();
  double meanFlip = std::numeric_limits<double>::quiet_NaN();
};

// The median frame time of `mode` over the scene's cases that timed it; NaN when none did
// (iblkit-report --bench 0).
double sceneFrameMilliseconds(const std::vector<CaseResult>& cases, const std::string& scene, const std::string& mode);

// One point per mode of `modes` that some case of the scene scored, in that order.
std::vector<CostPoint> costPoints(const std::vector<CaseResult>& cases, const std::string& scene,
                                  const std::vector<std::string>& modes);

// For each point: true when it is on the Pareto front, that is both of its numbers are finite and
// no other such point is at least as fast and at least as close with one of the two strictly.
std::vector<bool> paretoFront(const std::vector<CostPoint>& points);

// The plot: frame time on a log axis, mean FLIP on a linear one, the front's points filled and
// joined, every point labelled with its mode without overlap (label_layout.h). Without two timed
// and scored points it is a one-line note saying so.
std::string costSvg(const std::vector<CostPoint>& points);

}  // namespace iblkit
