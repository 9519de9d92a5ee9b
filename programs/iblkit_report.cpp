// iblkit-report: iblkit's main job. Bakes each scene under each environment map, renders every
// real-time mode headless, path-traces the reference and scores each mode against it, then writes
// OUT/report.html and OUT/report.json (docs/report.md). Stages are cached by their inputs' hash.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "cli/program.h"
#include "core/error.h"
#include "core/environment_map_file.h"
#include "core/file_io.h"
#include "core/usage_error.h"
#include "bakefile/bake_record.h"
#include "report/report_case.h"
#include "report/map_kind.h"
#include "report/report_claims.h"
#include "report/report_writer.h"
#include "report/pending_stages.h"
#include "report/slurm_scheduler.h"
#include "report/stage_plan.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

constexpr const char* kProgram = "iblkit-report";

struct Options {
  // The untextured scenes, then the textured ones (pmndrs.glb as shipped; the same model with a
  // normal map from the package assigned in the scene file).
  std::vector<std::string> scenes = {"assets/scenes/mirror_sphere.json", "assets/scenes/diffuse_sphere.json",
                                     "assets/scenes/bunny.json",         "assets/scenes/suzi.json",
                                     "assets/scenes/pmndrs.json",        "assets/scenes/tiles.json"};
  std::vector<std::string> environments = {"sky", "esplanade", "studio", "city", "forest", "sunset"};
  std::string environmentFolder = "assets/hdri", output = "out/demo", cacheFolder, binFolder;
  ReportSettings settings;
  bool strict = false, force = false;
  std::string scheduler = "local";  // or "slurm" (slurm_scheduler.h)
  SlurmOptions slurm;
  std::string sbatchArguments, viewSbatchArguments;  // split at white space into slurm's
  // The hidden task mode a Slurm array runs: --stage-task PLAN --task-index I (stage_plan.h).
  std::string stageTask;
  int taskIndex = -1;
};

// One case of the report: a scene under a map, and its result once every stage it needs exists.
struct PlannedCase {
  std::string scene;
  fs::path environment;
  std::optional<CaseResult> result;
  int stages = 0;  // the stages its finished pass found (cached or run)
};

// The report folder's kind: the marker the report writes first (so that a rerun after an
// interrupt finds it), or the report.json of a finished report.
const OutputFolderKind kReportFolder{"iblkit report folder", {".iblkit-report", "report.json"}};

// ENV-DIR/NAME.exr for a bare name, else the path given.
fs::path environmentFile(const Options& options, const std::string& name) {
  return name.find('/') != std::string::npos || fs::path(name).has_extension()
             ? fs::path(name)
             : fs::path(options.environmentFolder) / (name + ".exr");
}

fs::path programFolder() {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  return error ? fs::path("build/bin") : self.parent_path();
}

std::vector<std::string> splitAtSpaces(const std::string& text) {
  std::vector<std::string> words;
  std::istringstream stream(text);
  for (std::string word; stream >> word;) words.push_back(word);
  return words;
}

// Runs each case that is not finished yet, in order, through `cache`. When the cache collects
// missing stages, a case that needs one stays unfinished and its stages are in `pending`.
// `submitted` names the cases that had stages run by a scheduler in earlier passes (not cached).
void runCases(const ReportSettings& settings, const StageCache& cache, PendingStages* pending,
              const std::set<std::string>& submitted, std::vector<PlannedCase>& cases,
              std::map<fs::path, MapConcentration>& concentrations) {
  for (PlannedCase& reportCase : cases) {
    if (reportCase.result) continue;
    const std::string caseName =
        fs::path(reportCase.scene).stem().string() + "-" + reportCase.environment.stem().string();
    if (pending) pending->setCase(caseName);
    const int hits = cache.hits(), misses = cache.misses();
    CaseResult result = runCase(settings, cache, reportCase.scene, reportCase.environment);
    if (result.pending) continue;
    reportCase.stages = cache.hits() - hits + cache.misses() - misses;
    const fs::path& environment = reportCase.environment;
    if (!concentrations.contains(environment))
      concentrations[environment] = mapConcentration(loadEnvironmentMap(environment));
    result.concentration = concentrations[environment];
    result.mapKind = classifyMap(result.concentration);
    const bool cached = pending ? !submitted.contains(caseName) : cache.misses() == misses;
    std::fprintf(
        stderr, "iblkit-report: %s under %s: reference %d spp (relMSE %.2g, halves' FLIP %.3f, %s)%s\n",
        result.scene.c_str(), result.environment.c_str(), result.referenceSpp, result.referenceRelMse,
        result.referenceHalvesFlip, result.referenceConverged ? "converged" : "not converged",
        cached ? ", cached" : "");
    reportCase.result = std::move(result);
  }
}

