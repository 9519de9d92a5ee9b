#pragma once
// One case of an iblkit-report output read back, for iblkit-view --reference REPORT --case CASE
// (docs/viewer.md "Flipping through a report case"): the case's path-traced reference and each
// scored mode's engine frame, linear, from the images script the page uses (images/CASE-linear.js,
// page_images.h), with what report.json says of each (spp, mean FLIP, frame time).

#include <filesystem>
#include <string>
#include <vector>

#include "core/image.h"

namespace iblkit {

struct ReportCaseImage {
  std::string name;    // "reference", or the mode (iblkit-view --mode)
  std::string detail;  // "path-traced, 256 spp" or "mean FLIP 0.0412, relMSE 0.0031, 1.2 ms"
  Image image;
};

struct ReportCase {
  std::filesystem::path reportJson;
  std::string caseName;                 // SCENE-ENVIRONMENT, as the page's case ids
  // The case's scene and map as the report was given them (report.json's sceneFile and
  // environmentFile; relative paths are relative to the folder the report ran in); empty when the
  // report does not say.
  std::filesystem::path sceneFile, environmentFile;
  std::vector<ReportCaseImage> images;  // the reference first, then the modes in the report's order
};

// Whether --reference names a report rather than an image: a folder, or a file called report.json.
bool isReportPath(const std::filesystem::path& reference);

// Reads case `caseName` of the report `report` (its output folder or its report.json). An empty
// `caseName` takes the report's only case. Throws Error("<file>: <problem>"): no report.json,
// not a report, no such case (the problem lists the cases), no case named when there are several,
// a case without linear images (an older report), or an images script that does not read.
ReportCase readReportCase(const std::filesystem::path& report, const std::string& caseName);

}  // namespace iblkit
