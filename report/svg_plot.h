#pragma once
// The frame the report's SVG plots share (the ladder plot, report_writer.h; cost against error,
// cost_plot.h): the canvas with its margins, the plot area's border and a mean-FLIP axis from 0
// to `top` with five labelled ticks.
#include <ostream>

namespace iblkit {

struct SvgPlotFrame {
  double width, height, left, right, top, bottom, font;
  double plotWidth() const { return width - left - right; }
  double plotHeight() const { return height - top - bottom; }
  // The y coordinate of `value` on an axis from 0 (the bottom) to `axisTop` (the top).
  double y(double value, double axisTop) const { return top + plotHeight() * (1.0 - value / axisTop); }
};

// Writes the opening <svg class=CSS_CLASS ...> of `frame`, the plot area's border and the y axis's
// labels 0, axisTop / 4, ..., axisTop (3 decimals). `svg` is in fixed notation, 1 decimal.
void beginSvgPlot(std::ostream& svg, const char* cssClass, const SvgPlotFrame& frame, double axisTop);

}  // namespace iblkit
