#include "cli/pass_arguments.h"

#include <algorithm>
#include <array>
#include <string_view>

#include "core/usage_error.h"

namespace iblkit {

namespace {

// What a merge takes besides --merge.
constexpr std::array<std::string_view, 5> kMergeOptions = {"--output", "--sum", "--variance", "--png",
                                                           "--exposure"};
// The options that leave every sample as it is (samplingArguments).
constexpr std::array<std::string_view, 17> kNonSamplingOptions = {
    "--help",    "--output",   "--png",    "--exposure",    "--albedo", "--normal",
    "--depth",   "--variance", "--mask",   "--bent-normal", "--spp",    "--time",
    "--threads", "--pass",     "--passes", "--sum",         "--env"};

template <std::size_t N>
bool listed(const std::array<std::string_view, N>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

void addPassArguments(CLI::App& app, PassArguments& arguments, const std::string& scene) {
  app.get_option(scene)->required(false);
  CLI::Option* pass = app.add_option(
      "--pass", arguments.pass, "render only pass I (0-based) of --passes: its share of --spp's samples");
  CLI::Option* passes =
      app.add_option("--passes", arguments.passes, "the passes --spp is split into (1..--spp)");
  pass->needs(passes);
  passes->needs(pass);
  app.add_option("--sum", arguments.sum, "the render's exact sums, for --merge (docs/cluster.md)");
  app.add_option("--merge", arguments.merge, "add up these --sum files of one render's passes (no scene)")
      ->excludes(pass)
      ->excludes(passes);
}

void checkPassArguments(const CLI::App& app, const PassArguments& arguments, const std::string& scene) {
  const bool hasOutput = app.count("--output") > 0 || !arguments.sum.empty();
  if (arguments.merge.empty()) {
    if (app.count(scene) == 0) throw UsageError(scene + " is required");
    if (!hasOutput) throw UsageError("--output is required");
    return;
  }
  for (const CLI::Option* option : app.get_options())
    if (option->count() > 0 && option->get_name() != "--merge" && !listed(kMergeOptions, option->get_name()))
      failUsage(option->get_name() == scene ? scene : option->get_name(), "does not apply to --merge");
  if (!hasOutput && app.count("--variance") == 0 && app.count("--png") == 0)
    failUsage("--merge", "needs an output (-o, --sum, --variance or --png)");
}

std::string samplingArguments(const CLI::App& app, const std::string& scene) {
  std::string text;
  for (const CLI::Option* option : app.get_options()) {
    const std::string& name = option->get_name();
    if (option->count() == 0 || name == scene || listed(kNonSamplingOptions, name)) continue;
    text += name + "=";
    for (const std::string& value : option->results()) text += value + ";";
    text += "\n";
  }
  return text;
}

}  // namespace iblkit