// Runs every case, writes the report and prints the claims.
int report(Options& options) {
  ReportSettings& settings = options.settings;
  if (settings.minPasses % 2 != 0 || settings.maxPasses % 2 != 0 || settings.maxPasses < settings.minPasses)
    throw UsageError("--min-passes and --max-passes must be even, min <= max");
  for (std::size_t m = 0; m < settings.modes.size(); ++m)
    if (std::find(settings.modes.begin(), settings.modes.begin() + std::ptrdiff_t(m), settings.modes[m]) !=
        settings.modes.begin() + std::ptrdiff_t(m))
      throw UsageError("--modes: '" + settings.modes[m] + "' is listed twice");
  const auto start = std::chrono::steady_clock::now();
  settings.outDir = options.output;
  settings.binDir = options.binFolder.empty() ? programFolder() : fs::path(options.binFolder);
  std::vector<fs::path> inputs(options.scenes.begin(), options.scenes.end());
  for (const std::string& name : options.environments) inputs.push_back(environmentFile(options, name));
  checkOutputs(inputs, {settings.outDir / "report.json", settings.outDir / "report.html"},
               {OutputFolder(settings.outDir, kReportFolder, /*replaced=*/false)}, options.force);
  std::error_code error;
  fs::create_directories(settings.outDir, error);
  if (error) fail(settings.outDir, "cannot create folder: " + error.message());
  writeAtomically(settings.outDir / kReportFolder.markers.front(),
                  [](const fs::path& temporary) { std::ofstream(temporary) << "iblkit-report\n"; });
  StageCache cache(options.cacheFolder.empty() ? settings.outDir / "cache"
                                                     : fs::path(options.cacheFolder));

  std::vector<PlannedCase> cases;
  for (const std::string& scene : options.scenes) {
    if (!fs::is_regular_file(scene)) fail(scene, "scene file does not exist");
    for (const std::string& name : options.environments) {
      const fs::path environment = environmentFile(options, name);
      if (!fs::is_regular_file(environment)) fail(environment, "environment map does not exist");
      cases.push_back({scene, environment, std::nullopt, 0});
    }
  }
  std::map<fs::path, MapConcentration> concentrations;  // each map read once, for its kind
  ReportSummary summary;
  summary.modes = settings.modes;
  if (options.scheduler == "slurm") {
    // Waves: a pass collects what is missing, Slurm runs it, and the next pass goes on from there
    // with the same code as a local run, until a pass finds every stage (docs/cluster.md).
    options.slurm.reportProgram = programFolder() / kProgram;
    options.slurm.sbatchArguments = splitAtSpaces(options.sbatchArguments);
    options.slurm.viewSbatchArguments = splitAtSpaces(options.viewSbatchArguments);
    SlurmScheduler scheduler(options.slurm, cache.root());
    std::set<std::string> submitted;
    for (;;) {
      PendingStages pending;
      cache.collectInto(&pending);
      runCases(settings, cache, &pending, submitted, cases, concentrations);
      cache.collectInto(nullptr);
      if (pending.empty()) break;
      for (const PendingStage& stage : pending.stages()) submitted.insert(stage.caseName);
      scheduler.runWave(pending);
    }
    int stages = 0;
    for (const PlannedCase& reportCase : cases) stages += reportCase.stages;
    summary.runStages = scheduler.stagesRun();
    summary.cachedStages = stages - summary.runStages;
    std::fprintf(stderr, "iblkit-report: slurm: %d stages run in %d waves (%d tasks submitted)\n",
                 scheduler.stagesRun(), scheduler.waves(), scheduler.tasksSubmitted());
  } else {
    runCases(settings, cache, nullptr, {}, cases, concentrations);
    summary.cachedStages = cache.hits();
    summary.runStages = cache.misses();
  }
  for (PlannedCase& reportCase : cases) summary.cases.push_back(std::move(*reportCase.result));
  summary.claims = evaluateClaims(summary.cases);
  summary.settings = settings;
  summary.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  writeReportJson(settings.outDir / "report.json", summary);
  writeReportHtml(settings.outDir / "report.html", summary);

  int holding = 0;
  for (const Claim& claim : summary.claims) {
    holding += claim.holds ? 1 : 0;
    std::printf("%s %s: measured %.4g, bound %.4g (%s)\n",
                claim.holds ? "holds:" : "FAILS:", claim.statement.c_str(), claim.measured, claim.bound,
                claim.detail.c_str());
  }
  std::printf("iblkit-report: wrote %s (%zu cases, %d of %zu claims hold, %.1f s)\n",
              (settings.outDir / "report.html").c_str(), summary.cases.size(), holding, summary.claims.size(),
              summary.totalSeconds);
  return options.strict && holding < int(summary.claims.size()) ? kExitClaimFails : kExitSuccess;
}

}  // namespace
}  // namespace iblkit

