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

#include "cli/program.h"
#include "core/error.h"
#include "core/environment_map_file.h"
#include "core/file_io.h"
#include "core/usage_error.h"
#include "report/report_case.h"
#include "report/map_kind.h"
#include "report/report_claims.h"
#include "report/report_writer.h"

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

// Runs every case, writes the report and prints the claims.
int report(Options& options) {
  ReportSettings& settings = options.settings;
  if (settings.minPasses % 2 != 0 || settings.maxPasses % 2 != 0 || settings.maxPasses < settings.minPasses)
    throw UsageError("--min-passes and --max-passes must be even, min <= max");
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
  const StageCache cache(options.cacheFolder.empty() ? settings.outDir / "cache"
                                                     : fs::path(options.cacheFolder));

  ReportSummary summary;
  summary.modes = settings.modes;
  std::map<fs::path, MapConcentration> concentrations;  // each map read once, for its kind
  for (const std::string& scene : options.scenes) {
    if (!fs::is_regular_file(scene)) fail(scene, "scene file does not exist");
    for (const std::string& name : options.environments) {
      const fs::path environment = environmentFile(options, name);
      if (!fs::is_regular_file(environment)) fail(environment, "environment map does not exist");
      const int before = cache.misses();
      CaseResult result = runCase(settings, cache, scene, environment);
      if (!concentrations.contains(environment))
        concentrations[environment] = mapConcentration(loadEnvironmentMap(environment));
      result.concentration = concentrations[environment];
      result.mapKind = classifyMap(result.concentration);
      std::fprintf(
          stderr, "iblkit-report: %s under %s: reference %d spp (relMSE %.2g, halves' FLIP %.3f, %s)%s\n",
          result.scene.c_str(), result.environment.c_str(), result.referenceSpp, result.referenceRelMse,
          result.referenceHalvesFlip, result.referenceConverged ? "converged" : "not converged",
          cache.misses() == before ? ", cached" : "");
      summary.cases.push_back(std::move(result));
    }
  }
  summary.claims = evaluateClaims(summary.cases);
  summary.settings = settings;
  summary.cachedStages = cache.hits();
  summary.runStages = cache.misses();
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
                 "iblkit-trace --camera-light-samples of the reference passes (default 4)")
      ->check(CLI::Range(1, 64));
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
  return runProgram(app, argc, argv, [&] { return report(options); });
}
