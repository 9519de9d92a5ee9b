#include "report/report_case.h"

#include "report/case_modes.h"
#include "report/case_pictures.h"
#include "report/engine_frames.h"
#include "report/mode_scores.h"
#include "report/reference_passes.h"
#include "report/sh9_truncation.h"
#include "report/stage_commands.h"
#include "report/stage_run.h"

namespace iblkit {

namespace fs = std::filesystem;

namespace {

// What the `sh` frame gets wrong beyond SH9's own error; NaN without a scored `sh` frame.
double shBeyondSh9(const Reference& reference, const std::vector<Image>& frames,
                   const Sh9Truncation& truncation, const CaseResult& result) {
  double beyond = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t m = 0; m < result.modes.size(); ++m)
    if (result.modes[m].mode == "sh" && result.modes[m].failure.empty())
      beyond = errorBeyondSh9(reference.image, frames[m], truncation, reference.mask);
  return beyond;
}

}  // namespace

CaseResult runCase(const ReportSettings& settings, const StageCache& cache, const fs::path& sceneFile,
                   const fs::path& environmentFile) {
  CaseResult result;
  result.scene = sceneFile.stem().string();
  result.environment = environmentFile.stem().string();
  result.sceneFile = sceneFile;
  result.environmentFile = environmentFile;
  const std::string caseName = result.scene + "-" + result.environment;
  const CaseInputs inputs = caseInputs(sceneFile, environmentFile);
  ReportSettings caseSettings = settings;  // the stages below score caseSettings.modes
  caseSettings.modes = caseModes(settings.modes, inputs.lobes);
  for (const std::string& mode : settings.modes)
    if (std::string why = modeNotApplicable(mode, inputs.lobes); !why.empty()) result.notApplicable.push_back({mode, why});
  // Textured frames without sample shading (ReportSettings::engineSampleShading says why).
  if (inputs.textured) caseSettings.engineSampleShading = false;

  // The scene's visibility, shared by its bakes under every map (stage_commands.h).
  const StageRun visibility = runStage(cache, "visibility-" + result.scene, visibilityCommand(caseSettings, inputs));
  result.visibilitySeconds = visibility.seconds;
  result.commands.push_back(visibility.command);
  // The map's environment stages, shared by the bakes of every scene under it (stage_commands.h).
  const StageRun environment =
      runStage(cache, "environment-" + result.environment, environmentCommand(caseSettings, inputs));
  result.environmentSeconds = environment.seconds;
  result.commands.push_back(environment.command);
  const StageRun baked =
      runStage(cache, "bake-" + caseName, bakeCommand(caseSettings, inputs, visibility.folder, environment.folder));
  result.bakeSeconds = baked.seconds;
  result.commands.push_back(baked.command);
  const std::vector<Image> frames = renderEngineFrames(caseSettings, cache, caseName, baked.folder, result);
  const Reference reference = traceReference(caseSettings, cache, caseName, inputs, frames, result);
  result.pending = result.pending || visibility.pending || environment.pending || baked.pending;
  if (result.pending) return result;  // a scheduler runs the missing stages first
  const std::vector<FlipErrorMap> flipMaps = scoreModes(reference, frames, result);
  writeCasePictures(caseSettings.outDir, caseName, reference, frames, flipMaps, result);
  const Sh9Truncation truncation =
      caseSh9Truncation(sceneFile, environmentFile, baked.folder / "bake", reference.normals, reference.mask);
  result.sh9Truncation = truncation.meanRelativeError;
  result.shBeyondSh9 = shBeyondSh9(reference, frames, truncation, result);
  return result;
}

}  // namespace iblkit
