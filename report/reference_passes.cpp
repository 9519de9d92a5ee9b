#include "report/reference_passes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/halves_noise.h"
#include "core/image_io.h"
#include "report/frame_scores.h"
#include "report/stage_run.h"
#include "score/flip.h"
#include "score/halves_flip.h"
#include "score/image_metrics.h"

namespace iblkit {

namespace {

// The mean of the stages' images weighted by their passes (each image is the mean of its samples).
Image weightedMeanOf(const std::vector<const Image*>& images, const std::vector<int>& passes) {
  Image mean(images.front()->width(), images.front()->height());
  int total = 0;
  for (std::size_t k = 0; k < images.size(); ++k) {
    const float weight = float(passes[k]);
    total += passes[k];
    for (std::size_t i = 0; i < mean.pixelCount(); ++i) mean.pixels()[i] += weight * images[k]->pixels()[i];
  }
  for (glm::vec4& pixel : mean.pixels()) pixel /= float(total);
  return mean;
}

// Traces the stage with `seed` (`passes` passes in one run) and appends its beauty image to
// `stages`; stage 0 also gives the mask and the normals.
void traceStage(const ReportSettings& settings, const StageCache& cache, const std::string& caseName,
                const CaseInputs& inputs, int seed, int passes, std::vector<Image>& stages, Reference& reference,
                CaseResult& result) {
  const StageRun pass = runStage(cache, "trace-" + caseName + "-" + std::to_string(seed),
                                 traceCommand(settings, inputs, seed, passes));
  if (pass.pending) {
    result.pending = true;
    stages.emplace_back();
    return;
  }
  if (seed == 0) {
    result.commands.push_back(pass.command + "   (the first stage; " + std::to_string(settings.maxPasses) +
                              " passes of " + std::to_string(settings.passSpp) + " at most, up to " +
                              std::to_string(std::max(1, settings.maxStagePasses)) + " a stage)");
    const Image depth = readExr(pass.folder / "depth.exr");
    reference.mask = erodeMask(geometryMask(depth), depth.width(), depth.height());
    reference.normals = readExr(pass.folder / "normal.exr", nullptr, 0, PixelRepair::Keep);  // signed
  }
  result.traceSeconds += pass.seconds;
  stages.push_back(readExr(pass.folder / "beauty.exr", nullptr, 0, PixelRepair::Keep));
}

// The smallest relMSE of the frames against the reference; marks a frame of the wrong size as a
// failed mode. Only relMSE decides convergence: the full scores (FLIP is the costly one) come once.
double bestModeRelMse(const Reference& reference, const std::vector<Image>& frames, CaseResult& result) {
  const Image& image = reference.image;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t m = 0; m < result.modes.size(); ++m) {
    ModeResult& modeResult = result.modes[m];
    if (!modeResult.failure.empty() && frames[m].empty()) continue;
    if (frames[m].width() != image.width() || frames[m].height() != image.height()) {
      modeResult.failure = "frame is " + std::to_string(frames[m].width()) + "x" +
                           std::to_string(frames[m].height()) + ", reference is " +
                           std::to_string(image.width()) + "x" + std::to_string(image.height());
      continue;
    }
    const double relMse = relativeMeanSquaredError(image, frames[m], reference.mask);
    if (std::isfinite(relMse)) best = std::min(best, relMse);
  }
  return best;
}

}  // namespace

double referenceTargetRelMse(const ReportSettings& settings, double bestModeRelMse) {
  return std::min(settings.maxReferenceRelMse,
                  std::max(settings.negligibleRatio * bestModeRelMse, settings.negligibleRelMse));
}

int referencePassesFor(const ReportSettings& settings, int passes, double relMse, double target) {
  constexpr double kSpare = 1.25;
  const double aimed =
      target > 0.0 ? std::ceil(kSpare * passes * relMse / target) : double(settings.maxPasses);
  const int even = 2 * int(std::ceil(std::min(aimed, double(settings.maxPasses)) / 2.0));
  return std::clamp(even, std::min(passes + 2, settings.maxPasses), settings.maxPasses);
}

Reference traceReference(const ReportSettings& settings, const StageCache& cache, const std::string& caseName,
                         const CaseInputs& inputs, const std::vector<Image>& frames, CaseResult& result) {
  Reference reference;
  std::vector<Image> stages;
  std::vector<int> stagePasses;  // the passes of each stage
  int traced = 0;                // passes in the stages so far
  Image a, b;
  for (int count = settings.minPasses;;) {
    // The wave's passes, half to each half, in pairs of stages of at most maxStagePasses passes
    // (even seeds half A, odd seeds half B, so the halves always hold as many passes).
    for (int left = (count - traced) / 2; left > 0;) {
      const int group = std::min(left, std::max(1, settings.maxStagePasses));
      for (int half = 0; half < 2; ++half) {
        traceStage(settings, cache, caseName, inputs, int(stages.size()), group, stages, reference, result);
        stagePasses.push_back(group);
      }
      left -= group;
      traced += 2 * group;
    }
    // Collected passes or frames (StageCache::collectInto): the next wave is decided once they exist.
    if (result.pending) return reference;
    std::vector<const Image*> halfA, halfB;
    std::vector<int> passesA, passesB;
    for (std::size_t i = 0; i < stages.size(); ++i) {
      (i % 2 == 0 ? halfA : halfB).push_back(&stages[i]);
      (i % 2 == 0 ? passesA : passesB).push_back(stagePasses[i]);
    }
    a = weightedMeanOf(halfA, passesA);
    b = weightedMeanOf(halfB, passesB);
    reference.image = averageImages(a, b);
    result.referenceSpp = count * settings.passSpp;
    result.scoredPixels = scoredPixelCount(reference.mask, reference.image.pixelCount());
    if (result.scoredPixels == 0) fail(inputs.sceneFile, "no pixel of the reference sees geometry");
    result.referenceRelMse = halvesRelMseEstimate(a, b, reference.mask);
    result.flipExposures = automaticExposureRange(reference.image);
    const double target = referenceTargetRelMse(settings, bestModeRelMse(reference, frames, result));
    result.referenceConverged = result.referenceRelMse <= target;
    if (result.referenceConverged || count >= settings.maxPasses) break;
    count = referencePassesFor(settings, count, result.referenceRelMse, target);
  }
  result.referenceHalvesFlip = halvesMeanFlip(a, b, reference.mask, &result.flipExposures);
  return reference;
}

}  // namespace iblkit
