#include "engine/gl/shader_program.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "engine/gl/embedded_shaders.h"
#include "gl/test_context.h"
#include "support/error_capture.h"

namespace iblkit {
namespace {

// mesh.frag includes the generated constants and the files below (material.glsl includes the
// constants again, under their include guard; shadow.glsl includes light_directions.glsl,
// latlong_footprint.glsl environment.glsl): each is preceded by "#line 1 N" and
// followed by the line after the #include in file 0, so compiler messages map back to the
// original files.
TEST(ShaderProgram, IncludesAreExpandedWithLineDirectives) {
  const std::string source = expandedShaderSource("mesh.frag");
  EXPECT_EQ(source.rfind("#version 450 core\n", 0), 0u);
  EXPECT_EQ(source.find("#include"), std::string::npos);
  EXPECT_NE(source.find("#line 1 1\n"), std::string::npos);
  EXPECT_NE(source.find("#line 1 4\n"), std::string::npos);
  for (const EmbeddedShader& shader : embeddedShaders())
    if (shader.name == "mesh.frag") {
      ASSERT_EQ(shader.files.size(), 12u);
      EXPECT_EQ(shader.files[0], "shaders/mesh.frag");
      EXPECT_EQ(shader.files[1], "generated/shared_constants.glsl");
      EXPECT_EQ(shader.files[2], "shaders/latlong_footprint.glsl");
      EXPECT_EQ(shader.files[3], "shaders/environment.glsl");  // included by latlong_footprint.glsl
      EXPECT_EQ(shader.files[4], "shaders/sh9.glsl");
      EXPECT_EQ(shader.files[5], "shaders/brdf.glsl");
      EXPECT_EQ(shader.files[6], "shaders/material.glsl");
      EXPECT_EQ(shader.files[7], "shaders/lights.glsl");
      EXPECT_EQ(shader.files[8], "shaders/shadow.glsl");
      EXPECT_EQ(shader.files[9], "shaders/light_directions.glsl");  // included by shadow.glsl
      EXPECT_EQ(shader.files[10], "shaders/visibility_cone.glsl");
      EXPECT_EQ(shader.files[11], "shaders/dominant_lights.glsl");
    }
}

TEST(ShaderProgram, UnknownShaderIsAnError) {
  test::glContext();
  EXPECT_EQ(test::errorMessage([] { ShaderProgram("mesh.vert", "nope.frag"); }),
            "shaders/nope.frag: no such embedded shader");
}

// The 1-based line of shaders/mesh.frag whose text is `line` (its first), counted in the
// embedded source from the last "#line L 0" directive before it; 0 if absent.
int meshFragLineOf(const std::string& line) {
  const std::string source = expandedShaderSource("mesh.frag");
  const std::size_t at = source.find("\n" + line + "\n");
  if (at == std::string::npos) return 0;
  const std::size_t directive = source.rfind("\n#line ", at);
  if (directive == std::string::npos) return int(std::count(source.begin(), source.begin() + long(at) + 1, '\n')) + 1;
  int number = 0, file = -1;
  if (std::sscanf(source.c_str() + directive + 1, "#line %d %d", &number, &file) != 2 || file != 0) return 0;
  const std::size_t directiveEnd = source.find('\n', directive + 1);
  return number + int(std::count(source.begin() + long(directiveEnd) + 1, source.begin() + long(at) + 1, '\n'));
}

// Compile errors name the original file and line, in the stage and in an included file (a define
// breaks the source on purpose: mesh.frag's `const int mode = SHADING_MODE;` reads SHADING_MODE,
// environment.glsl line 7 declares rotateAboutY; shadow_surface.vert, unlike mesh.vert, does not
// read SHADING_MODE, so the error is the fragment stage's).
TEST(ShaderProgram, CompileErrorsNameTheShaderFileAndLine) {
  test::glContext();
  const int modeLine = meshFragLineOf("const int mode = SHADING_MODE;");
  ASSERT_GT(modeLine, 0);
  const std::string inStage = test::errorMessage(
      [] { ShaderProgram("shadow_surface.vert", "mesh.frag", "#define SHADING_MODE undefinedName"); });
  EXPECT_EQ(inStage.rfind("shaders/mesh.frag:" + std::to_string(modeLine) + ": ", 0), 0u) << inStage;
  const std::string inInclude =
      test::errorMessage([] { ShaderProgram("fullscreen.vert", "sky.frag", "#define rotateAboutY 1"); });
  EXPECT_EQ(inInclude.rfind("shaders/environment.glsl:7: ", 0), 0u) << inInclude;
  takeGlErrors();  // the failed compiles are not GL errors, but drain whatever the driver reported
}

TEST(ShaderProgram, EveryEmbeddedStageCompilesAndLinks) {
  test::glContext();
  EXPECT_NO_THROW(ShaderProgram("mesh.vert", "mesh.frag"));
  EXPECT_NO_THROW(ShaderProgram("fullscreen.vert", "sky.frag"));
  EXPECT_NO_THROW(ShaderProgram("fullscreen.vert", "present.frag"));
  EXPECT_NO_THROW(ShaderProgram("fullscreen.vert", "brdf_probe.frag"));
  EXPECT_NO_THROW(ShaderProgram("fullscreen.vert", "brdf_lobes_probe.frag"));
  EXPECT_NO_THROW(ShaderProgram("fullscreen.vert", "difference_heatmap.frag"));
  EXPECT_NO_THROW(ShaderProgram("fullscreen.vert", "shared_constants_probe.frag"));
  EXPECT_NO_THROW(ShaderProgram("fullscreen.vert", "material_probe.frag"));
  checkGlErrors("shader programs");
}

}  // namespace
}  // namespace iblkit
