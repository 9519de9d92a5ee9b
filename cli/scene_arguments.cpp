#include "cli/scene_arguments.h"

#include "cli/program.h"
#include "core/error.h"

namespace iblkit {

void addSceneArguments(CLI::App& app, SceneArguments& arguments, const std::string& name,
                       const std::string& description, bool required) {
  app.add_option(name, arguments.input, description)->required(required);
  addEnvironmentOptions(app, arguments.environment);
}

void checkSceneArguments(const SceneArguments& arguments) {
  checkEnvironmentOverride(arguments.environment);
  const std::filesystem::path& map = arguments.environment.file;
  std::error_code error;
  if (!map.empty() && !std::filesystem::is_regular_file(map, error)) fail(map, "cannot open: No such file or directory");  // the map loader's words
}

bool isSceneFile(const std::filesystem::path& input) {
  std::error_code error;
  return std::filesystem::is_regular_file(input, error);
}

}  // namespace iblkit
