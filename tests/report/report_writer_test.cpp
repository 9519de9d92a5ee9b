#include "report/report_writer.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "report/label_layout.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

ReportSummary summaryWithOneFailure() {
  ReportSummary summary;
  summary.modes = {"sh", "sh-ao"};
  for (const char* environment : {"sky", "city"}) {
    CaseResult result;
    result.scene = "bunny";
    result.environment = environment;
    result.referenceSpp = 256;
    result.referenceRelMse = 1e-4;
    result.referenceConverged = true;
    for (const std::string& mode : summary.modes) {
      ModeResult modeResult;
      modeResult.mode = mode;
      modeResult.scores.meanFlip = mode == "sh" ? 0.2 : 0.1;
      modeResult.frameMilliseconds = 4.0;
      result.modes.push_back(modeResult);
    }
    summary.cases.push_back(result);
  }
  summary.cases[1].modes[1].failure = "2 NaN or infinite pixel values";
  summary.claims = evaluateClaims(summary.cases);
  return summary;
}

std::string readText(const std::filesystem::path& file) {
  std::ifstream stream(file);
  std::stringstream text;
  text << stream.rdbuf();
  return text.str();
}

TEST(ReportWriter, JsonHoldsTheNumbersAndTheFailure) {
  const auto file = test::scratchDir() / "report.json";
  writeReportJson(file, summaryWithOneFailure());
  const nlohmann::json report = nlohmann::json::parse(readText(file));
  ASSERT_EQ(report["cases"].size(), 2u);
  EXPECT_EQ(report["cases"][0]["modes"][0]["meanFlip"], 0.2);
  EXPECT_EQ(report["cases"][0]["reference"]["spp"], 256);
  EXPECT_EQ(report["cases"][1]["modes"][1]["failure"], "2 NaN or infinite pixel values");
  EXPECT_FALSE(report["cases"][1]["modes"][1].contains("meanFlip"));
  EXPECT_EQ(report["claims"][0]["holds"], false);  // the failed frame breaks the sh > sh-ao rung
  EXPECT_FALSE(std::filesystem::exists(file.string() + ".tmp"));
}

TEST(ReportWriter, HtmlShowsClaimsTablesAndPlot) {
  const auto file = test::scratchDir() / "report.html";
  writeReportHtml(file, summaryWithOneFailure());
  const std::string html = readText(file);
  EXPECT_NE(html.find("bunny: mean FLIP of sh &gt; sh-ao"), std::string::npos);
  EXPECT_NE(html.find("<td class=no title=\"2 NaN or infinite pixel values\">failed</td>"), std::string::npos);
  EXPECT_NE(html.find("<svg"), std::string::npos);
}

// The map kinds: in report.json per case, under each map's name, and the table of every mode's
// mean FLIP per kind, where a kind's failed frame leaves its mean unmeasured.
TEST(ReportWriter, KindsOfMapAreShownWithTheirMeans) {
  ReportSummary summary = summaryWithOneFailure();
  summary.cases[0].mapKind = MapKind::Sunny;
  summary.cases[0].concentration = {0.5, 0.6};
  summary.cases[1].mapKind = MapKind::Soft;
  const auto jsonFile = test::scratchDir() / "kinds.json";
  writeReportJson(jsonFile, summary);
  const nlohmann::json report = nlohmann::json::parse(readText(jsonFile));
  EXPECT_EQ(report["cases"][0]["mapKind"], "sunny");
  EXPECT_EQ(report["cases"][0]["mapSunShare"], 0.5);
  EXPECT_EQ(report["cases"][1]["mapKind"], "soft");

  const auto htmlFile = test::scratchDir() / "kinds.html";
  writeReportHtml(htmlFile, summary);
  const std::string html = readText(htmlFile);
  EXPECT_NE(html.find("<th>sky<br><span class=small>sunny</span></th>"), std::string::npos);
  const std::size_t table = html.find("<h2>By kind of map</h2>");
  ASSERT_NE(table, std::string::npos);
  EXPECT_NE(html.find("<th>sunny<br><span class=small>sky</span></th><th>soft<br><span class=small>city</span></th>", table),
            std::string::npos);
  // sh: 0.2 on both kinds; sh-ao: 0.1 on sky, failed on city.
  EXPECT_NE(html.find("<tr><td class=l>bunny</td><td class=l>sh</td><td>0.2000</td><td>0.2000</td></tr>", table),
            std::string::npos);
  EXPECT_NE(html.find("<tr><td class=l>bunny</td><td class=l>sh-ao</td><td>0.1000</td><td>&ndash;</td></tr>", table),
            std::string::npos);
  // A light claim that fails is explained once, above the tables.
  EXPECT_EQ(html.find("Where the dominant lights lose"), std::string::npos);  // no light claim here
  summary.claims = {Claim{"bunny on sunny maps (sky): lights-shadowed mean FLIP at most 0.5 x full's on each map",
                          0.6, 0.5, false, ""}};
  writeReportHtml(htmlFile, summary);
  EXPECT_NE(readText(htmlFile).find("Where the dominant lights lose to <code>full</code>"), std::string::npos);
  summary.claims[0].holds = true;
  writeReportHtml(htmlFile, summary);
  EXPECT_EQ(readText(htmlFile).find("Where the dominant lights lose"), std::string::npos);
  // Without kinds, no table.
  writeReportHtml(htmlFile, summaryWithOneFailure());
  EXPECT_EQ(readText(htmlFile).find("By kind of map"), std::string::npos);
}

