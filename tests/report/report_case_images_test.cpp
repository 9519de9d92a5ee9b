// A report case read back for iblkit-view --reference REPORT --case CASE, from a report output
// written by the report's own writers (tests/support/report_output.h).
#include "report/report_case_images.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "support/report_output.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

std::string problemOf(const fs::path& report, const std::string& caseName) {
  try {
    readReportCase(report, caseName);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(ReportCaseImages, ReadsTheReferenceAndEachModeInOrderFromTheFolderOrItsReportJson) {
  const fs::path out = test::scratchDir() / "report";
  test::writeReportOutput(out, {{"bunny",
                                 "sky",
                                 {{"reference", Image(8, 4, glm::vec4(1.0f, 0.0f, 1.0f, 1.0f))},
                                  {"sh", Image(8, 4, glm::vec4(0.0f, 2.0f, 0.0f, 1.0f))},
                                  {"full", Image(8, 4, glm::vec4(0.0f, 0.0f, 0.5f, 1.0f))}}},
                                {"bunny", "studio", {{"reference", Image(8, 4)}}}});
  for (const fs::path& report : {out, out / "report.json"}) {
    const ReportCase read = readReportCase(report, "bunny-sky");
    EXPECT_EQ(read.reportJson, out / "report.json");
    EXPECT_EQ(read.caseName, "bunny-sky");
    ASSERT_EQ(read.images.size(), 3u);
    EXPECT_EQ(read.images[0].name, "reference");
    EXPECT_EQ(read.images[0].detail, "path-traced, 64 spp");
    EXPECT_EQ(read.images[1].name, "sh");
    EXPECT_EQ(read.images[1].detail, "mean FLIP 0.1000, relMSE 0.0000, 2.50 ms");
    EXPECT_EQ(read.images[2].name, "full");
    EXPECT_EQ(read.images[2].detail, "mean FLIP 0.2000, relMSE 0.0000, 2.50 ms");
    EXPECT_NEAR(read.images[0].image.at(3, 2).r, 1.0f, 1e-2f);
    EXPECT_NEAR(read.images[1].image.at(3, 2).g, 2.0f, 2e-2f);
    EXPECT_NEAR(read.images[2].image.at(3, 2).b, 0.5f, 5e-3f);
  }
  EXPECT_TRUE(isReportPath(out));
  EXPECT_TRUE(isReportPath(out / "report.json"));
  EXPECT_FALSE(isReportPath(out / "images" / "bunny-sky.exr"));
}

TEST(ReportCaseImages, BadCasesAreOneLineNamingTheFile) {
  const fs::path dir = test::scratchDir(), out = dir / "report";
  test::writeReportOutput(out, {{"bunny", "sky", {{"reference", Image(2, 2)}}},
                                {"bunny", "studio", {{"reference", Image(2, 2)}}}});
  const std::string json = (out / "report.json").string();
  EXPECT_EQ(problemOf(out, "bunny-city"), json + ": no case 'bunny-city' (cases: bunny-sky, bunny-studio)");
  EXPECT_EQ(problemOf(out, ""), json + ": name one of its cases with --case: bunny-sky, bunny-studio");
  const fs::path empty = dir / "empty";
  fs::create_directories(empty);
  EXPECT_EQ(problemOf(empty, "bunny-sky"),
            (empty / "report.json").string() +
                ": cannot open: No such file or directory (not an iblkit-report output?)");
  std::ofstream(empty / "report.json") << "{\"settings\": {}}";
  EXPECT_EQ(problemOf(empty, "bunny-sky"),
            (empty / "report.json").string() + ": no cases (not an iblkit-report report.json?)");
  fs::remove(out / "images" / "bunny-studio-linear.js");
  EXPECT_EQ(problemOf(out, "bunny-studio"), (out / "images" / "bunny-studio-linear.js").string() +
                                                ": cannot open: No such file or directory");
}

}  // namespace
}  // namespace iblkit
