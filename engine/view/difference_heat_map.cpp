#include "engine/view/difference_heat_map.h"

#include "core/color_map.h"
#include "core/image.h"
#include "engine/gl/texture_unit.h"

namespace iblkit {
namespace {

// Samples of magma at t = i / (n - 1). magma is piecewise linear in sRGB over five segments whose
// ends (t = 0.2 k) are samples (255 = 5 x 51), and bilinear filtering between 256 samples of the
// decoded curve stays within 1e-5 of it: far below one 8-bit display step.
constexpr int kColorMapSamples = 256;

Image magmaTable() {
  Image table(kColorMapSamples, 1);
  for (int i = 0; i < kColorMapSamples; ++i)
    table.at(i, 0) = glm::vec4(magma(float(i) / float(kColorMapSamples - 1)), 1.0f);
  return table;
}

}  // namespace

DifferenceHeatMap::DifferenceHeatMap() : colorMap_(uploadTable(magmaTable())) {
  glCreateVertexArrays(1, &emptyVertexArray_);
}

DifferenceHeatMap::~DifferenceHeatMap() { glDeleteVertexArrays(1, &emptyVertexArray_); }

void DifferenceHeatMap::draw(GLuint liveTexture, GLuint referenceTexture, float maxValue, int width, int height,
                             int x, int y, int w, int h) const {
  glViewport(x, y, w, h);
  // The rectangle's texture coordinates (0 to 1) to the live frame's.
  program_.set("liveUvOffset", glm::vec2(float(x) / float(width), float(y) / float(height)));
  program_.set("liveUvScale", glm::vec2(float(w) / float(width), float(h) / float(height)));
  // The samplers are declared with these units (layout(binding), texture_unit.h).
  glBindTextureUnit(kTextureUnitLive, liveTexture);
  glBindTextureUnit(kTextureUnitReference, referenceTexture);
  glBindTextureUnit(kTextureUnitColorMap, colorMap_.id());
  program_.set("maxValue", maxValue);
  program_.use();
  glBindVertexArray(emptyVertexArray_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glUseProgram(0);
}

}  // namespace iblkit
