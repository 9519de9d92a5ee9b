#include "report/engine_frames.h"

#include <algorithm>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <regex>
#include <sstream>

#include "core/error.h"
#include "core/image_io.h"
#include "report/stage_commands.h"
#include "report/stage_run.h"

namespace iblkit {

namespace fs = std::filesystem;

std::vector<Image> renderEngineFrames(const ReportSettings& settings, const StageCache& cache,
                                      const std::string& caseName, const fs::path& bake, CaseResult& result) {
  std::vector<Image> frames(settings.modes.size());
  std::vector<ModeResult> modes(settings.modes.size());
  for (std::size_t m = 0; m < settings.modes.size(); ++m) modes[m].mode = settings.modes[m];
  const auto indexOf = [&](const std::string& mode) {
    return std::size_t(std::find(settings.modes.begin(), settings.modes.end(), mode) - settings.modes.begin());
  };
  // One group's stage; when it fails and holds several modes, each of them alone, so that a mode
  // iblkit-view refuses (an unknown name) fails by itself and names its own error.
  std::function<void(const std::vector<std::string>&)> renderGroup = [&](const std::vector<std::string>& group) {
    std::string name = "view-" + caseName;
    for (std::size_t k = 0; k < group.size(); ++k) name += (k ? "+" : "-") + group[k];
    StageRun rendered;
    try {
      rendered = runStage(cache, name, viewCommand(settings, bake, group));
    } catch (const Error& e) {
      if (group.size() > 1) {
        for (const std::string& mode : group) renderGroup({mode});
      } else {
        modes[indexOf(group.front())].failure = e.what();
      }
      return;
    }
    result.commands.push_back(rendered.command);
    if (rendered.pending) {
      result.pending = true;
      return;
    }
    std::ifstream logFile(rendered.folder / "log.txt");
    const std::string log(std::istreambuf_iterator<char>(logFile), std::istreambuf_iterator<char>{});
    for (const std::string& mode : group) {
      ModeResult& modeResult = modes[indexOf(mode)];
      try {
        modeResult.frameMilliseconds = parseMedianMilliseconds(log, mode);
        frames[indexOf(mode)] = readExr(rendered.folder / viewFrameFile(mode), nullptr, 0, PixelRepair::Keep);
      } catch (const Error& e) {
        modeResult.failure = e.what();
      }
    }
  };
  for (const std::vector<std::string>& group : viewGroups(settings, settings.modes)) renderGroup(group);
  result.modes.insert(result.modes.end(), modes.begin(), modes.end());
  return frames;
}

double parseMedianMilliseconds(const std::string& output, const std::string& mode) {
  static const std::regex pattern(R"(^\s+(\S+)\s+cpu\s+([0-9]+(\.[0-9]+)?)\s*ms)");
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    std::smatch match;
    if (std::regex_search(line, match, pattern) && match[1].str() == mode) return std::stod(match[2].str());
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace iblkit
