// The sampling study's outputs from made-up results: the markdown table (its ratios, its shape)
// and the SVG plot (well-formed, one line per strategy and map, nothing undefined in it).
#include "bench/sampling_study_report.h"

#include <gtest/gtest.h>

#include <vector>

#include "support/text_lines.h"

namespace iblkit {
namespace {

// 1, 2 and 4 spp; uniform, cosine, brdf, env, mis, mediancut, lights4, lights16, lights64, lights256.
SamplingStudySettings settings() {
  SamplingStudySettings out;
  out.width = 32;
  out.height = 18;
  out.maxSpp = 4;
  out.referenceSpp = 1024;
  return out;
}

MapStudy study(const std::string& name, const std::string& label, std::vector<std::vector<double>> relMse) {
  MapStudy out;
  out.name = name;
  out.label = label;
  out.referenceFloor = 7.89e-4;
  out.relMse = std::move(relMse);
  out.microsecondsPerSample = {0.9, 1.0, 0.75, 0.95, 1.25, 1.3, 0.5, 0.5, 0.5, 0.5};
  return out;
}

// Cosine / mis: 100x, 10x and 1000x on sky; 2x at every level on venice. At 4 spp, over mis: on
// sky mediancut 1.1x, the point lights 2000x, 600x, 150x and 10x; on venice 1x, 20x, 10x, 4x, 1.2x.
std::vector<MapStudy> twoMaps() {
  return {study("sky", "sunny",
                {{2, 3, 4},
                 {100, 1, 10},
                 {50, 2, 5},
                 {2, 0.2, 0.02},
                 {1, 0.1, 0.01},
                 {1, 0.1, 0.011},
                 {40, 30, 20},
                 {10, 8, 6},
                 {3, 2, 1.5},
                 {1.2, 0.3, 0.1}}),
          study("venice", "soft",
                {{1, 0.5, 0.25},
                 {0.4, 0.2, 0.1},
                 {0.4, 0.2, 0.1},
                 {0.4, 0.2, 0.1},
                 {0.2, 0.1, 0.05},
                 {0.2, 0.1, 0.05},
                 {1, 1, 1},
                 {0.5, 0.5, 0.5},
                 {0.3, 0.2, 0.2},
                 {0.2, 0.1, 0.06}})};
}

// Every element closed in order (<a ...>...</a> or <a .../>), no text outside the root, and every
// '&' an entity: enough of XML to tell a truncated or garbled plot.
::testing::AssertionResult wellFormedXml(const std::string& xml) {
  std::vector<std::string> open;
  std::size_t at = 0;
  while ((at = xml.find('<', at)) != std::string::npos) {
    const std::size_t end = xml.find('>', at);
    if (end == std::string::npos) return ::testing::AssertionFailure() << "unclosed tag at " << at;
    const std::string tag = xml.substr(at + 1, end - at - 1);
    if (tag.empty()) return ::testing::AssertionFailure() << "empty tag at " << at;
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1))
        return ::testing::AssertionFailure() << "</" << tag.substr(1) << "> closes nothing open at " << at;
      open.pop_back();
    } else if (tag.back() != '/') {
      open.push_back(tag.substr(0, tag.find(' ')));
    }
    if (open.empty() && xml.find_first_not_of(" \n", end + 1) != std::string::npos)
      return ::testing::AssertionFailure() << "content after the root element";
    at = end + 1;
  }
  if (!open.empty()) return ::testing::AssertionFailure() << "<" << open.back() << "> never closed";
  for (std::size_t amp = xml.find('&'); amp != std::string::npos; amp = xml.find('&', amp + 1))
    if (xml.find(';', amp) > xml.find_first_of(" <\"", amp))
      return ::testing::AssertionFailure() << "bare & at " << amp;
  return ::testing::AssertionSuccess();
}

TEST(SamplingStudyReport, NumbersHaveThreeSignificantDigits) {
  EXPECT_EQ(formatStudyNumber(0.0), "0");
  EXPECT_EQ(formatStudyNumber(0.00792), "0.00792");
  EXPECT_EQ(formatStudyNumber(28.14), "28.1");
  EXPECT_EQ(formatStudyNumber(1370.0), "1.37e+03");
  EXPECT_EQ(formatStudyNumber(22600.0), "2.26e+04");
  EXPECT_EQ(formatStudyNumber(4.7e-4), "4.70e-04");
}

