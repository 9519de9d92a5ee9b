#pragma once
// The layering of the source tree as a checkable rule: each folder may include the project
// headers of some folders and some system headers, and no others (docs/architecture.md). The
// layering test applies it to the whole tree, so a wrong-way include fails the test suite.
#include <filesystem>
#include <string>
#include <vector>

namespace iblkit::test {

struct Layer {
  std::string folder;                     // relative to the root, e.g. "engine/gl"
  std::vector<std::string> mayInclude;    // folders whose headers it may include ("core", ...)
  std::vector<std::string> forbiddenSystem;  // system header prefixes it must not include ("embree")
};

// Every #include "a/b.h" and #include <x> of every .h/.cpp/.cc file under `root` (skipping
// folders named build*, .git and the ignored assets), checked against `layers`: a project
// include resolves to the longest layer folder that prefixes it. Returns one line per violation,
// "file:line: includes "x" (folder may include only: ...)" or "file: in no layer", relative to
// `root`, sorted. Files of folders listed in `unchecked` (tests, benchmarks) are not checked.
std::vector<std::string> layeringViolations(const std::filesystem::path& root, const std::vector<Layer>& layers,
                                            const std::vector<std::string>& unchecked);

}  // namespace iblkit::test
