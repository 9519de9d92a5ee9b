// iblkit-score: compares a test image with a reference (MSE, relMSE, PSNR, SSIM, FLIP), prints one
// line for people or JSON for scripts, and optionally writes an error heat map (docs/scoring.md).
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "cli/program.h"
#include "core/error.h"
#include "core/usage_error.h"
#include "score/flip.h"
#include "score/heat_map.h"
#include "score/image_metrics.h"
#include "score/score_images.h"
#include "score/score_inputs.h"

namespace iblkit {
namespace {

constexpr const char* kProgram = "iblkit-score";

const std::vector<std::string> kMetrics = {"mse", "relmse", "psnr", "ssim", "flip"};
const std::vector<std::string> kHeatMapMetrics = {"flip", "relmse"};

struct Options {
  std::string referenceFile, testFile, maskFile, heatMapFile, heatMapMetric = "flip";
  std::vector<std::string> metricList;
  std::vector<float> exposureRange;
  float pixelsPerDegree = kDefaultPixelsPerDegree;
  bool json = false;
};

std::string formatted(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

// Scores options.testFile against options.referenceFile (scoreImages) and prints the scores.
int score(const Options& options) {
  const std::set<std::string> all(kMetrics.begin(), kMetrics.end());
  const std::set<std::string> metrics =
      options.metricList.empty()
          ? all
          : std::set<std::string>(options.metricList.begin(), options.metricList.end());
  checkOutputs({options.referenceFile, options.testFile, options.maskFile}, {options.heatMapFile});
  const ScoreInputs inputs = loadScoreInputs(options.referenceFile, options.testFile, options.maskFile);
  ScoreOptions scoring;
  scoring.mse = metrics.count("mse") || metrics.count("psnr");
  scoring.relMse = metrics.count("relmse");
  scoring.ssim = metrics.count("ssim");
  scoring.flip = metrics.count("flip") || (!options.heatMapFile.empty() && options.heatMapMetric == "flip");
  scoring.meanRelativeError = false;
  scoring.highDynamicRange = inputs.highDynamicRange;
  scoring.pixelsPerDegree = options.pixelsPerDegree;
  if (scoring.flip && inputs.highDynamicRange && !options.exposureRange.empty()) {
    if (options.exposureRange[1] < options.exposureRange[0])
      failUsage("--exposure-range", "the stop exposure is below the start");
    scoring.exposures = exposureBracket(options.exposureRange[0], options.exposureRange[1]);
  }
  FlipErrorMap flipMap;
  const ImageScores scores = scoreImages(inputs.reference, inputs.test, inputs.mask, scoring, &flipMap);

  nlohmann::json result = {{"reference", options.referenceFile}, {"test", options.testFile}};
  std::string line;
  const auto append = [&line](const std::string& text) { line += (line.empty() ? "" : "  ") + text; };
  result["scored_pixels"] = scores.scoredPixels;
  if (metrics.count("relmse")) {
    result["relmse"] = scores.relMse;
    append("relMSE " + formatted("%.4g", scores.relMse));
  }
  if (metrics.count("mse")) {
    result["mse"] = scores.mse;
    append("MSE " + formatted("%.4g", scores.mse));
  }
  if (metrics.count("psnr")) {
    // JSON has no infinity: identical images give null.
    result["psnr"] = std::isinf(scores.psnr) ? nlohmann::json() : nlohmann::json(scores.psnr);
    append("PSNR " + (std::isinf(scores.psnr) ? std::string("inf") : formatted("%.1f", scores.psnr)) + " dB");
  }
  if (metrics.count("ssim")) {
    result["ssim"] = scores.ssim;
    append("SSIM " + formatted("%.4f", scores.ssim));
  }
  if (scoring.flip && inputs.highDynamicRange) {
    const ExposureRange& exposures = scores.flipExposures;
    result["flip_exposures"] = {{"start", exposures.start}, {"stop", exposures.stop}, {"count", exposures.count}};
  }
  if (metrics.count("flip")) {
    const std::string kind = inputs.highDynamicRange
                                 ? " (HDR, exposures " + formatted("%.1f", scores.flipExposures.start) + ".." +
                                       formatted("%.1f", scores.flipExposures.stop) + ", " +
                                       std::to_string(scores.flipExposures.count) + ")"
                                 : std::string(" (LDR)");
    append("FLIP " + formatted("%.4f", scores.meanFlip) + kind);
    result["flip"] = scores.meanFlip;
    result["flip_kind"] = inputs.highDynamicRange ? "HDR" : "LDR";
  }
  if (!options.heatMapFile.empty()) {
    std::vector<float> values = options.heatMapMetric == "flip"
                                    ? flipMap.error
                                    : relativeSquaredErrorMap(inputs.reference, inputs.test);
    // Unscored pixels show as 0 (black): the map shows what was scored.
    for (std::size_t i = 0; i < inputs.mask.size(); ++i)
      if (!inputs.mask[i]) values[i] = 0.0f;
    writeHeatMap(options.heatMapFile, values, inputs.reference.width(), inputs.reference.height());
  }
  if (options.json)
    std::cout << result.dump(2) << "\n";
  else
    std::cout << line << "\n";
  return kExitSuccess;
}

}  // namespace
}  // namespace iblkit

int main(int argc, char** argv) {
  using namespace iblkit;
  Options options;
  CLI::App app{"Scores a test image against a reference: MSE, relMSE, PSNR, SSIM and FLIP (docs/scoring.md).",
               kProgram};
  app.add_option("REFERENCE", options.referenceFile, "reference image (.exr/.hdr linear HDR, or .png sRGB)")
      ->required();
  app.add_option("TEST", options.testFile, "test image, same size and kind as the reference")->required();
  app.add_flag("--json", options.json, "print the scores as one JSON object");
  app.add_option("--heatmap", options.heatMapFile, "write a heat map of the per-pixel error (PNG)");
  app.add_option("--heatmap-metric", options.heatMapMetric, "error shown in the heat map")
      ->check(nameChoice(kHeatMapMetrics, "heat map metric"))
      ->capture_default_str();
  app.add_option("--mask", options.maskFile,
                 "scored pixels: alpha (or luminance) > 0.5; default: the test's alpha");
  app.add_option("--metric", options.metricList, "metrics to compute (default: all)")
      ->check(nameChoice(kMetrics, "metric"));
  app.add_option("--exposure-range", options.exposureRange, "HDR-FLIP start and stop exposures in stops")
      ->expected(2);
  app.add_option("--ppd", options.pixelsPerDegree, "pixels per degree of visual angle for FLIP")
      ->check(CLI::PositiveNumber);
  return runProgram(app, argc, argv, [&] { return score(options); });
}
