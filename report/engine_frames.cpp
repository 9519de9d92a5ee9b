#include "report/engine_frames.h"

#include <fstream>
#include <iterator>
#include <limits>
#include <regex>

#include "core/error.h"
#include "core/image_io.h"
#include "report/stage_commands.h"
#include "report/stage_run.h"

namespace iblkit {

namespace fs = std::filesystem;

std::vector<Image> renderEngineFrames(const ReportSettings& settings, const StageCache& cache,
                                      const std::string& caseName, const fs::path& bake, CaseResult& result) {
  std::vector<Image> frames;
  for (const std::string& mode : settings.modes) {
    ModeResult modeResult;
    modeResult.mode = mode;
    try {
      const StageRun rendered =
          runStage(cache, "view-" + caseName + "-" + mode, viewCommand(settings, bake, mode));
      result.commands.push_back(rendered.command);
      if (rendered.pending) {
        result.pending = true;
        frames.emplace_back();
        result.modes.push_back(modeResult);
        continue;
      }
      std::ifstream log(rendered.folder / "log.txt");
      modeResult.frameMilliseconds = parseMedianMilliseconds(
          std::string(std::istreambuf_iterator<char>(log), std::istreambuf_iterator<char>()));
      frames.push_back(readExr(rendered.folder / "frame.exr", nullptr, 0, PixelRepair::Keep));
    } catch (const Error& e) {
      modeResult.failure = e.what();
      frames.emplace_back();
    }
    result.modes.push_back(modeResult);
  }
  return frames;
}

double parseMedianMilliseconds(const std::string& output) {
  static const std::regex pattern(R"(\bcpu\s+([0-9]+(\.[0-9]+)?)\s*ms)");
  std::smatch match;
  if (!std::regex_search(output, match, pattern)) return std::numeric_limits<double>::quiet_NaN();
  return std::stod(match[1].str());
}

}  // namespace iblkit
