// sampling_study: the environment-sampling study of the reference path tracer (issue 3; results
// in docs/benchmarks.md, "Reference tracer").
//
// Renders the bundled bunny-on-plane scene (`path` integrator) under several environment maps with
// each --env-sampling strategy (uniform, cosine, brdf, env, mis) at equal sample counts 1, 2, 4,
// ..., --max-spp, and scores every render by its relMSE (score/image_metrics.h) against a
// high-spp MIS render of the same map (rendered once with another seed and cached as OpenEXR in
// --cache). Also measures the time per camera sample of each strategy. Writes a markdown table
// (--out-dir/NAME.md), a log-log plot of relMSE against spp, one panel per map and one line per
// strategy (--out-dir/NAME.svg), and, with --update FILE, replaces the text between the lines
// "<!-- NAME:begin -->" and "<!-- NAME:end -->" of FILE with the table; NAME is --name
// (default sampling_study). --phong E gives every surface the modified Phong lobe of exponent E
// (the second material model, a glossy lobe that BRDF sampling follows) instead of the
// scene's glTF materials.
//
// The reference has noise of its own: the expected relMSE of a test render against it is the
// test's own plus the reference's, which the reference's per-pixel variance estimates (the
// "floor" in the table). The floor is reported, not subtracted.

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "engine/core/environment_map_file.h"
#include "engine/core/error.h"
#include "engine/core/file_io.h"
#include "engine/core/image_io.h"
#include "engine/core/scene.h"
#include "reference/environment_sampler.h"
#include "reference/integrator.h"
#include "reference/render_scene.h"
#include "reference/renderer.h"
#include "score/image_metrics.h"

namespace iblkit {
namespace {

constexpr std::uint32_t kReferenceSeed = 0x5eed5eedU;

struct Strategy {
  const char* name;
  EnvSampling sampling;
  const char* colour;
};
constexpr Strategy kStrategies[] = {{"uniform", EnvSampling::Uniform, "#7f7f7f"},
                                    {"cosine", EnvSampling::Cosine, "#1f77b4"},
                                    {"brdf", EnvSampling::Brdf, "#2ca02c"},
                                    {"env", EnvSampling::Env, "#ff7f0e"},
                                    {"mis", EnvSampling::Mis, "#d62728"}};
constexpr int kStrategyCount = static_cast<int>(std::size(kStrategies));

struct Options {
  std::filesystem::path scene, assets, cache = "build/sampling_study", outDir = "docs/benchmarks", update;
  std::vector<std::string> maps{"sky:sunny", "studio:studio", "venice:soft"};
  int width = 160, height = 90, maxSpp = 64, referenceSpp = 4096, threads = 2;
  std::optional<float> phong;
  std::string name = "sampling_study";

