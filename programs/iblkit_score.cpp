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

#include "core/error.h"
#include "score/flip.h"
#include "score/heat_map.h"
#include "score/image_metrics.h"
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
    const bool wantFlip = metrics.count("flip") || (!heatMapFile.empty() && heatMapMetric == "flip");

    nlohmann::json result = {{"reference", referenceFile}, {"test", testFile}};
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
        if (!exposureRange.empty() && exposureRange[1] < exposureRange[0])
          throw Error("--exposure-range: the stop exposure is below the start");
        const ExposureRange exposures = exposureRange.empty()
                                            ? automaticExposureRange(inputs.reference)
                                            : exposureBracket(exposureRange[0], exposureRange[1]);
        flipMap = hdrFlip(inputs.reference, inputs.test, exposures, pixelsPerDegree);
        result["flip_exposures"] = {
            {"start", exposures.start}, {"stop", exposures.stop}, {"count", exposures.count}};
        if (metrics.count("flip"))
          append("FLIP " + formatted("%.4f", maskedMean(flipMap.error, inputs.mask)) + " (HDR, exposures " +
                 formatted("%.1f", exposures.start) + ".." + formatted("%.1f", exposures.stop) + ", " +
                 std::to_string(exposures.count) + ")");
      } else {
        flipMap = ldrFlip(inputs.reference, inputs.test, pixelsPerDegree);
        if (metrics.count("flip"))
          append("FLIP " + formatted("%.4f", maskedMean(flipMap.error, inputs.mask)) + " (LDR)");
      }
      if (metrics.count("flip")) {
        result["flip"] = maskedMean(flipMap.error, inputs.mask);
        result["flip_kind"] = inputs.highDynamicRange ? "HDR" : "LDR";
      }
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
