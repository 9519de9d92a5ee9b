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

#include "core/error.h"
#include "score/flip.h"
#include "score/heat_map.h"
#include "score/image_metrics.h"
#include "score/score_images.h"
#include "score/score_inputs.h"

namespace {

std::string formatted(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace iblkit;
  CLI::App app{
      "Scores a test image against a reference: MSE, relMSE, PSNR, SSIM and FLIP (docs/scoring.md)."};
  std::string referenceFile, testFile, maskFile, heatMapFile, heatMapMetric = "flip";
  std::vector<std::string> metricList;
  std::vector<float> exposureRange;
  float pixelsPerDegree = kDefaultPixelsPerDegree;
  bool json = false;
  app.add_option("REFERENCE", referenceFile, "reference image (.exr/.hdr linear HDR, or .png sRGB)")
      ->required();
  app.add_option("TEST", testFile, "test image, same size and kind as the reference")->required();
  app.add_flag("--json", json, "print the scores as one JSON object");
  app.add_option("--heatmap", heatMapFile, "write a heat map of the per-pixel error (PNG)");
  app.add_option("--heatmap-metric", heatMapMetric, "error shown in the heat map")
      ->check(CLI::IsMember({"flip", "relmse"}));
  app.add_option("--mask", maskFile, "scored pixels: alpha (or luminance) > 0.5; default: the test's alpha");
  app.add_option("--metric", metricList, "metrics to compute (default: all)")
      ->check(CLI::IsMember({"mse", "relmse", "psnr", "ssim", "flip"}));
  app.add_option("--exposure-range", exposureRange, "HDR-FLIP start and stop exposures in stops")
      ->expected(2);
  app.add_option("--ppd", pixelsPerDegree, "pixels per degree of visual angle for FLIP")
      ->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);

  try {
    const std::set<std::string> all = {"mse", "relmse", "psnr", "ssim", "flip"};
    const std::set<std::string> metrics =
        metricList.empty() ? all : std::set<std::string>(metricList.begin(), metricList.end());
    const ScoreInputs inputs = loadScoreInputs(referenceFile, testFile, maskFile);
    ScoreOptions options;
    options.mse = metrics.count("mse") || metrics.count("psnr");
    options.relMse = metrics.count("relmse");
    options.ssim = metrics.count("ssim");
    options.flip = metrics.count("flip") || (!heatMapFile.empty() && heatMapMetric == "flip");
    options.meanRelativeError = false;
    options.highDynamicRange = inputs.highDynamicRange;
    options.pixelsPerDegree = pixelsPerDegree;
    if (options.flip && inputs.highDynamicRange && !exposureRange.empty()) {
      if (exposureRange[1] < exposureRange[0])
        throw Error("--exposure-range: the stop exposure is below the start");
      options.exposures = exposureBracket(exposureRange[0], exposureRange[1]);
    }
    FlipErrorMap flipMap;
    const ImageScores scores = scoreImages(inputs.reference, inputs.test, inputs.mask, options, &flipMap);

    nlohmann::json result = {{"reference", referenceFile}, {"test", testFile}};
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
      append("PSNR " + (std::isinf(scores.psnr) ? std::string("inf") : formatted("%.1f", scores.psnr)) +
             " dB");
    }
    if (metrics.count("ssim")) {
      result["ssim"] = scores.ssim;
      append("SSIM " + formatted("%.4f", scores.ssim));
    }
    if (options.flip && inputs.highDynamicRange) {
      const ExposureRange& exposures = scores.flipExposures;
      result["flip_exposures"] = {
          {"start", exposures.start}, {"stop", exposures.stop}, {"count", exposures.count}};
    }
    if (metrics.count("flip")) {
      const std::string kind = inputs.highDynamicRange
                                   ? " (HDR, exposures " + formatted("%.1f", scores.flipExposures.start) +
                                         ".." + formatted("%.1f", scores.flipExposures.stop) + ", " +
                                         std::to_string(scores.flipExposures.count) + ")"
                                   : std::string(" (LDR)");
      append("FLIP " + formatted("%.4f", scores.meanFlip) + kind);
      result["flip"] = scores.meanFlip;
      result["flip_kind"] = inputs.highDynamicRange ? "HDR" : "LDR";
    }
    if (!heatMapFile.empty()) {
      std::vector<float> values =
          heatMapMetric == "flip" ? flipMap.error : relativeSquaredErrorMap(inputs.reference, inputs.test);
      // Unscored pixels show as 0 (black): the map shows what was scored.
      for (std::size_t i = 0; i < inputs.mask.size(); ++i)
        if (!inputs.mask[i]) values[i] = 0.0f;
      writeHeatMap(heatMapFile, values, inputs.reference.width(), inputs.reference.height());
    }
    if (json)
      std::cout << result.dump(2) << "\n";
    else
      std::cout << line << "\n";
  } catch (const Error& e) {
    std::cerr << "iblkit-score: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
