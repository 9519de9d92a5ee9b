#pragma once
// The options of a split reference render (iblkit-trace; docs/cluster.md): --pass I --passes N
// renders the I-th of N disjoint sample ranges of --spp, --sum FILE writes the render's exact sums
// (reference/pass_sum.h) for a merge, and --merge SUM... adds such files up and writes the image
// (-o), its variance (--variance), a preview (--png) or the merged sums (--sum) instead of
// rendering. A Slurm array task runs `--pass $SLURM_ARRAY_TASK_ID --passes $SLURM_ARRAY_TASK_COUNT`.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace iblkit {

struct PassArguments {
  std::optional<int> pass, passes;
  std::filesystem::path sum;
  std::vector<std::filesystem::path> merge;
};

// Adds --pass, --passes, --sum and --merge to `app`; the positional `scene` becomes optional (a
// merge has none; checkPassArguments asks for it otherwise).
void addPassArguments(CLI::App& app, PassArguments& arguments, const std::string& scene);

// Throws UsageError for a command line these options make impossible: --pass without --passes
// or the other way round, a render without the scene ("scene is required") or without an output
// ("--output is required", unless --sum), a merge with the scene or an option of a render
// (anything but -o, --sum, --variance, --png and --exposure), a merge without an output.
void checkPassArguments(const CLI::App& app, const PassArguments& arguments, const std::string& scene);

// The options given on the command line that can change a sample, one "name=value" line each in
// the app's order: every option but the scene and map files (their bytes go into the render key
// instead: their paths may differ from node to node), the outputs, --spp, --time, --threads, the
// pass options and --exposure. A new option of the tracer is so part of the render key
// (reference/pass_sum.h renderKey) unless it is listed here as one that leaves samples alone.
std::string samplingArguments(const CLI::App& app, const std::string& scene);

}  // namespace iblkit
