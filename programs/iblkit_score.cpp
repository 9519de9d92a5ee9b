// iblkit-score: compares a test image with a reference (MSE, relMSE, PSNR, SSIM, FLIP), prints one
// line for people or JSON for scripts, and optionally writes an error heat map (docs/scoring.md).
#include <CLI/CLI.hpp>
#include <algorithm>
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

// Scores options.testFile against options.referenceFile and prints the scores.
int score(const Options& options) {
  const std::set<std::string> all(kMetrics.begin(), kMetrics.end());
  const std::set<std::string> metrics =
      options.metricList.empty()
          ? all
          : std::set<std::string>(options.metricList.begin(), options.metricList.end());
  const ScoreInputs inputs = loadScoreInputs(options.referenceFile, options.testFile, options.maskFile);
  const bool wantFlip =
      metrics.count("flip") || (!options.heatMapFile.empty() && options.heatMapMetric == "flip");

  nlohmann::json result = {{"reference", options.referenceFile}, {"test", options.testFile}};
  std::string line;
  const auto append = [&line](const std::string& text) { line += (line.empty() ? "" : "  ") + text; };
  result["scored_pixels"] =
      inputs.mask.empty() ? inputs.reference.pixelCount()
                          : static_cast<std::size_t>(std::count(inputs.mask.begin(), inputs.mask.end(), 1));
  if (metrics.count("relmse")) {
    const double relMse = relativeMeanSquaredError(inputs.reference, inputs.test, inputs.mask);
    result["relmse"] = relMse;
    append("relMSE " + formatted("%.4g", relMse));
  }
  if (metrics.count("mse") || metrics.count("psnr")) {
    const double mse = meanSquaredError(inputs.reference, inputs.test, inputs.mask);
    if (metrics.count("mse")) {
      result["mse"] = mse;
      append("MSE " + formatted("%.4g", mse));
    }
    if (metrics.count("psnr")) {
      const double psnr = peakSignalToNoiseRatio(mse);
      // JSON has no infinity: identical images give null.
      result["psnr"] = std::isinf(psnr) ? nlohmann::json() : nlohmann::json(psnr);
      append("PSNR " + (std::isinf(psnr) ? std::string("inf") : formatted("%.1f", psnr)) + " dB");
    }
  }
  if (metrics.count("ssim")) {
    const double ssim = structuralSimilarity(inputs.reference, inputs.test, inputs.mask);
    result["ssim"] = ssim;
    append("SSIM " + formatted("%.4f", ssim));
  }
  FlipErrorMap flipMap;
  if (wantFlip) {
    if (inputs.highDynamicRange) {
      if (!options.exposureRange.empty() && options.exposureRange[1] < options.exposureRange[0])
        failUsage("--exposure-range", "the stop exposure is below the start");
      const ExposureRange exposures =
          options.exposureRange.empty() ? automaticExposureRange(inputs.reference)
                                        : exposureBracket(options.exposureRange[0], options.exposureRange[1]);
      flipMap = hdrFlip(inputs.reference, inputs.test, exposures, options.pixelsPerDegree);
      result["flip_exposures"] = {
          {"start", exposures.start}, {"stop", exposures.stop}, {"count", exposures.count}};
      if (metrics.count("flip"))
        append("FLIP " + formatted("%.4f", maskedMean(flipMap.error, inputs.mask)) + " (HDR, exposures " +
               formatted("%.1f", exposures.start) + ".." + formatted("%.1f", exposures.stop) + ", " +
               std::to_string(exposures.count) + ")");
    } else {
      flipMap = ldrFlip(inputs.reference, inputs.test, options.pixelsPerDegree);
      if (metrics.count("flip"))
        append("FLIP " + formatted("%.4f", maskedMean(flipMap.error, inputs.mask)) + " (LDR)");
    }
    if (metrics.count("flip")) {
      result["flip"] = maskedMean(flipMap.error, inputs.mask);
      result["flip_kind"] = inputs.highDynamicRange ? "HDR" : "LDR";
    }
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
