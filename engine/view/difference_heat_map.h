#pragma once
// The viewer's difference view (shaders/difference_heatmap.frag): the live frame against the
// path-traced reference as the scorer's heat map shows it, per pixel the relMSE term
// (relativeSquaredErrorMap, score/image_metrics.h) through magma (core/color_map.h, the scorer's
// colour map, uploaded as a table) from 0 to a maximum (heatMapImage, score/heat_map.h, without
// its legend bar).
#include <epoxy/gl.h>

#include "engine/gl/gpu_textures.h"
#include "engine/gl/shader_program.h"

namespace iblkit {

class DifferenceHeatMap {
 public:
  // Builds the program and uploads the colour map. Needs a current OpenGL 4.5 context.
  DifferenceHeatMap();
  ~DifferenceHeatMap();
  DifferenceHeatMap(const DifferenceHeatMap&) = delete;
  DifferenceHeatMap& operator=(const DifferenceHeatMap&) = delete;

  // Draws the heat map of `liveTexture` (the width x height frame) against `referenceTexture`
  // (linear radiance, stretched over the rectangle (x, y, w, h) of the frame, which may reach
  // beyond it) into that rectangle of the bound draw framebuffer, as display-referred sRGB,
  // `maxValue` (> 0) at the top of the colour map. Each pixel compares the live frame's pixel under it.
  void draw(GLuint liveTexture, GLuint referenceTexture, float maxValue, int width, int height, int x, int y, int w,
            int h) const;

 private:
  ShaderProgram program_{"fullscreen.vert", "difference_heatmap.frag"};
  GlTexture colorMap_;
  GLuint emptyVertexArray_ = 0;
};

}  // namespace iblkit
