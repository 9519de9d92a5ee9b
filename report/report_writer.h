#pragma once
// Writes the demo report: out/demo/report.html (static HTML, viewable from file:// without a
// server: the claims and a summary first, then per scene its tables, the ladder and the cost
// plots side by side, and each case collapsed with its large view, compare_view.h) and out/demo/report.json (the same numbers for scripts and
// regression checks). Both are written to a temporary name and renamed.

#include <filesystem>
#include <string>
#include <vector>

#include "report/report_case.h"
#include "report/report_claims.h"

namespace iblkit {

struct ReportSummary {
  std::vector<CaseResult> cases;
  std::vector<Claim> claims;
  std::vector<std::string> modes;  // in ladder order
  ReportSettings settings;
  double totalSeconds = 0.0;
  int cachedStages = 0, runStages = 0;
};

void writeReportJson(const std::filesystem::path& file, const ReportSummary& summary);
void writeReportHtml(const std::filesystem::path& file, const ReportSummary& summary);

// The approximation ladder of one scene as an SVG line chart: the modes along x in the given
// order, mean FLIP along y, one thin line per environment and a thick line for their mean.
std::string ladderSvg(const std::vector<CaseResult>& cases, const std::string& scene,
                      const std::vector<std::string>& modes);

}  // namespace iblkit
