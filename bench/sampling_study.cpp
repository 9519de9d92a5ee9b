// sampling_study: the environment-sampling study of the reference path tracer (issue 3; results
// in docs/benchmarks.md, "Reference tracer"; the study itself is env_sampling_study.h).
//
// Renders the bundled bunny-on-plane scene (`path` integrator) under several environment maps with
// each --env-sampling strategy (uniform, cosine, brdf, env, mis) at equal sample counts 1, 2, 4,
// ..., --max-spp, and scores every render by its relMSE against a high-spp MIS render of the same
// map (rendered once with another seed and cached as OpenEXR in --cache). Writes a markdown table
// (--out-dir/NAME.md), a log-log plot of relMSE against spp, one panel per map and one line per
// strategy (--out-dir/NAME.svg), and, with --update FILE, replaces the text between the lines
// "<!-- NAME:begin -->" and "<!-- NAME:end -->" of FILE with the table; NAME is --name
// (default sampling_study). --phong E gives every surface the modified Phong lobe of exponent E
// (the second material model, a glossy lobe that BRDF sampling follows) instead of the
// scene's glTF materials.
//
// Bad input (settings out of range, a map that does not load, a missing --out-dir, an --update
// file without the section) fails with one line on stderr before anything is rendered or written,
// with the exit status of cli/program.h (2 for the command line, 1 for the files).

#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "bench/env_sampling_study.h"
#include "bench/marked_section.h"
#include "bench/sampling_study_report.h"
#include "cli/program.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/scene.h"
#include "core/scene_environment.h"
#include "core/usage_error.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

struct Options {
  SamplingStudySettings study;
  fs::path scene, assets, outDir = "docs/benchmarks", update;
  std::vector<std::string> maps{"sky:sunny", "studio:studio", "venice:soft"};
  std::string name = "sampling_study";
};

struct StudyMap {
  std::string name, label;
  EnvironmentMap environment;
};

std::string readText(const fs::path& file) {
  const std::vector<char> bytes = readFileBytes(file);
  return std::string(bytes.begin(), bytes.end());
}

void writeText(const fs::path& file, const std::string& text) {
  writeAtomically(file, [&](const fs::path& temporary) {
    std::ofstream stream(temporary, std::ios::binary);
    stream << text;
    if (!stream.flush()) fail(temporary, "cannot write");
  });
}

// Each "NAME[:LABEL]" of --maps with ASSETS/hdri/NAME.exr loaded in place of the scene's map.
std::vector<StudyMap> loadStudyMaps(const Options& options, const Scene& scene) {
  if (options.maps.empty()) failUsage("--maps", "no map given");
  std::vector<StudyMap> maps;
  for (const std::string& entry : options.maps) {
    const std::size_t colon = entry.find(':');
    const std::string name = entry.substr(0, colon);
    if (name.empty() || name.find('/') != std::string::npos)
      failUsage("--maps", "'" + entry + "' is not NAME[:LABEL] with NAME a map in ASSETS/hdri");
    maps.push_back({name, colon == std::string::npos ? name : entry.substr(colon + 1),
                    loadSceneEnvironment(scene, options.assets / "hdri" / (name + ".exr"))});
  }
  return maps;
}

int run(const Options& options) {
  // Everything that can be refused is checked before the first render.
  validateSamplingStudySettings(options.study);
  if (options.name.empty() || options.name.find('/') != std::string::npos)
    failUsage("--name", "'" + options.name + "' is not a file name");
  if (!fs::is_directory(options.outDir)) fail(options.outDir, "folder does not exist");
  if (!options.update.empty())
    replaceMarkedSection(readText(options.update), options.name, "", options.update);
  const fs::path sceneFile = options.scene.empty() ? options.assets / "scenes" / "bunny.json" : options.scene;
  const Scene scene = loadScene(sceneFile);
  const std::vector<StudyMap> maps = loadStudyMaps(options, scene);
  // --update is rewritten on purpose (its marked section); the tables must not replace an input.
  std::vector<fs::path> inputs = sceneInputs(scene);
  for (const StudyMap& map : maps) inputs.push_back(options.assets / "hdri" / (map.name + ".exr"));
  checkOutputs(inputs, {options.outDir / (options.name + ".md"), options.outDir / (options.name + ".svg")});

  const StudyLog log = [](const std::string& line) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  };
  std::vector<MapStudy> results;
  for (const StudyMap& map : maps) {
    results.push_back(studyEnvironmentMap(options.study, scene, map.environment, map.name, map.label, log));
    std::printf("%s: reference %s (%.1f s), floor %s\n", map.name.c_str(),
                results.back().referenceCached ? "cached" : "rendered", results.back().referenceSeconds,
                formatStudyNumber(results.back().referenceFloor).c_str());
  }
  const std::string table = samplingStudyMarkdown(options.study, sceneFile.filename().string(), results);
  writeText(options.outDir / (options.name + ".md"), "# Sampling study\n\n" + table);
  writeText(options.outDir / (options.name + ".svg"), samplingStudySvg(options.study, results));
  // Read again: the file may have been edited during the run, which takes minutes at full size.
  if (!options.update.empty())
    writeText(options.update,
              replaceMarkedSection(readText(options.update), options.name, table, options.update));
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
  CLI::App app{"relMSE of each environment-sampling strategy against spp (docs/benchmarks.md)",
               "sampling_study"};
  app.add_option("--assets", options.assets, "assets folder (default $IBLKIT_ASSETS or ./assets)");
  app.add_option("--scene", options.scene, "scene (default ASSETS/scenes/bunny.json)");
  app.add_option("--maps", options.maps, "maps in ASSETS/hdri as NAME[:LABEL]")->delimiter(',');
  app.add_option("--width", options.study.width, "image width");
  app.add_option("--height", options.study.height, "image height");
  app.add_option("--max-spp", options.study.maxSpp, "largest sample count (1, 2, 4, ... up to it)");
  app.add_option("--reference-spp", options.study.referenceSpp, "samples per pixel of the reference");
  app.add_option("--threads", options.study.threads, "worker threads (0: all)");
  app.add_option("--cache", options.study.cache, "folder of the cached references");
  app.add_option("--out-dir", options.outDir, "where NAME.md and NAME.svg go");
  app.add_option("--name", options.name,
                 "name of the outputs and of the --update section (default sampling_study)");
  app.add_option("--phong", options.study.phong,
                 "every surface uses the modified Phong lobe of this exponent");
  app.add_option("--update", options.update, "markdown file whose sampling-study section gets the table");
  return runProgram(app, argc, argv, [&] { return run(options); });
}
