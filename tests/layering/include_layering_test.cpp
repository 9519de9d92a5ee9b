// The source tree's layering (docs/architecture.md): which folder may include which. A wrong-way
// include, a GL or Embree header where it does not belong, or a new folder that is in no layer
// fails here.
#include "support/include_layering.h"

#include <gtest/gtest.h>

#include <fstream>

#include "support/test_paths.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

// OpenGL, windowing and Embree headers, by the prefixes of their include paths.
const std::vector<std::string> kGl = {"epoxy/", "GL/", "EGL/", "GLFW/", "imgui"};
const std::vector<std::string> kEmbree = {"embree"};

std::vector<std::string> both(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// From the bottom up; a layer may include only those listed (and itself).
const std::vector<test::Layer> kLayers = {
    {"core", {}, both(kGl, kEmbree)},
    {"raytrace", {"core"}, kGl},
    {"bakefile", {"core"}, both(kGl, kEmbree)},
    {"baker", {"core", "raytrace", "bakefile"}, kGl},
    {"engine/gl", {"core", "bakefile"}, kEmbree},
    {"engine/view", {"core", "bakefile", "engine/gl"}, kEmbree},
    {"reference", {"core", "raytrace"}, kGl},
    {"score", {"core"}, both(kGl, kEmbree)},
    {"report", {"core", "bakefile", "score"}, both(kGl, kEmbree)},
    {"cli", {"core"}, both(kGl, kEmbree)},
    {"programs",
     {"core", "raytrace", "bakefile", "baker", "engine/gl", "engine/view", "reference", "score", "report",
      "cli"},
     {}},
    {"bench", {"core", "raytrace", "bakefile", "baker", "reference", "score", "cli"}, kGl},
    {"fuzz", {"core", "bakefile", "reference"}, both(kGl, kEmbree)},
};

TEST(IncludeLayering, TheTreeHasNoWrongWayInclude) {
  const std::vector<std::string> violations = test::layeringViolations(IBLKIT_SOURCE_DIR, kLayers, {"tests"});
  std::string listed;
  for (const std::string& v : violations) listed += v + "\n";
  EXPECT_TRUE(violations.empty()) << listed;
}

// The check on a small tree of its own: each kind of violation is found, with its file and line.
TEST(IncludeLayering, FindsWrongWayIncludesForbiddenHeadersAndFilesInNoLayer) {
  const fs::path root = test::scratchDir() / "layering_tree";
  fs::remove_all(root);
  for (const char* folder : {"core", "engine/gl", "report", "stray", "tests", "build/x"})
    fs::create_directories(root / folder);
  std::ofstream(root / "core" / "image.h") << "#pragma once\n#include <vector>\n#include \"core/other.h\"\n";
  std::ofstream(root / "core" / "bad.cpp") << "#include \"core/image.h\"\n  #  include \"engine/gl/renderer.h\"\n";
  std::ofstream(root / "core" / "gl.cpp") << "#include <epoxy/gl.h>\n";
  std::ofstream(root / "report" / "case.cpp") << "#include \"baker/bake_in_memory.h\"\n// #include \"engine/gl/x.h\"\n";
  std::ofstream(root / "stray" / "x.cpp") << "int x;\n";
  std::ofstream(root / "tests" / "t.cpp") << "#include \"engine/gl/renderer.h\"\n";
  std::ofstream(root / "build" / "x" / "gen.cpp") << "#include \"engine/gl/renderer.h\"\n";
  const std::vector<std::string> found = test::layeringViolations(root, kLayers, {"tests"});
  const std::vector<std::string> expected = {
      "core/bad.cpp:2: includes \"engine/gl/renderer.h\" (core may include only its own headers)",
      "core/gl.cpp:1: includes <epoxy/gl.h> (core must not use epoxy/)",
      "report/case.cpp:1: includes \"baker/bake_in_memory.h\" (report may include only core, bakefile, score)",
      "stray/x.cpp: in no layer",
  };
  EXPECT_EQ(found, expected);
}

}  // namespace
}  // namespace iblkit
