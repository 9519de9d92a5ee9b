#pragma once
// A small iblkit-report output folder written through the report's own writers
// (writeCaseImagesScript for each case's images/CASE-linear.js, writeReportJson for report.json),
// for the tests that read a report case back. Header-only: the tests that use it link iblkit_report.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/image.h"
#include "report/page_images.h"
#include "report/report_writer.h"

namespace iblkit::test {

struct ReportOutputCase {
  std::string scene, environment;
  // "reference" first, then each mode's frame; every mode gets mean FLIP 0.1 * its position.
  std::vector<std::pair<std::string, Image>> images;
};

inline void writeReportOutput(const std::filesystem::path& out, const std::vector<ReportOutputCase>& cases) {
  ReportSummary summary;
  for (const ReportOutputCase& outputCase : cases) {
    CaseResult result;
    result.scene = outputCase.scene;
    result.environment = outputCase.environment;
    result.referenceSpp = 64;
    const std::string caseName = result.scene + "-" + result.environment;
    std::vector<std::pair<std::string, const Image*>> linear;
    for (std::size_t i = 0; i < outputCase.images.size(); ++i) {
      linear.push_back({outputCase.images[i].first, &outputCase.images[i].second});
      if (i == 0) continue;
      ModeResult mode;
      mode.mode = outputCase.images[i].first;
      mode.scores.meanFlip = 0.1 * double(i);
      mode.frameMilliseconds = 2.5;
      result.modes.push_back(mode);
    }
    result.linearImages = "images/" + caseName + "-linear.js";
    std::filesystem::create_directories(out / "images");
    writeCaseImagesScript(out / result.linearImages, caseName, linear);
    summary.cases.push_back(result);
  }
  writeReportJson(out / "report.json", summary);
}

}  // namespace iblkit::test