TEST(ReportWriter, LadderPlotHasALinePerEnvironmentAndTheMean) {
  const std::string svg = ladderSvg(summaryWithOneFailure().cases, "bunny", {"sh", "sh-ao"});
  std::size_t lines = 0;
  for (std::size_t at = svg.find("<polyline"); at != std::string::npos; at = svg.find("<polyline", at + 1)) ++lines;
  EXPECT_EQ(lines, 3u);
  EXPECT_NE(svg.find(">sky</text>"), std::string::npos);
  EXPECT_NE(svg.find(">city</text>"), std::string::npos);
}


// Six maps whose lines end at the same mean FLIP: their labels at the plot's right are spread.
TEST(ReportWriter, LadderLabelsDoNotOverlap) {
  std::vector<CaseResult> cases;
  for (const char* environment : {"sky", "esplanade", "studio", "city", "forest", "sunset"}) {
    CaseResult result;
    result.scene = "bunny";
    result.environment = environment;
    for (const char* mode : {"sh", "full"}) {
      ModeResult modeResult;
      modeResult.mode = mode;
      modeResult.scores.meanFlip = 0.1;
      result.modes.push_back(modeResult);
    }
    cases.push_back(result);
  }
  const std::string svg = ladderSvg(cases, "bunny", {"sh", "full"});
  const std::regex label("<text class=label x=\"([0-9.-]+)\" y=\"([0-9.-]+)\">(.*?)</text>");
  std::vector<LabelBox> boxes;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), label); it != std::sregex_iterator(); ++it)
    boxes.push_back({std::stod((*it)[1]), std::stod((*it)[2]) - 11.0, labelWidth((*it)[3], 11), 11.0});
  ASSERT_EQ(boxes.size(), 7u);  // six maps and the mean
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j) EXPECT_FALSE(overlaps(boxes[i], boxes[j])) << i << " " << j;
}

// The page's order: claims, summary, then the scenes; each case collapsed with its large view;
// a mode that does not apply marked n/a with its reason, and listed in report.json.
TEST(ReportWriter, SummaryFirstCasesCollapsedModesThatDoNotApplyMarked) {
  ReportSummary summary = summaryWithOneFailure();
  for (CaseResult& result : summary.cases) {
    result.referenceImage = "images/" + result.scene + "-" + result.environment + "-reference.png";
    result.linearImages = "images/" + result.scene + "-" + result.environment + "-linear.js";
    result.notApplicable = {{"mirror", "no specular lobe: every material is pure Lambert"}};
  }
  summary.modes.insert(summary.modes.begin(), "mirror");
  const auto file = test::scratchDir() / "order.html";
  writeReportHtml(file, summary);
  const std::string html = readText(file);
  const std::size_t claims = html.find("What the numbers must show"), table = html.find("<h2>Summary</h2>"),
                    scene = html.find("<h2 id=\"scene-bunny\">");
  ASSERT_NE(scene, std::string::npos);
  EXPECT_LT(claims, table);
  EXPECT_LT(table, scene);
  EXPECT_NE(html.find("<td class=na title=\"no specular lobe: every material is pure Lambert\">n/a</td>"),
            std::string::npos);
  EXPECT_NE(html.find("<details class=case id=\"case-bunny-sky\">"), std::string::npos);
  EXPECT_EQ(html.find("<details class=case open"), std::string::npos);
  EXPECT_NE(html.find("data-linear=\"images/bunny-sky-linear.js\""), std::string::npos);
  EXPECT_NE(html.find("const ACES = {a: 2.51"), std::string::npos);  // core's constants in the script
  EXPECT_NE(html.find("class=cost"), std::string::npos);             // frame times are there: the cost plot
  const auto jsonFile = test::scratchDir() / "order.json";
  writeReportJson(jsonFile, summary);
  const nlohmann::json report = nlohmann::json::parse(readText(jsonFile));
  EXPECT_EQ(report["cases"][0]["notApplicable"][0]["mode"], "mirror");
}

}  // namespace
}  // namespace iblkit
