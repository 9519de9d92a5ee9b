// Replacing a document's generated section (docs/benchmarks.md's sampling-study tables): only the
// text between the markers changes, sections whose names share a prefix stay apart, and a missing
// or reversed marker is an error naming the document.
#include "bench/marked_section.h"

#include <gtest/gtest.h>

#include "support/error_capture.h"

namespace iblkit {
namespace {

const std::string kDocument =
    "# Notes\n\nBefore.\n<!-- study:begin -->\nold table\n<!-- study:end -->\n\nBetween.\n"
    "<!-- study_phong:begin -->\nold glossy table\n<!-- study_phong:end -->\nAfter.\n";

TEST(MarkedSection, ReplacesOnlyTheTextBetweenTheMarkers) {
  EXPECT_EQ(replaceMarkedSection(kDocument, "study", "new table\n", "notes.md"),
            "# Notes\n\nBefore.\n<!-- study:begin -->\nnew table\n<!-- study:end -->\n\nBetween.\n"
            "<!-- study_phong:begin -->\nold glossy table\n<!-- study_phong:end -->\nAfter.\n");
  EXPECT_EQ(replaceMarkedSection(kDocument, "study_phong", "new glossy table\n", "notes.md"),
            "# Notes\n\nBefore.\n<!-- study:begin -->\nold table\n<!-- study:end -->\n\nBetween.\n"
            "<!-- study_phong:begin -->\nnew glossy table\n<!-- study_phong:end -->\nAfter.\n");
}

TEST(MarkedSection, ReplacingAgainWithTheSameTextChangesNothing) {
  const std::string once = replaceMarkedSection(kDocument, "study", "table\n", "notes.md");
  EXPECT_EQ(replaceMarkedSection(once, "study", "table\n", "notes.md"), once);
}

TEST(MarkedSection, MissingOrReversedMarkersAreAnErrorNamingTheDocument) {
  const std::string expected = "notes.md: has no <!-- study:begin --> ... <!-- study:end --> section";
  const auto error = [](const std::string& document) {
    return test::errorMessage([&] { replaceMarkedSection(document, "study", "x\n", "notes.md"); });
  };
  EXPECT_EQ(error("no markers at all\n"), expected);
  EXPECT_EQ(error("<!-- study:begin -->\nno end\n"), expected);
  EXPECT_EQ(error("no begin\n<!-- study:end -->\n"), expected);
  EXPECT_EQ(error("<!-- study:end -->\n<!-- study:begin -->\n"), expected);
  EXPECT_EQ(error("<!-- study_phong:begin -->\n<!-- study_phong:end -->\n"), expected);
}

}  // namespace
}  // namespace iblkit
