#include "report/cost_plot.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "report/html_text.h"
#include "report/label_layout.h"
#include "report/report_claims.h"
#include "report/svg_plot.h"

namespace iblkit {

namespace {

bool finite(const CostPoint& point) { return std::isfinite(point.milliseconds) && std::isfinite(point.meanFlip); }

std::string number(double value, int digits) { return fixedText(value, digits); }

}  // namespace

double sceneFrameMilliseconds(const std::vector<CaseResult>& cases, const std::string& scene, const std::string& mode) {
  std::vector<double> times;
  for (const CaseResult& result : cases) {
    if (result.scene != scene) continue;
    for (const ModeResult& modeResult : result.modes)
      if (modeResult.mode == mode && std::isfinite(modeResult.frameMilliseconds))
        times.push_back(modeResult.frameMilliseconds);
  }
  if (times.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

std::vector<CostPoint> costPoints(const std::vector<CaseResult>& cases, const std::string& scene,
                                  const std::vector<std::string>& modes) {
  std::vector<CostPoint> points;
  for (const std::string& mode : modes) {
    const bool scored = std::any_of(cases.begin(), cases.end(), [&](const CaseResult& result) {
      return result.scene == scene && std::any_of(result.modes.begin(), result.modes.end(),
                                                   [&](const ModeResult& m) { return m.mode == mode; });
    });
    if (!scored) continue;
    points.push_back({mode, sceneFrameMilliseconds(cases, scene, mode),
                      meanOverEnvironments(cases, scene, mode, Metric::MeanFlip)});
  }
  return points;
}

std::vector<bool> paretoFront(const std::vector<CostPoint>& points) {
  std::vector<bool> front(points.size(), false);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!finite(points[i])) continue;
    front[i] = std::none_of(points.begin(), points.end(), [&](const CostPoint& other) {
      return finite(other) && other.milliseconds <= points[i].milliseconds && other.meanFlip <= points[i].meanFlip &&
             (other.milliseconds < points[i].milliseconds || other.meanFlip < points[i].meanFlip);
    });
  }
  return front;
}

std::string costSvg(const std::vector<CostPoint>& points) {
  std::vector<std::size_t> shown;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (finite(points[i]) && points[i].milliseconds > 0.0) shown.push_back(i);
  if (shown.size() < 2)
    return "<p class=small>Cost against error: fewer than two modes have both a frame time and a score "
           "(frame times come from <code>--bench</code>).</p>\n";
  constexpr double kWidth = 460, kHeight = 280, kLeft = 60, kRight = 16, kTop = 16, kBottom = 44, kFont = 11;
  constexpr SvgPlotFrame kFrame{kWidth, kHeight, kLeft, kRight, kTop, kBottom, kFont};
  double fastest = points[shown[0]].milliseconds, slowest = fastest, worst = 0.0;
  for (const std::size_t i : shown) {
    fastest = std::min(fastest, points[i].milliseconds);
    slowest = std::max(slowest, points[i].milliseconds);
    worst = std::max(worst, points[i].meanFlip);
  }
  // A log axis over at least a factor of 4, a quarter of it beyond each end.
  double low = std::log10(fastest), high = std::log10(slowest);
  if (high - low < std::log10(4.0)) {
    const double middle = (low + high) / 2;
    low = middle - std::log10(2.0);
    high = middle + std::log10(2.0);
  }
  const double pad = (high - low) * 0.1;
  low -= pad;
  high += pad;
  const double top = worst > 0.0 ? worst * 1.15 : 1.0;
  const double plotWidth = kFrame.plotWidth(), plotHeight = kFrame.plotHeight();
  const auto x = [&](double ms) { return kLeft + plotWidth * (std::log10(ms) - low) / (high - low); };
  const auto y = [&](double flip) { return kFrame.y(flip, top); };

  std::ostringstream svg;
  svg.setf(std::ios::fixed);
  svg.precision(1);
  beginSvgPlot(svg, "cost", kFrame, top);
  // Ticks at 1, 2 and 5 times the powers of ten inside the axis.
  for (int power = int(std::floor(low)); power <= int(std::ceil(high)); ++power)
    for (const double factor : {1.0, 2.0, 5.0}) {
      const double ms = factor * std::pow(10.0, power);
      if (std::log10(ms) < low || std::log10(ms) > high) continue;
      svg << "<line x1=\"" << x(ms) << "\" x2=\"" << x(ms) << "\" y1=\"" << kTop + plotHeight << "\" y2=\""
          << kTop + plotHeight + 4 << "\" stroke=\"#999\"/><text x=\"" << x(ms) << "\" y=\"" << kTop + plotHeight + 16
          << "\" text-anchor=\"middle\">" << number(ms, ms < 1.0 ? 2 : ms < 10.0 ? 1 : 0) << "</text>\n";
    }
  svg << "<text x=\"" << kLeft + plotWidth / 2 << "\" y=\"" << kHeight - 8
      << "\" text-anchor=\"middle\">frame time (ms, log scale)</text>\n";
  svg << "<text x=\"14\" y=\"" << kTop + plotHeight / 2 << "\" transform=\"rotate(-90 14 " << kTop + plotHeight / 2
      << ")\" text-anchor=\"middle\">mean FLIP</text>\n";

  const std::vector<bool> front = paretoFront(points);
  std::vector<std::size_t> frontOrder;
  for (const std::size_t i : shown)
    if (front[i]) frontOrder.push_back(i);
  std::sort(frontOrder.begin(), frontOrder.end(),
            [&](std::size_t a, std::size_t b) { return points[a].milliseconds < points[b].milliseconds; });
  svg << "<polyline class=front fill=\"none\" stroke=\"#c30\" stroke-width=\"1.5\" stroke-dasharray=\"4 3\" points=\"";
  for (const std::size_t i : frontOrder) svg << x(points[i].milliseconds) << "," << y(points[i].meanFlip) << " ";
  svg << "\"/>\n";

  std::vector<LabelBox> wanted;
  for (const std::size_t i : shown) {
    const double px = x(points[i].milliseconds), py = y(points[i].meanFlip);
    const double width = labelWidth(points[i].mode, kFont);
    const double lx = px + 6 + width <= kWidth - 2 ? px + 6 : px - 6 - width;
    wanted.push_back({lx, py - kFont / 2 - 1, width, kFont + 2});
  }
  const std::vector<double> labelY = placeLabels(wanted, kTop, kTop + plotHeight);
  for (std::size_t k = 0; k < shown.size(); ++k) {
    const CostPoint& point = points[shown[k]];
    const bool onFront = front[shown[k]];
    svg << "<circle cx=\"" << x(point.milliseconds) << "\" cy=\"" << y(point.meanFlip) << "\" r=\"4\" "
        << (onFront ? "fill=\"#c30\" stroke=\"#c30\"" : "fill=\"white\" stroke=\"#456\"") << "><title>" << point.mode
        << ": " << number(point.milliseconds, 2) << " ms, mean FLIP " << number(point.meanFlip, 4)
        << (onFront ? " (Pareto front)" : "") << "</title></circle>\n";
    svg << "<text class=label x=\"" << wanted[k].x << "\" y=\"" << labelY[k] + kFont << "\""
        << (onFront ? " font-weight=\"bold\"" : "") << ">" << point.mode << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace iblkit
