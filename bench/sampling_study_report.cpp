#include "bench/sampling_study_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "score/image_metrics.h"

namespace iblkit {

namespace {

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

// `text` with the characters that XML reserves escaped (map names and labels come from the command line).
std::string xmlEscaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

std::string formatStudyNumber(double value) {
  if (value == 0.0) return "0";
  const double magnitude = std::fabs(value);
  if (magnitude >= 1e-3 && magnitude < 1e4) return format("%.3g", value);
  return format("%.2e", value);
}

std::string samplingStudyMarkdown(const SamplingStudySettings& settings, const std::string& sceneName,
                                  const std::vector<MapStudy>& maps) {
  const std::vector<int> levels = studySppLevels(settings.maxSpp);
  const std::size_t cosine = studyStrategyIndex(EnvSampling::Cosine);
  std::ostringstream md;
  md << "Scene `" << sceneName << "` ("
     << (settings.phong ? "every surface the modified Phong lobe of exponent " + format("%g", *settings.phong)
                        : std::string("its own materials"))
     << "; path integrator, max depth 16), " << settings.width << " x " << settings.height << ", "
     << settings.threads << " threads. relMSE (score/image_metrics.h, epsilon " << kRelMseEpsilon
     << ") against " << settings.referenceSpp
     << " spp of `mis` with another seed; \"floor\" is the reference's own expected "
        "relMSE (from its variance), included in every score.\n\n";
  md << "Ratio cosine / mis (relMSE at equal spp), per map: ";
  for (std::size_t m = 0; m < maps.size(); ++m) {
    double lo = 1e300, hi = 0.0;
    for (std::size_t i = 0; i < levels.size(); ++i) {
      const double ratio = relMseRatio(maps[m], EnvSampling::Cosine, EnvSampling::Mis, i);
      lo = std::min(lo, ratio);
      hi = std::max(hi, ratio);
    }
    md << (m ? "; " : "") << "**" << maps[m].name << "** " << formatStudyNumber(lo) << "x to "
       << formatStudyNumber(hi) << "x";
  }
  md << ".\n\n";
  // The median-cut strategies against mis where the noise is lowest: the unbiased sampler stays
  // near 1x, the point lights level off at their bias.
  md << "Median cut and point lights, relMSE over mis's at " << levels.back() << " spp, per map: ";
  const std::size_t mis = studyStrategyIndex(EnvSampling::Mis);
  for (std::size_t m = 0; m < maps.size(); ++m) {
    md << (m ? "; " : "") << "**" << maps[m].name << "**";
    bool first = true;
    for (std::size_t s = 0; s < kStudyStrategyCount; ++s) {
      if (kStudyStrategies[s].lights == 0) continue;
      md << (first ? " " : ", ") << kStudyStrategies[s].name << " "
         << formatStudyNumber(maps[m].relMse[s].back() / maps[m].relMse[mis].back()) << "x";
      first = false;
    }
  }
  md << ".\n";
  for (const MapStudy& map : maps) {
    md << "\n**" << map.name << "** (" << map.label << "), reference floor "
       << formatStudyNumber(map.referenceFloor) << "\n\n";
    md << "| strategy |";
    for (const int spp : levels) md << " " << spp << " spp |";
    md << " us / sample | cosine / strategy |\n|---|";
    for (std::size_t i = 0; i < levels.size() + 2; ++i) md << "---:|";
    md << "\n";
    for (std::size_t s = 0; s < kStudyStrategyCount; ++s) {
      md << "| " << kStudyStrategies[s].name << " |";
      double logRatioSum = 0.0;
      for (std::size_t i = 0; i < levels.size(); ++i) {
        md << " " << formatStudyNumber(map.relMse[s][i]) << " |";
        logRatioSum += std::log(map.relMse[cosine][i] / map.relMse[s][i]);
      }
      md << " " << format("%.2f", map.microsecondsPerSample[s]) << " | "
         << formatStudyNumber(std::exp(logRatioSum / static_cast<double>(levels.size()))) << " |\n";
    }
  }
  md << "\n\"cosine / strategy\" is the geometric mean over the spp levels of cosine's relMSE over the "
        "strategy's.\n";
  return md.str();
}

std::string samplingStudySvg(const SamplingStudySettings& settings, const std::vector<MapStudy>& maps) {
  const std::vector<int> levels = studySppLevels(settings.maxSpp);
  constexpr double kPanelWidth = 300, kPanelHeight = 260, kLeft = 62, kRight = 14, kTop = 30, kBottom = 44;
  const double width = kPanelWidth * static_cast<double>(maps.size()) + 130;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << kPanelHeight
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" "
         "fill=\"white\"/>\n";
  const double xMax = std::log2(static_cast<double>(levels.back()));
  for (std::size_t m = 0; m < maps.size(); ++m) {
    const MapStudy& map = maps[m];
    double lo = 1e300, hi = 0.0;
    for (const auto& line : map.relMse)
      for (const double v : line)
        if (v > 0.0) lo = std::min(lo, v), hi = std::max(hi, v);
    if (hi == 0.0) lo = hi = 1.0;  // nothing to plot: one decade of empty axes
    const int decadeLo = static_cast<int>(std::floor(std::log10(lo))),
              decadeHi = static_cast<int>(std::ceil(std::log10(hi)));
    const double x0 = kPanelWidth * static_cast<double>(m) + kLeft, plotWidth = kPanelWidth - kLeft - kRight;
    const double plotHeight = kPanelHeight - kTop - kBottom;
    const auto px = [&](int level) { return x0 + (xMax > 0 ? level / xMax : 0.0) * plotWidth; };
    const auto py = [&](double v) {
      return kTop + (decadeHi - std::log10(v)) / std::max(1, decadeHi - decadeLo) * plotHeight;
    };
    svg << "<text x=\"" << x0 + plotWidth / 2 << "\" y=\"18\" text-anchor=\"middle\" font-size=\"13\">"
        << xmlEscaped(map.name) << " (" << xmlEscaped(map.label) << ")</text>\n";
    svg << "<rect x=\"" << x0 << "\" y=\"" << kTop << "\" width=\"" << plotWidth << "\" height=\""
        << plotHeight << "\" fill=\"none\" stroke=\"black\"/>\n";
    for (int d = decadeLo; d <= decadeHi; ++d) {
      const double y = py(std::pow(10.0, d));
      svg << "<line x1=\"" << x0 << "\" x2=\"" << x0 + plotWidth << "\" y1=\"" << y << "\" y2=\"" << y
          << "\" stroke=\"#ddd\"/><text x=\"" << x0 - 4 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">1e"
          << d << "</text>\n";
    }
    for (std::size_t i = 0; i < levels.size(); ++i) {
      const double x = px(static_cast<int>(i));
      svg << "<line x1=\"" << x << "\" x2=\"" << x << "\" y1=\"" << kTop << "\" y2=\"" << kTop + plotHeight
          << "\" stroke=\"#eee\"/><text x=\"" << x << "\" y=\"" << kTop + plotHeight + 14
          << "\" text-anchor=\"middle\">" << levels[i] << "</text>\n";
    }
    svg << "<text x=\"" << x0 + plotWidth / 2 << "\" y=\"" << kPanelHeight - 8
        << "\" text-anchor=\"middle\">samples per pixel</text>\n";
    if (m == 0)
      svg << "<text transform=\"translate(14 " << kTop + plotHeight / 2
          << ") rotate(-90)\" text-anchor=\"middle\">relMSE</text>\n";
    for (std::size_t s = 0; s < kStudyStrategyCount; ++s) {
      svg << "<polyline fill=\"none\" stroke-width=\"2\" stroke=\"" << kStudyStrategies[s].colour
          << "\" points=\"";
      for (std::size_t i = 0; i < levels.size(); ++i)
        if (map.relMse[s][i] > 0.0) svg << px(static_cast<int>(i)) << "," << py(map.relMse[s][i]) << " ";
      svg << "\"/>\n";
    }
  }
  const double legendX = kPanelWidth * static_cast<double>(maps.size()) + 10;
  for (std::size_t s = 0; s < kStudyStrategyCount; ++s) {
    const double y = kTop + 10 + 18 * static_cast<double>(s);
    svg << "<line x1=\"" << legendX << "\" x2=\"" << legendX + 24 << "\" y1=\"" << y << "\" y2=\"" << y
        << "\" stroke-width=\"2\" stroke=\"" << kStudyStrategies[s].colour << "\"/><text x=\"" << legendX + 30
        << "\" y=\"" << y + 4 << "\">" << kStudyStrategies[s].name << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace iblkit
