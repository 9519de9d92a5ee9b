#pragma once
// What the sampling study (env_sampling_study.h) writes: a markdown table per map of relMSE
// against spp for each strategy, with the cosine / MIS ratios the claim is about, and an SVG plot
// of the same numbers, log-log, one panel per map and one line per strategy.

#include <string>
#include <vector>

#include "bench/env_sampling_study.h"

namespace iblkit {

// Three significant digits in plain (0.001 <= |value| < 10^4) or scientific notation.
std::string formatStudyNumber(double value);

// The markdown of the study of `sceneName` (a file name, e.g. "bunny.json") with `settings`: a
// sentence on the setup, the range of cosine / MIS ratios per map, the median-cut strategies' relMSE
// over MIS's at the highest spp per map, then one table per map (a row
// per strategy, a column per spp level, us / sample, and the geometric mean of cosine / strategy).
// Every MapStudy has a row for each strategy and a column for each level of studySppLevels(settings.maxSpp).
std::string samplingStudyMarkdown(const SamplingStudySettings& settings, const std::string& sceneName,
                                  const std::vector<MapStudy>& maps);

// A standalone SVG document: relMSE (log10 axis, whole decades) against spp (log2 axis), one panel
// per map, one polyline per strategy and a legend. Zero scores are left out of the lines.
std::string samplingStudySvg(const SamplingStudySettings& settings, const std::vector<MapStudy>& maps);

}  // namespace iblkit