TEST(SamplingStudyReport, MarkdownHasTheRatiosAndOneTableRowPerStrategy) {
  const std::string md = samplingStudyMarkdown(settings(), "bunny.json", twoMaps());
  EXPECT_EQ(
      md.rfind("Scene `bunny.json` (its own materials; path integrator, max depth 16), 32 x 18, 2 threads. "
               "relMSE (score/image_metrics.h, epsilon 0.01) against 1024 spp of `mis`",
               0),
      0u)
      << md;
  EXPECT_NE(
      md.find(
          "Ratio cosine / mis (relMSE at equal spp), per map: **sky** 10x to 1e+03x; **venice** 2x to 2x.\n"),
      std::string::npos)
      << md;
  EXPECT_NE(
      md.find("Median cut and point lights, relMSE over mis's at 4 spp, per map: **sky** mediancut 1.1x, "
              "lights4 2e+03x, lights16 600x, lights64 150x, lights256 10x; **venice** mediancut 1x, "
              "lights4 20x, lights16 10x, lights64 4x, lights256 1.2x.\n"),
      std::string::npos)
      << md;
  EXPECT_NE(md.find("\n**sky** (sunny), reference floor 7.89e-04\n"), std::string::npos) << md;
  EXPECT_NE(md.find("\n**venice** (soft), reference floor 7.89e-04\n"), std::string::npos) << md;

  // Each map: a header, the alignment row and ten strategies, each with 1 + 3 + 2 cells.
  const std::vector<std::string> all = test::splitLines(md);
  std::vector<std::string> rows;
  for (const std::string& line : all)
    if (line.rfind("|", 0) == 0) rows.push_back(line);
  ASSERT_EQ(rows.size(), 2u * (2 + kStudyStrategyCount));
  for (const std::string& row : rows) EXPECT_EQ(test::countOccurrences(row, "|"), 7u) << row;
  EXPECT_EQ(rows[0], "| strategy | 1 spp | 2 spp | 4 spp | us / sample | cosine / strategy |");
  EXPECT_EQ(rows[1], "|---|---:|---:|---:|---:|---:|");
  // The last column is the geometric mean of cosine / strategy: (100 * 10 * 1000)^(1/3) = 100 for mis.
  EXPECT_EQ(rows[3], "| cosine | 100 | 1 | 10 | 1.00 | 1 |");
  EXPECT_EQ(rows[6], "| mis | 1 | 0.1 | 0.01 | 1.25 | 100 |");
  EXPECT_EQ(rows[8], "| lights4 | 40 | 30 | 20 | 0.50 | 0.347 |");
  EXPECT_EQ(rows[2 + kStudyStrategyCount + 2], "| uniform | 1 | 0.5 | 0.25 | 0.90 | 0.4 |");
  EXPECT_EQ(all.back(),
            "\"cosine / strategy\" is the geometric mean over the spp levels of cosine's relMSE over the "
            "strategy's.");
}

TEST(SamplingStudyReport, MarkdownNamesThePhongLobe) {
  SamplingStudySettings phong = settings();
  phong.phong = 20.0f;
  const std::string md = samplingStudyMarkdown(phong, "bunny.json", twoMaps());
  EXPECT_EQ(
      md.rfind("Scene `bunny.json` (every surface the modified Phong lobe of exponent 20; path integrator",
               0),
      0u)
      << md;
}

TEST(SamplingStudyReport, SvgIsWellFormedWithALinePerStrategyAndMap) {
  std::vector<MapStudy> maps = twoMaps();
  maps[1].label = "soft <&> \"quoted\"";  // labels come from the command line
  const std::string svg = samplingStudySvg(settings(), maps);
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"730\" height=\"260\"", 0), 0u)
      << svg;
  EXPECT_TRUE(wellFormedXml(svg)) << svg;
  EXPECT_EQ(test::countOccurrences(svg, "<polyline "), 2 * kStudyStrategyCount);
  // Three points per line: one per spp level.
  for (std::size_t at = svg.find("points=\""); at != std::string::npos; at = svg.find("points=\"", at + 1))
    EXPECT_EQ(test::countOccurrences(svg.substr(at, svg.find('"', at + 8) - at), ","), 3u);
  EXPECT_NE(svg.find(">venice (soft &lt;&amp;&gt; &quot;quoted&quot;)</text>"), std::string::npos) << svg;
  EXPECT_EQ(test::countOccurrences(svg, "nan"), 0u);
  EXPECT_EQ(test::countOccurrences(svg, "inf"), 0u);
  // The legend names every strategy; the sky panel's axis spans 1e-2 to 1e2.
  for (const StudyStrategy& strategy : kStudyStrategies)
    EXPECT_NE(svg.find(std::string(strategy.name) + "</text>"), std::string::npos) << strategy.name;
  EXPECT_NE(svg.find(">1e-2</text>"), std::string::npos);
  EXPECT_NE(svg.find(">1e2</text>"), std::string::npos);
}

TEST(SamplingStudyReport, ZeroScoresAreLeftOutOfThePlot) {
  std::vector<MapStudy> maps = twoMaps();
  maps[0].relMse[0] = {0.0, 0.0, 0.0};
  for (std::vector<double>& line : maps[1].relMse) line = {0.0, 0.0, 0.0};
  const std::string svg = samplingStudySvg(settings(), maps);
  EXPECT_TRUE(wellFormedXml(svg)) << svg;
  EXPECT_EQ(test::countOccurrences(svg, "points=\"\""), 1 + kStudyStrategyCount);
  EXPECT_EQ(test::countOccurrences(svg, "nan"), 0u);
  EXPECT_EQ(test::countOccurrences(svg, "inf"), 0u);
}

}  // namespace
}  // namespace iblkit
