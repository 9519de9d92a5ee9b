// End-to-end tests of the sampling_study program (build/bench/sampling_study) on a tiny study:
// what it writes (the table, the plot, the --update file's section and nothing else of it), and
// bad input, which must fail with one line (after any warnings about repaired input) and a non-zero
// exit before anything is rendered or written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/test_paths.h"
#include "support/text_lines.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

const std::string kBefore = "# Benchmarks\n\nWritten by hand.\n";
const std::string kAfter = "\nAlso by hand.\n<!-- other:begin -->\nanother program's\n<!-- other:end -->\n";
const std::string kNotes = kBefore + "<!-- study:begin -->\nold table\n<!-- study:end -->" + kAfter;

std::string readText(const fs::path& file) {
  std::ifstream stream(file, std::ios::binary);
  std::ostringstream text;
  text << stream.rdbuf();
  return text.str();
}

class SamplingStudyProgram : public testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(test::assetsDir() / "hdri" / "sky.exr")) GTEST_SKIP() << "assets not fetched";
    dir_ = test::scratchDir();
    fs::create_directories(dir_ / "out");
    std::ofstream(dir_ / "notes.md") << kNotes;
    std::ofstream(dir_ / "plain.md") << "# No markers here\n";
  }

  // Runs the program in the scratch folder on sky at 16 x 9, 1 to 4 spp against 64, with
  // `changed` replacing or adding options; returns the exit status, stdout and stderr in *output.
  int study(const std::map<std::string, std::string>& changed, std::string* output) const {
    std::map<std::string, std::string> options = {{"--assets", test::assetsDir().string()},
                                                  {"--maps", "sky:sunny"},
                                                  {"--width", "16"},
                                                  {"--height", "9"},
                                                  {"--max-spp", "4"},
                                                  {"--reference-spp", "64"},
                                                  {"--threads", "2"},
                                                  {"--cache", "cache"},
                                                  {"--out-dir", "out"},
                                                  {"--name", "study"},
                                                  {"--update", "notes.md"}};
    for (const auto& [option, value] : changed) options[option] = value;
    std::string command = "cd " + test::shellQuoted(dir_) + " && " + test::shellQuoted(IBLKIT_SAMPLING_STUDY);
    for (const auto& [option, value] : options) command += " " + option + " " + test::shellQuoted(value);
    return test::runCommand(command, output);
  }

  fs::path dir_;
};

TEST_F(SamplingStudyProgram, WritesTheTableThePlotAndOnlyItsSectionOfTheUpdatedFile) {
  std::string output;
  ASSERT_EQ(study({}, &output), 0) << output;
  EXPECT_NE(output.find("sky: rendering the reference, 64 spp mis\n"), std::string::npos) << output;
  EXPECT_NE(output.find("sky: reference rendered ("), std::string::npos) << output;

  const std::string md = readText(dir_ / "out" / "study.md");
  const std::string heading = "# Sampling study\n\n";
  ASSERT_EQ(md.rfind(heading, 0), 0u) << md;
  const std::string table = md.substr(heading.size());
  EXPECT_EQ(
      table.rfind("Scene `bunny.json` (its own materials; path integrator, max depth 16), 16 x 9, 2 threads.",
                  0),
      0u)
      << md;
  EXPECT_NE(table.find("Ratio cosine / mis (relMSE at equal spp), per map: **sky** "), std::string::npos)
      << md;
  EXPECT_NE(table.find("\n**sky** (sunny), reference floor "), std::string::npos) << md;
  std::vector<std::string> rows;
  for (const std::string& line : test::splitLines(table))
    if (line.rfind("|", 0) == 0) rows.push_back(line);
  ASSERT_EQ(rows.size(), 12u) << md;  // header, alignment, ten strategies
  EXPECT_EQ(rows[0], "| strategy | 1 spp | 2 spp | 4 spp | us / sample | cosine / strategy |");
  for (const std::string& row : rows) EXPECT_EQ(test::countOccurrences(row, "|"), 7u) << row;
  EXPECT_EQ(rows[6].rfind("| mis | ", 0), 0u) << rows[6];
  EXPECT_EQ(rows[7].rfind("| mediancut | ", 0), 0u) << rows[7];
  EXPECT_EQ(rows[11].rfind("| lights256 | ", 0), 0u) << rows[11];
  // The table is also the end of stdout.
  EXPECT_TRUE(output.ends_with(table)) << output;

  const std::string svg = readText(dir_ / "out" / "study.svg");
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\" ", 0), 0u) << svg;
  EXPECT_TRUE(svg.ends_with("</svg>\n")) << svg;
  EXPECT_EQ(test::countOccurrences(svg, "<polyline "), 10u) << svg;
  EXPECT_NE(svg.find(">sky (sunny)</text>"), std::string::npos) << svg;

  // The section holds the table; every other byte of the file is as it was.
  EXPECT_EQ(readText(dir_ / "notes.md"),
            kBefore + "<!-- study:begin -->\n" + table + "<!-- study:end -->" + kAfter);
  std::vector<std::string> files;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(dir_))
    if (entry.is_regular_file()) files.push_back(fs::relative(entry.path(), dir_).string());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, std::vector<std::string>({"cache/reference_sky_16x9_64spp.exr",
                                             "cache/reference_sky_16x9_64spp_variance.exr", "notes.md",
                                             "out/study.md", "out/study.svg", "plain.md"}));

  ASSERT_EQ(study({}, &output), 0) << output;
  EXPECT_NE(output.find("sky: reference cached ("), std::string::npos) << output;
  EXPECT_EQ(output.find("rendering the reference"), std::string::npos) << output;
}

