#include "report/report_case_images.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "report/html_text.h"
#include "report/page_images.h"

namespace iblkit {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string caseNameOf(const json& entry) {
  return entry.value("scene", std::string()) + "-" + entry.value("environment", std::string());
}

std::string modeDetail(const json& mode) {
  std::string detail;
  auto add = [&](const char* label, const char* key, int digits) {
    if (!mode.contains(key) || !mode[key].is_number()) return;
    detail += (detail.empty() ? "" : ", ") + std::string(label) + fixedText(mode[key].get<double>(), digits);
  };
  add("mean FLIP ", "meanFlip", 4);
  add("relMSE ", "relMse", 4);
  if (mode.contains("frameMilliseconds") && mode["frameMilliseconds"].is_number())
    detail += (detail.empty() ? "" : ", ") + fixedText(mode["frameMilliseconds"].get<double>(), 2) + " ms";
  return detail;
}

}  // namespace

bool isReportPath(const fs::path& reference) {
  std::error_code error;
  return fs::is_directory(reference, error) || reference.filename() == "report.json";
}

ReportCase readReportCase(const fs::path& report, const std::string& caseName) {
  std::error_code error;
  ReportCase result;
  result.reportJson = fs::is_directory(report, error) ? report / "report.json" : report;
  const fs::path& file = result.reportJson;
  std::ifstream stream(file);
  if (!stream) fail(file, "cannot open: No such file or directory (not an iblkit-report output?)");
  json document;
  try {
    document = json::parse(stream);
  } catch (const json::exception& e) {
    fail(file, std::string("not an iblkit-report report.json: ") + e.what());
  }
  if (!document.is_object() || !document.contains("cases") || !document["cases"].is_array() ||
      document["cases"].empty())
    fail(file, "no cases (not an iblkit-report report.json?)");
  std::string names;
  const json* chosen = nullptr;
  for (const json& entry : document["cases"]) {
    names += (names.empty() ? "" : ", ") + caseNameOf(entry);
    if (caseNameOf(entry) == caseName) chosen = &entry;
  }
  if (caseName.empty()) {
    if (document["cases"].size() > 1) fail(file, "name one of its cases with --case: " + names);
    chosen = &document["cases"].front();
  }
  if (!chosen) fail(file, "no case '" + caseName + "' (cases: " + names + ")");
  result.caseName = caseNameOf(*chosen);
  if (chosen->contains("sceneFile") && chosen->at("sceneFile").is_string())
    result.sceneFile = chosen->at("sceneFile").get<std::string>();
  if (chosen->contains("environmentFile") && chosen->at("environmentFile").is_string())
    result.environmentFile = chosen->at("environmentFile").get<std::string>();
  if (!chosen->contains("linearImages"))
    fail(file, "case '" + result.caseName +
                   "' has no linear images (written before iblkit-report wrote them: run it again)");
  const CaseImagesScript script =
      readCaseImagesScript(file.parent_path() / chosen->at("linearImages").get<std::string>());
  for (const auto& [name, image] : script.images) {
    std::string detail;
    if (name == "reference") {
      const json& reference = chosen->value("reference", json::object());
      detail = "path-traced, " + std::to_string(reference.value("spp", 0)) + " spp";
    } else {
      for (const json& mode : chosen->value("modes", json::array()))
        if (mode.value("mode", std::string()) == name) detail = modeDetail(mode);
    }
    result.images.push_back({name, detail, image});
  }
  return result;
}

}  // namespace iblkit