  IntegratorSettings integratorSettings(EnvSampling sampling) const {
    IntegratorSettings settings;
    settings.envSampling = sampling;
    if (phong) settings.phong = PhongLobe{*phong};
    return settings;
  }
};

struct MapResult {
  std::string name, label;
  double referenceFloor = 0.0;  // expected relMSE of the reference itself
  double referenceSeconds = 0.0;
  bool referenceCached = false;
  // [strategy][spp level]
  std::vector<std::vector<double>> relMse;
  std::vector<double> microsecondsPerSample;  // per strategy, over all its renders
};

std::vector<int> sppLevels(int maxSpp) {
  std::vector<int> levels;
  for (int spp = 1; spp <= maxSpp; spp *= 2) levels.push_back(spp);
  return levels;
}

// Mean over pixels and RGB of var(reference pixel) / (reference^2 + epsilon): the relMSE the
// reference's own noise adds to every score against it.
double referenceNoiseFloor(const Image& reference, const Image& variance) {
  double sum = 0.0;
  for (std::size_t i = 0; i < reference.pixelCount(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double r = reference.pixels()[i][c];
      sum += variance.pixels()[i][c] / (r * r + kRelMseEpsilon);
    }
  return sum / (3.0 * static_cast<double>(reference.pixelCount()));
}

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

// Three significant digits in plain or scientific notation, whichever reads better.
std::string number(double value) {
  if (value == 0.0) return "0";
  const double magnitude = std::fabs(value);
  if (magnitude >= 1e-3 && magnitude < 1e4) return format("%.3g", value);
  return format("%.2e", value);
}

MapResult studyMap(const Options& options, const Scene& baseScene, const std::string& name,
                   const std::string& label) {
  MapResult out;
  out.name = name;
  out.label = label;
  const std::filesystem::path mapFile = options.assets / "hdri" / (name + ".exr");
  EnvironmentMap environment = loadEnvironmentMap(mapFile);
  environment.setRotationDegrees(baseScene.environment.rotationDegrees);
  environment.setIntensity(baseScene.environment.intensity);
  const EnvironmentSampler sampler(environment);
  const Camera camera = sceneCamera(baseScene, static_cast<float>(options.width) / options.height);
  const RenderScene scene(baseScene);

  RenderSettings settings;
  settings.width = options.width;
  settings.height = options.height;
  settings.threads = options.threads;

  // The reference, cached by map, size and sample count.
  const std::string key = name + "_" + std::to_string(options.width) + "x" + std::to_string(options.height) +
                          "_" + std::to_string(options.referenceSpp) + "spp" +
                          (options.phong ? "_phong" + format("%g", *options.phong) : std::string());
  const std::filesystem::path referenceFile = options.cache / ("reference_" + key + ".exr");
  const std::filesystem::path varianceFile = options.cache / ("reference_" + key + "_variance.exr");
  Image reference, variance;
  if (std::filesystem::exists(referenceFile) && std::filesystem::exists(varianceFile)) {
    reference = readExr(referenceFile);
    variance = readExr(varianceFile);
    out.referenceCached = true;
  } else {
    std::printf("%s: rendering the reference, %d spp mis\n", name.c_str(), options.referenceSpp);
    std::fflush(stdout);
    const Integrator integrator(scene, environment, sampler, options.integratorSettings(EnvSampling::Mis));
    RenderSettings referenceSettings = settings;
    referenceSettings.samplesPerPixel = options.referenceSpp;
    referenceSettings.seed = kReferenceSeed;
    RenderResult result = render(integrator, camera, referenceSettings);
    out.referenceSeconds = result.seconds;
    reference = std::move(result.beauty);
    variance = std::move(result.variance);
    std::filesystem::create_directories(options.cache);
    writeExr(referenceFile, reference, {.pixelType = PixelType::Float});
    writeExr(varianceFile, variance, {.pixelType = PixelType::Float});
  }
  if (reference.width() != options.width || reference.height() != options.height)
    fail(referenceFile, "cached reference has the wrong size (delete the cache folder)");
  out.referenceFloor = referenceNoiseFloor(reference, variance);

  const std::vector<int> levels = sppLevels(options.maxSpp);
  for (const Strategy& strategy : kStrategies) {
    const Integrator integrator(scene, environment, sampler, options.integratorSettings(strategy.sampling));
    std::vector<double> scores;
    double seconds = 0.0, samples = 0.0;
    for (std::size_t level = 0; level < levels.size(); ++level) {
      settings.samplesPerPixel = levels[level];
      settings.seed = static_cast<std::uint32_t>(level + 1);
      const RenderResult result = render(integrator, camera, settings);
      scores.push_back(relativeMeanSquaredError(reference, result.beauty));
      seconds += result.seconds;
      samples += static_cast<double>(options.width) * options.height * levels[level];
    }
    out.relMse.push_back(scores);
    out.microsecondsPerSample.push_back(1e6 * seconds / samples);
    std::printf("%s %-7s relMSE %s at 1 spp, %s at %d spp; %.2f us/sample\n", name.c_str(), strategy.name,
                number(scores.front()).c_str(), number(scores.back()).c_str(), levels.back(),
                out.microsecondsPerSample.back());
    std::fflush(stdout);
  }
  return out;
}

std::string markdownTable(const Options& options, const std::vector<MapResult>& results) {
  const std::vector<int> levels = sppLevels(options.maxSpp);
  std::ostringstream md;
  md << "Scene `bunny.json` ("
     << (options.phong ? "every surface the modified Phong lobe of exponent " + format("%g", *options.phong)
                       : std::string("its own materials"))
     << "; path integrator, max depth 16), " << options.width << " x " << options.height << ", "
     << options.threads << " threads. relMSE (score/image_metrics.h, epsilon 0.01) against "
     << options.referenceSpp
     << " spp of `mis` with another seed; \"floor\" is the reference's own expected "
        "relMSE (from its variance), included in every score.\n\n";
  md << "Ratio cosine / mis (relMSE at equal spp), per map: ";
  for (std::size_t m = 0; m < results.size(); ++m) {
    const auto& cosine = results[m].relMse[1];
    const auto& mis = results[m].relMse[4];
    double lo = 1e300, hi = 0.0;
    for (std::size_t i = 0; i < levels.size(); ++i) {
      const double ratio = cosine[i] / mis[i];
      lo = std::min(lo, ratio);
      hi = std::max(hi, ratio);
    }
    md << (m ? "; " : "") << "**" << results[m].name << "** " << number(lo) << "x to " << number(hi) << "x";
  }
  md << ".\n";
  for (const MapResult& r : results) {
    md << "\n**" << r.name << "** (" << r.label << "), reference floor " << number(r.referenceFloor)
       << "\n\n";
    md << "| strategy |";
    for (const int spp : levels) md << " " << spp << " spp |";
    md << " us / sample | cosine / strategy |\n|---|";
    for (std::size_t i = 0; i < levels.size() + 2; ++i) md << "---:|";
    md << "\n";
    for (int s = 0; s < kStrategyCount; ++s) {
      md << "| " << kStrategies[s].name << " |";
      double ratioSum = 0.0;
      for (std::size_t i = 0; i < levels.size(); ++i) {
        md << " " << number(r.relMse[s][i]) << " |";
        ratioSum += std::log(r.relMse[1][i] / r.relMse[s][i]);
      }
      md << " " << format("%.2f", r.microsecondsPerSample[s]) << " | "
         << number(std::exp(ratioSum / static_cast<double>(levels.size()))) << " |\n";
    }
  }
  md << "\n\"cosine / strategy\" is the geometric mean over the spp levels of cosine's relMSE over the "
        "strategy's.\n";
  return md.str();
}

std::string svgPlot(const Options& options, const std::vector<MapResult>& results) {
  const std::vector<int> levels = sppLevels(options.maxSpp);
  constexpr double kPanelWidth = 300, kPanelHeight = 260, kLeft = 62, kRight = 14, kTop = 30, kBottom = 44;
  const double width = kPanelWidth * static_cast<double>(results.size()) + 130;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << kPanelHeight
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" "
         "fill=\"white\"/>\n";
  const double xMax = std::log2(static_cast<double>(levels.back()));
  for (std::size_t m = 0; m < results.size(); ++m) {
    const MapResult& r = results[m];
    double lo = 1e300, hi = 0.0;
    for (const auto& line : r.relMse)
      for (const double v : line)
        if (v > 0.0) lo = std::min(lo, v), hi = std::max(hi, v);
    const int decadeLo = static_cast<int>(std::floor(std::log10(lo))),
              decadeHi = static_cast<int>(std::ceil(std::log10(hi)));
    const double x0 = kPanelWidth * static_cast<double>(m) + kLeft, plotWidth = kPanelWidth - kLeft - kRight;
    const double plotHeight = kPanelHeight - kTop - kBottom;
    const auto px = [&](int level) { return x0 + (xMax > 0 ? level / xMax : 0.0) * plotWidth; };
    const auto py = [&](double v) {
      return kTop + (decadeHi - std::log10(v)) / std::max(1, decadeHi - decadeLo) * plotHeight;
    };
    svg << "<text x=\"" << x0 + plotWidth / 2 << "\" y=\"18\" text-anchor=\"middle\" font-size=\"13\">"
        << r.name << " (" << r.label << ")</text>\n";
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
    for (int s = 0; s < kStrategyCount; ++s) {
      svg << "<polyline fill=\"none\" stroke-width=\"2\" stroke=\"" << kStrategies[s].colour
          << "\" points=\"";
      for (std::size_t i = 0; i < levels.size(); ++i)
        if (r.relMse[s][i] > 0.0) svg << px(static_cast<int>(i)) << "," << py(r.relMse[s][i]) << " ";
      svg << "\"/>\n";
    }
  }
  const double legendX = kPanelWidth * static_cast<double>(results.size()) + 10;
  for (int s = 0; s < kStrategyCount; ++s) {
    const double y = kTop + 10 + 18 * s;
    svg << "<line x1=\"" << legendX << "\" x2=\"" << legendX + 24 << "\" y1=\"" << y << "\" y2=\"" << y
        << "\" stroke-width=\"2\" stroke=\"" << kStrategies[s].colour << "\"/><text x=\"" << legendX + 30
        << "\" y=\"" << y + 4 << "\">" << kStrategies[s].name << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

void writeText(const std::filesystem::path& file, const std::string& text) {
  std::ofstream stream(file, std::ios::binary);
  stream << text;
  if (!stream) fail(file, "cannot write");
}

// `file`'s text with the text between the markers of section `name` replaced by `text`; fails
// (before anything is rendered, when called with an empty text first) if the section is missing.
std::string withSection(const std::filesystem::path& file, const std::string& name, const std::string& text) {
  const std::string beginMarker = "<!-- " + name + ":begin -->", endMarker = "<!-- " + name + ":end -->";
  std::ifstream in(file, std::ios::binary);
  if (!in) fail(file, "cannot read");
  std::ostringstream whole;
  whole << in.rdbuf();
  const std::string content = whole.str();
  const std::size_t begin = content.find(beginMarker), end = content.find(endMarker);
  if (begin == std::string::npos || end == std::string::npos || end < begin)
    fail(file, "has no " + beginMarker + " ... " + endMarker + " section");
  const std::size_t afterBegin = begin + beginMarker.size();
  return content.substr(0, afterBegin) + "\n" + text + content.substr(end);
}

int run(const Options& options) {
  if (options.width < 1 || options.height < 1 || options.maxSpp < 1 || options.referenceSpp < 1)
    fail("sampling_study", "sizes and sample counts must be positive");
  if (options.phong && !(std::isfinite(*options.phong) && *options.phong >= 0.0f))
    fail("--phong", "exponent must be finite and >= 0");
  if (!std::filesystem::is_directory(options.outDir)) fail(options.outDir, "folder does not exist");
  if (!options.update.empty()) withSection(options.update, options.name, "");
  const Scene scene =
      loadScene(options.scene.empty() ? options.assets / "scenes" / "bunny.json" : options.scene);
  std::vector<MapResult> results;
  for (const std::string& entry : options.maps) {
    const std::size_t colon = entry.find(':');
    const std::string name = entry.substr(0, colon);
    const std::string label = colon == std::string::npos ? name : entry.substr(colon + 1);
    results.push_back(studyMap(options, scene, name, label));
    std::printf("%s: reference %s (%.1f s), floor %s\n", name.c_str(),
                results.back().referenceCached ? "cached" : "rendered", results.back().referenceSeconds,
                number(results.back().referenceFloor).c_str());
  }
  const std::string table = markdownTable(options, results);
  writeText(options.outDir / (options.name + ".md"), "# Sampling study\n\n" + table);
  writeText(options.outDir / (options.name + ".svg"), svgPlot(options, results));
  if (!options.update.empty()) writeText(options.update, withSection(options.update, options.name, table));
  std::printf("%s", table.c_str());
  return 0;
}

}  // namespace
}  // namespace iblkit

int main(int argc, char** argv) {
  using namespace iblkit;
  Options options;
  const char* assets = std::getenv("IBLKIT_ASSETS");
  options.assets = assets && *assets ? assets : "assets";
  CLI::App app{
      "sampling_study: relMSE of each environment-sampling strategy against spp (docs/benchmarks.md)"};
  app.add_option("--assets", options.assets, "assets folder (default $IBLKIT_ASSETS or ./assets)");
  app.add_option("--scene", options.scene, "scene (default ASSETS/scenes/bunny.json)");
  app.add_option("--maps", options.maps, "maps in ASSETS/hdri as NAME[:LABEL]")->delimiter(',');
  app.add_option("--width", options.width, "image width");
  app.add_option("--height", options.height, "image height");
  app.add_option("--max-spp", options.maxSpp, "largest sample count (1, 2, 4, ... up to it)");
  app.add_option("--reference-spp", options.referenceSpp, "samples per pixel of the reference");
  app.add_option("--threads", options.threads, "worker threads");
  app.add_option("--cache", options.cache, "folder of the cached references");
  app.add_option("--out-dir", options.outDir, "where NAME.md and NAME.svg go");
  app.add_option("--name", options.name,
                 "name of the outputs and of the --update section (default sampling_study)");
  app.add_option("--phong", options.phong, "every surface uses the modified Phong lobe of this exponent");
  app.add_option("--update", options.update, "markdown file whose sampling-study section gets the table");
  CLI11_PARSE(app, argc, argv);
  try {
    return run(options);
  } catch (const std::exception& e) {
    std::cerr << "sampling_study: " << e.what() << "\n";
    return 1;
  }
}