TEST_F(SamplingStudyProgram, BadInputFailsWithOneLineBeforeAnythingIsWritten) {
  const std::string missingMap = "sampling_study: " + (test::assetsDir() / "hdri" / "nope.exr").string() +
                                 ": cannot open: No such file or directory";
  struct Case {
    std::map<std::string, std::string> changed;
    int status;  // 2: the command line, 1: a file (cli/program.h)
    std::string message;
  };
  const std::vector<Case> cases = {
      {{{"--maps", "nope"}}, 1, missingMap},
      // The good map first: nothing of it may be rendered or cached before the bad one fails.
      {{{"--maps", "sky,nope"}}, 1, missingMap},
      {{{"--maps", ""}}, 2, "sampling_study: --maps: '' is not NAME[:LABEL] with NAME a map in ASSETS/hdri"},
      {{{"--maps", "sky,:label"}},
       2,
       "sampling_study: --maps: ':label' is not NAME[:LABEL] with NAME a map in ASSETS/hdri"},
      {{{"--update", "missing.md"}}, 1, "sampling_study: missing.md: cannot open: No such file or directory"},
      {{{"--update", "plain.md"}},
       1,
       "sampling_study: plain.md: has no <!-- study:begin --> ... <!-- study:end --> section"},
      {{{"--name", "other2"}},
       1,
       "sampling_study: notes.md: has no <!-- other2:begin --> ... <!-- other2:end --> section"},
      {{{"--name", "a/b"}}, 2, "sampling_study: --name: 'a/b' is not a file name"},
      {{{"--out-dir", "missing"}}, 1, "sampling_study: missing: folder does not exist"},
      {{{"--scene", "missing.json"}},
       1,
       "sampling_study: missing.json: cannot open: No such file or directory"},
      {{{"--width", "0"}}, 2, "sampling_study: --width: must be in 1..16384, not 0"},
      {{{"--height", "20000"}}, 2, "sampling_study: --height: must be in 1..16384, not 20000"},
      {{{"--max-spp", "99999999"}}, 2, "sampling_study: --max-spp: must be in 1..16777216, not 99999999"},
      {{{"--reference-spp", "-1"}}, 2, "sampling_study: --reference-spp: must be in 1..16777216, not -1"},
      {{{"--threads", "-2"}}, 2, "sampling_study: --threads: must be >= 0, not -2"},
      {{{"--phong", "-1"}}, 2, "sampling_study: --phong: exponent must be finite and >= 0"},
      {{{"--width", "abc"}}, 2, "sampling_study: Could not convert: --width = abc"},
      {{{"--max-spp", "4x"}}, 2, "sampling_study: Could not convert: --max-spp = 4x"},
      {{{"--frobnicate", "1"}},
       2,
       "sampling_study: The following arguments were not expected: 1 --frobnicate"},
  };
  for (const auto& [changed, status, expected] : cases) {
    const std::string what = changed.begin()->first + " " + changed.begin()->second;
    std::string output;
    EXPECT_EQ(study(changed, &output), status) << what << ": " << output;
    const std::vector<std::string> printed = test::splitLines(output);
    ASSERT_FALSE(printed.empty()) << what;
    EXPECT_EQ(printed.back(), expected) << what << ": " << output;
    for (std::size_t i = 0; i + 1 < printed.size(); ++i)
      EXPECT_NE(printed[i].find(": warning: "), std::string::npos) << what << ": " << output;
    EXPECT_TRUE(fs::is_empty(dir_ / "out")) << what;
    EXPECT_FALSE(fs::exists(dir_ / "cache")) << what;
    EXPECT_EQ(readText(dir_ / "notes.md"), kNotes) << what;
  }
}

}  // namespace
}  // namespace iblkit
