#include "report/svg_plot.h"

#include "report/html_text.h"

namespace iblkit {

void beginSvgPlot(std::ostream& svg, const char* cssClass, const SvgPlotFrame& frame, double axisTop) {
  svg << "<svg class=" << cssClass << " xmlns=\"http://www.w3.org/2000/svg\" width=\"" << frame.width
      << "\" height=\"" << frame.height << "\" font-family=\"sans-serif\" font-size=\"" << frame.font << "\">\n";
  svg << "<rect x=\"" << frame.left << "\" y=\"" << frame.top << "\" width=\"" << frame.plotWidth() << "\" height=\""
      << frame.plotHeight() << "\" fill=\"none\" stroke=\"#999\"/>\n";
  for (int tick = 0; tick <= 4; ++tick) {
    const double value = axisTop * tick / 4.0;
    svg << "<text x=\"" << frame.left - 6 << "\" y=\"" << frame.y(value, axisTop) + 4 << "\" text-anchor=\"end\">"
        << fixedText(value, 3) << "</text>\n";
  }
}

}  // namespace iblkit