int main(int argc, char** argv) {
  using namespace iblkit;
  Options options;
  ReportSettings& settings = options.settings;
  // full-gltf-ao and full-both-ao run only on scenes with a glTF occlusion texture (report/case_modes.h).
  // lights and lights-shadowed (the dominant lights plus the residual, issue 15) after full, which
  // they are measured against (report_claims.h).
  settings.modes = {"mirror", "sh",     "irradiance",      "sh-ao",        "sh-ao-bent",  "prt",
                    "full",   "lights", "lights-shadowed", "full-gltf-ao", "full-both-ao"};
  CLI::App app{"Scores every real-time mode against the path-traced reference", kProgram};
  app.add_option("scenes", options.scenes, "scene files (.json, .gltf, .glb)");
  app.add_option("--envs", options.environments, "environment map names (files ENV-DIR/NAME.exr) or paths")
      ->delimiter(',');
  app.add_option("--env-dir", options.environmentFolder, "folder of the environment maps");
  app.add_option("-o,--output", options.output, "report folder (report.html, report.json, images/)");
  addForceOption(app, options.force);
  app.add_option("--cache", options.cacheFolder, "stage cache folder (default: OUTPUT/cache)");
  app.add_option("--bin", options.binFolder,
                 "folder of iblkit-bake, iblkit-trace, iblkit-view (default: this program's)");
  app.add_option("--width", settings.width, "image width")->check(CLI::Range(8, 4096));
  app.add_option("--height", settings.height, "image height")->check(CLI::Range(8, 4096));
  app.add_option("--modes", settings.modes, "engine modes to score, in ladder order")->delimiter(',');
  app.add_option("--pass-spp", settings.passSpp, "samples per pixel of one reference pass")->check(CLI::Range(1, 65536));
  app.add_option("--min-passes", settings.minPasses, "reference passes before the first convergence check")
      ->check(CLI::Range(2, 4096));
  app.add_option("--max-passes", settings.maxPasses, "most reference passes")->check(CLI::Range(2, 4096));
  app.add_option("--max-stage-passes", settings.maxStagePasses,
                 "most reference passes one iblkit-trace run traces together (1: a run per pass; "
                 "more: fewer runs, better stratified samples; --scheduler slurm: fewer, longer tasks)")
      ->check(CLI::Range(1, 4096));
  app.add_option("--negligible", settings.negligibleRatio,
                 "converged when the reference's relMSE is at most this fraction of the best mode's")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--negligible-relmse", settings.negligibleRelMse, "...or, when larger, at most this relMSE")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option(
         "--max-reference-relmse", settings.maxReferenceRelMse,
         "a converged reference's estimated relMSE is at most this, whatever the modes' (default 1e-3)")
      ->check(CLI::Range(0.0, 1e9));
  app.add_option("--reference-light-samples", settings.referenceLightSamples,
                 "iblkit-trace --camera-light-samples of the reference passes (default 2)")
      ->check(CLI::Range(1, 64));
  app.add_option("--bake-bounces", settings.bakeBounces,
                 "iblkit-bake --bounces of the bakes: interreflection in the SH transfer (default 2)")
      ->check(CLI::Range(0, kMaxTransferBounces));
  app.add_flag("--bake-ao-area,!--no-bake-ao-area", settings.bakeAreaSampling,
               "iblkit-bake --ao-area for the bakes: visibility over each vertex's share of the surface (default on)");
  app.add_option("--bench", settings.benchFrames, "frames for each mode's median frame time (0: none)")
      ->check(CLI::Range(0, 1000));
  app.add_option("--samples", settings.engineSamples,
                 "shaded samples per pixel of the engine frames (MSAA with sample shading; 1: none)")
      ->check(CLI::Range(1, 32));
  app.add_option("--supersample", settings.engineSupersample,
                 "engine frames render K x K pixels per pixel, box-filtered down (1, 2 or 4)")
      ->check(CLI::IsMember({1, 2, 4}));
  app.add_option("--integrator", settings.referenceIntegrator,
                 "the reference's iblkit-trace integrator: path (default) or direct (no interreflection)")
      ->check(nameChoice(std::vector<std::string>{"path", "direct"}, "integrator"));
  app.add_flag("--strict", options.strict, "exit with status 3 when a claim does not hold");
  app.add_option("--scheduler", options.scheduler,
                 "where missing stages run: local (here, the default) or slurm (job arrays; docs/cluster.md)")
      ->check(nameChoice(std::vector<std::string>{"local", "slurm"}, "scheduler"));
  app.add_option("--partition", options.slurm.partition, "with --scheduler slurm: sbatch --partition");
  app.add_option("--sbatch-args", options.sbatchArguments,
                 "with --scheduler slurm: more sbatch arguments for every array, one string (--sbatch-args='--time=30')");
  app.add_option("--view-sbatch-args", options.viewSbatchArguments,
                 "with --scheduler slurm: more sbatch arguments for the engine frames (--view-sbatch-args='--gres=gpu:1')");
  // A Slurm task's hidden mode (stage_plan.h).
  app.add_option("--stage-task", options.stageTask)->group("");
  app.add_option("--task-index", options.taskIndex)->group("");
  return runProgram(app, argc, argv, [&]() -> int {
    if (!options.stageTask.empty()) {
      runStageTask(options.stageTask, options.taskIndex);
      return kExitSuccess;
    }
    if (options.scheduler != "slurm" &&
        (!options.slurm.partition.empty() || !options.sbatchArguments.empty() || !options.viewSbatchArguments.empty()))
      throw UsageError("--partition, --sbatch-args and --view-sbatch-args are for --scheduler slurm");
    return report(options);
  });
}
